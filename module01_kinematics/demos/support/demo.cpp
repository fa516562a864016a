#include "demo.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include <gnuplot-iostream.h>

namespace fmbd::demo {

namespace {

// Output of a shell command (empty if it cannot run).
std::string capture(const std::string& command) {
  std::string out;
  if (FILE* pipe = ::popen(command.c_str(), "r")) {
    char buffer[4096];
    while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
    ::pclose(pipe);
  }
  return out;
}

bool has_gnuplot() { return !capture("command -v gnuplot 2>/dev/null").empty(); }

// The first interactive terminal this gnuplot offers, or "".
std::string window_terminal() {
  const std::string terminals = capture("echo 'set terminal' | gnuplot 2>&1");
  for (const char* t : {"qt", "wxt", "x11"}) {
    if (terminals.find(std::string(" ") + t + "  ") != std::string::npos) return t;
  }
  return "";
}

}  // namespace

Figure::Figure(const Options& options, const std::string& file, int width, int height, Format format)
    : window_(options.window) {
  if (!options.gnuplot) return;
  if (options.window) {
    gp_ = std::make_unique<Gnuplot>("gnuplot -persist");
    *gp_ << "set terminal " << window_terminal() << " size " << width << "," << height << " title '"
         << options.name << ": " << file << "'\n";
  } else {
    gp_ = std::make_unique<Gnuplot>("gnuplot");
    const bool gif = format == Format::gif_animation;
    *gp_ << (gif ? "set terminal gif animate delay 4 optimize size " : "set terminal pngcairo size ") << width
         << "," << height << (gif ? "\n" : " enhanced font 'Sans,11'\n") << "set output '"
         << (std::filesystem::path(options.out_dir) / (file + (gif ? ".gif" : ".png"))).string() << "'\n";
  }
  *gp_ << "set grid\nset key top right\n";
}

Figure::~Figure() {
  if (gp_) *gp_ << "unset output\n" << std::flush;
}

void Figure::end_frame(double seconds) {
  if (gp_ && window_) *gp_ << "pause " << seconds << "\n";
}

Gnuplot& Figure::gp() {
  if (!gp_) throw std::logic_error("Figure::gp: gnuplot is not available");
  return *gp_;
}

void Figure::send(const Table& table, const std::vector<int>& cols) {
  std::vector<std::vector<double>> block;
  block.reserve(table.rows.size());
  for (const auto& row : table.rows) {
    std::vector<double> picked;
    for (int c : cols) picked.push_back(row.at(c));
    block.push_back(std::move(picked));
  }
  gp().send1d(block);
}

void write_csv(const Options& options, const std::string& file, const Table& table) {
  if (options.out_dir.empty()) return;
  const auto path = std::filesystem::path(options.out_dir) / (file + ".csv");
  // Every column names its unit ("t [s]", "x [m]", "[-]" for a pure number). A value that does
  // not exist (NaN, e.g. a method not applicable to that row) is an empty field, never "nan".
  for (const std::string& c : table.columns)
    if (c.size() < 3 || c.back() != ']' || c.find(" [") == std::string::npos)
      throw std::invalid_argument(file + ".csv: column '" + c + "' has no unit (write it as 'name [unit]')");
  std::ofstream csv(path);
  csv.precision(12);
  for (std::size_t c = 0; c < table.columns.size(); ++c) csv << (c ? "," : "") << table.columns[c];
  csv << '\n';
  for (const auto& row : table.rows) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (c) csv << ',';
      if (std::isfinite(row[c])) csv << row[c];
    }
    csv << '\n';
  }
  if (!csv) throw std::runtime_error("cannot write " + path.string());
}

