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

int run(int argc, char** argv, const std::string& name, const std::function<void(const Options&)>& body) {
  Options options;
  options.name = name;
  bool out_given = false;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--out" && k + 1 < argc) {
      options.out_dir = argv[++k];
      out_given = true;
    } else if (arg == "--csv" && k + 1 < argc) {
      options.out_dir = argv[++k];  // CSV files there, figures still in a window if there is one
    } else {
      std::cerr << name << ": unknown argument '" << arg << "'\nusage: " << argv[0] << " [--out DIR | --csv DIR]\n";
      return 2;
    }
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
