#include "demo.hpp"

#include <climits>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "build.hpp"
#include "exit_status.hpp"
#include "file_io.hpp"
#include "layout.hpp"
#include "process.hpp"
#include "strings.hpp"

namespace fmbd::frontend {

namespace fs = std::filesystem;
using tools::Command;

namespace {

// No demos in the build (configured with the demos on: CMake finds no gnuplot-iostream): what to
// install. Returns exit status 1.
int no_demos(const std::string& build) {
  std::cout.flush();
  std::cerr << "workbook: no demos were built: CMake finds no gnuplot-iostream with Boost (" << BuildLayout{build}.configure_log() << ").\n";
  if (tools::on_path("dpkg-query")) {
    const char* packages = std::getenv("FMBD_DEMO_PACKAGES");
    std::cerr << "Install them, then run this command again:\n"
              << "  sudo apt-get install -y --no-install-recommends " << (packages ? packages : "") << "\n";
  } else {
    std::cerr << "Install gnuplot and Boost (macOS: brew install gnuplot boost) and put gnuplot-iostream.h on the\n"
              << "include path, then run this command again.\n";
  }
  return 1;
}

}  // namespace

const CommandSpec& demo_command() {
  static const CommandSpec spec = [] {
    CommandSpec s;
    s.name = "demo";
    s.options = {{"--out", OptionKind::value, "DIR", "a directory", "PNG and CSV files in DIR/NAME"},
                 {"--csv", OptionKind::value, "DIR", "a directory", "windows, and the CSV files in DIR/NAME"}};
    s.positional = "NAME";
    s.max_positionals = INT_MAX;  // one, said below with both names
    s.unknown_hint = " (a demo's own parameters go after --: ./workbook demo NAME -- {option} ...)";
    s.pass_rest = true;
    s.synopsis = "[NAME] [--out DIR | --csv DIR] [-- DEMO-PARAMETERS...]";
    s.help = {"Run the lecture demos (all, or NAME): gnuplot windows with a DISPLAY, otherwise",
              "PNG and CSV files in DIR (default out/demos). After --, parameters of demo NAME,",
              "e.g. ./workbook demo spinning_beam -- --spin-rate 40; ./workbook demo NAME -- --help",
              "lists them with their defaults. An unknown parameter exits 2."};
    return s;
  }();
  return spec;
}

int run_demo(const std::vector<std::string>& args, const Context& context) {
  const ParsedOptions options = parse_options(demo_command(), args);
  if (print_usage_if_asked(options, demo_command(), context.out)) return 0;
  if (options.positionals.size() > 1) {
    throw UsageError("demo: one NAME at a time ('" + options.positionals[0] + "', then '" + options.positionals[1] + "')");
  }
  const std::string name = options.positionals.empty() ? "" : options.positionals.front();
  if (options.ended && name.empty()) {
    throw UsageError("demo: parameters after -- need a demo NAME (each demo has its own)");
  }
  std::string out = options.has("--out") ? tools::absolute_path(options.value("--out"), context.source_dir) : "";
  const std::string csv = options.has("--csv") ? tools::absolute_path(options.value("--csv"), context.source_dir) : "";

  const std::string& build = context.manifest.build_dir;
  std::vector<Demo> demos = context.manifest.demos;
  if (demos.empty()) {  // configured before the demo packages were installed, or with demos off: look again
    context.out << "workbook: build/student has no demos; configuring it again to look for gnuplot-iostream\n"
                << std::flush;
    tools::run(Command{{cmake_program(), "-DFMBD_BUILD_DEMOS=ON", build}, context.source_dir, BuildLayout{build}.configure_log()});
    demos = read_manifest(BuildLayout{build}.course_json()).demos;
  }
  if (demos.empty()) return no_demos(build);

  const char* display = std::getenv("DISPLAY");
  if (out.empty() && csv.empty() && (display == nullptr || *display == '\0')) out = context.source_dir + "/out/demos";
  bool found = false;
  std::string failed;
  for (const Demo& demo : demos) {
    if (!name.empty() && name != demo.name) continue;
    found = true;
    const std::string log = build + "/demo_" + demo.name + ".build.log";
    if (tools::run(Command{{cmake_program(), "--build", build, "--target", demo.target}, "", log}) != 0) {
      context.out << "workbook: demo " << demo.name << " does not build (build/student/demo_" << demo.name
                  << ".build.log)\n";
      failed += " " + demo.name;
      continue;
    }
    // A demo runs your code of its modules: an unfinished task stops it with "not implemented yet".
    std::vector<std::string> argv = {demo.program};
    if (!out.empty()) {
      argv.insert(argv.end(), {"--out", out + "/" + demo.name});
    } else if (!csv.empty()) {
      argv.insert(argv.end(), {"--csv", csv + "/" + demo.name});
    }
    argv.insert(argv.end(), options.rest.begin(), options.rest.end());
    context.out.flush();
    const int status = tools::run(Command{argv});
    if (status == 2) return 2;  // the demo refused a parameter, and said which
    if (status != 0) {
      context.out << "workbook: demo " << demo.name << " failed (its message is above)\n";
      failed += " " + demo.name;
    }
  }
  if (!found) {
    std::string names;
    for (const Demo& demo : demos) names += demo.name + " ";
    throw UsageError("no demo named '" + name + "'; the demos are: " + names);
  }
  if (!failed.empty()) throw StepFailed("these demos failed:" + failed);
  return 0;
}

}  // namespace fmbd::frontend