namespace {

const Parameter& find_parameter(const std::vector<Parameter>& table, const std::string& name) {
  for (const Parameter& p : table)
    if (p.name == name) return p;
  throw std::logic_error("demo parameter '" + name + "' is not in the demo's table");
}

// Whether `text` is a whole number (count) or, with whole = false, any finite number.
bool parses(const std::string& text, bool whole) {
  if (text.empty()) return false;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  return *end == '\0' && std::isfinite(v) && (!whole || v == std::floor(v));
}

bool is_count(const Parameter& p) { return p.unit.empty() && p.choices.empty(); }

// What a value of `p` must look like, for --help and error messages.
std::string kind(const Parameter& p) {
  if (is_count(p)) return "a whole number";
  if (p.choices.empty()) return "a number";
  std::string words;
  for (const std::string& c : p.choices) words += (words.empty() ? "" : " | ") + c;
  return words;
}

// Empty if `value` is allowed for `p`, otherwise why not.
std::string check_value(const Parameter& p, const std::string& value) {
  if (!p.choices.empty()) {
    for (const std::string& c : p.choices)
      if (c == value) return "";
  } else if (parses(value, is_count(p))) {
    return "";
  }
  return "--" + p.name + " takes " + kind(p) + ", not '" + value + "'";
}

void print_usage(std::ostream& out, const char* program, const std::string& name,
                 const std::vector<Parameter>& table) {
  out << "usage: " << program << " [--out DIR | --csv DIR]" << (table.empty() ? "" : " [--PARAMETER VALUE]...")
      << "\n\n  --out DIR   write PNG and CSV files into DIR, open no window\n"
      << "  --csv DIR   open windows (with a DISPLAY) and write the CSV files into DIR\n";
  if (table.empty()) {
    out << "\n" << name << " has no parameters.\n";
    return;
  }
  out << "\nparameters of " << name << " (default in brackets):\n";
  for (const Parameter& p : table) {
    std::string head = "  --" + p.name + " " + (p.choices.empty() ? "X" : kind(p));
    if (head.size() < 34) head.resize(34, ' ');
    out << head << " " << p.help << " [" << p.value << (p.unit.empty() || p.unit == "-" ? "" : " " + p.unit)
        << "]\n";
  }
}

}  // namespace

double Options::number(const std::string& parameter) const {
  return std::strtod(find_parameter(parameters, parameter).value.c_str(), nullptr);
}

int Options::integer(const std::string& parameter) const {
  return static_cast<int>(std::lround(number(parameter)));
}

const std::string& Options::text(const std::string& parameter) const {
  return find_parameter(parameters, parameter).value;
}

int run(int argc, char** argv, const std::string& name, const std::function<void(const Options&)>& body) {
  return run(argc, argv, name, {}, body);
}

int run(int argc, char** argv, const std::string& name, const std::vector<Parameter>& parameters,
        const std::function<void(const Options&)>& body) {
  Options options;
  options.name = name;
  options.parameters = parameters;
  for (const Parameter& p : parameters)  // a wrong default is the demo's own bug
    if (const std::string why = check_value(p, p.value); !why.empty()) {
      std::cerr << name << ": the demo's default is wrong: " << why << '\n';
      return 1;
    }
  bool out_given = false;
  const auto fail = [&](const std::string& why) {
    std::cerr << name << ": " << why << " (" << argv[0] << " --help lists the options)\n";
    return 2;
  };
  for (int k = 1; k < argc; ++k) {
    std::string arg = argv[k], value;
    const bool has_next = k + 1 < argc;
    if (arg == "--help" || arg == "-h") {
      print_usage(std::cout, argv[0], name, parameters);
      return 0;
    }
    if (arg == "--out" || arg == "--csv") {
      if (!has_next) return fail(arg + " needs a directory");
      options.out_dir = argv[++k];  // --csv: CSV files there, figures still in a window if there is one
      out_given = out_given || arg == "--out";
      continue;
    }
    if (arg.rfind("--", 0) != 0) return fail("unknown argument '" + arg + "'");
    const std::size_t equals = arg.find('=');
    const bool inline_value = equals != std::string::npos;
    if (inline_value) {
      value = arg.substr(equals + 1);
      arg.erase(equals);
    }
    Parameter* p = nullptr;
    for (Parameter& q : options.parameters)
      if ("--" + q.name == arg) p = &q;
    if (!p) {
      std::string known;
      for (const Parameter& q : parameters) known += " --" + q.name;
      return fail("unknown parameter '" + arg + "'; " +
                  (known.empty() ? "this demo has none" : "its parameters are" + known));
    }
    if (!inline_value) {
      if (!has_next) return fail(arg + " needs a value: " + kind(*p));
      value = argv[++k];
    }
    if (const std::string why = check_value(*p, value); !why.empty()) return fail(why);
    p->value = value;
  }
  options.gnuplot = has_gnuplot();
  const char* display = std::getenv("DISPLAY");
  options.window = !out_given && display && *display && options.gnuplot;
  if (options.window && window_terminal().empty()) {
    std::cout << name << ": this gnuplot has no window terminal (install gnuplot-qt); writing files instead\n";
    options.window = false;
  }
  if (!options.window && options.out_dir.empty()) options.out_dir = "demo_output";
  if (!options.gnuplot) std::cout << name << ": gnuplot is not installed; writing CSV files only\n";
  try {
    if (!options.out_dir.empty()) std::filesystem::create_directories(options.out_dir);
    body(options);
  } catch (const std::exception& e) {
    std::cerr << name << ": " << e.what() << '\n';
    return 1;
  }
  if (!options.window) std::cout << name << ": wrote files to " << options.out_dir << '\n';
  return 0;
}

}  // namespace fmbd::demo
