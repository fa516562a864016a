#include "maintainer.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string_view>

#include "build.hpp"
#include "exit_status.hpp"
#include "file_io.hpp"
#include "grade.hpp"
#include "layout.hpp"
#include "process.hpp"
#include "release.hpp"
#include "strings.hpp"

namespace fmbd::frontend {

namespace fs = std::filesystem;
using tools::Command;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

bool is_folder(const Context& context, const char* name) { return fs::is_directory(fs::path(context.source_dir) / name); }

// One row of the bench table: a wall time, rounded to a tenth of a second.
std::string time_row(const std::string& group, const std::string& what, double seconds) {
  char value[32];
  std::snprintf(value, sizeof value, "%.1f", seconds);
  return group + "," + what + ",wall time," + value + ",s\n";
}

// Runs ./workbook ARGS in the folder `tree` (a release: what a student types there), quietly;
// its wall time, or a StepFailed saying `failure`.
double timed_workbook(const std::string& tree, std::vector<std::string> args, const std::string& failure) {
  args.insert(args.begin(), tree + "/workbook");
  const Clock::time_point start = Clock::now();
  if (tools::run(Command{args, tree, "/dev/null"}) != 0) throw StepFailed(failure);
  return seconds_since(start);
}

// Runs ./workbook grade in this tree, its output dropped; its wall time.
double timed_grade(const Context& context, const std::vector<std::string>& args) {
  std::ostringstream ignored;
  const Clock::time_point start = Clock::now();
  if (run_grade(args, Context{context.source_dir, context.manifest, ignored}) != 0) {
    throw StepFailed("bench: ./workbook grade --solutions failed");
  }
  return seconds_since(start);
}

// The student loop's rows: a fresh release graded from clean, module 1 first (the quick start's
// first command), then all modules, again, after an edit; the autograder on the reference.
std::string student_loop(const Context& context) {
  const std::string release = context.source_dir + "/build/bench/release";
  const auto fresh_release = [&] {
    fs::remove_all(release);
    std::ostringstream ignored;
    if (run_release({"--out", release}, Context{context.source_dir, context.manifest, ignored}) != 0) {
      throw StepFailed("bench: the release failed");
    }
  };
  std::string rows;
  context.out << "workbook: bench: ./workbook grade --module 1 in a student release, built from clean ...\n" << std::flush;
  fresh_release();
  rows += time_row("student loop", "release: first ./workbook grade --module 1 (configure; build; grade; target 60 s)",
                   timed_workbook(release, {"grade", "--module", "1"}, "bench: grading module 1 of the release failed"));
  context.out << "workbook: bench: a student release, built from clean ...\n" << std::flush;
  fresh_release();
  rows += time_row("student loop", "release: first ./workbook grade (configure; build; grade)",
                   timed_workbook(release, {"grade"}, "bench: grading the release failed"));
  rows += time_row("student loop", "release: ./workbook grade again (all modules; skeletons)",
                   timed_workbook(release, {"grade"}, "bench: grading the release again failed"));
  const fs::path edited = fs::path(release) / "module04_integration/src/integrators.cpp";
  fs::last_write_time(edited, fs::file_time_type::clock::now());
  rows += time_row("student loop", "edit integrators.cpp then ./workbook grade --module 4",
                   timed_workbook(release, {"grade", "--module", "4"}, "bench: grading module 4 of the release failed"));
  fs::remove_all(release);

  context.out << "workbook: bench: the autograder on the reference ...\n" << std::flush;
  timed_grade(context, {"--solutions"});  // builds
  rows += time_row("student loop", "./workbook grade --solutions (built; all modules)", timed_grade(context, {"--solutions"}));
  // The reference's time per test, one test at a time, from which grading sets each test's
  // timeout (commit the file when it changes).
  timed_grade(context, {"--solutions", "--jobs", "1", "--timings-out", timings_path(context.source_dir)});
  return rows;
}

}  // namespace

const CommandSpec& test_command() {
  static const CommandSpec spec = [] {
    CommandSpec s;
    s.name = "test";
    s.options = {{"--preset", OptionKind::value, "ci|asan|clang-libcxx", "a name", "the build and test preset"}};
    s.help = {"The project's whole test suite (reference, skeletons, mutants, driver, demos)."};
    return s;
  }();
  return spec;
}

const CommandSpec& bench_command() {
  static const CommandSpec spec = [] {
    CommandSpec s;
    s.name = "bench";
    s.options = {{"--quick", OptionKind::flag, "", "", "the benchmark programs only, on small cases"},
                 {"--out", OptionKind::value, "FILE.csv", "a file name", "the CSV file to write"}};
    s.help = {"Benchmarks: a student release built and graded from clean, the edit-rebuild-regrade",
              "loop, the autograder on the reference, and the benchmark programs of the extras",
              "(extras/*/bench: simulation, modal analysis). Prints a table and writes it as CSV",
              "(default build/bench/bench.csv). --quick: the benchmark programs only, on small cases."};
    return s;
  }();
  return spec;
}

const CommandSpec& bench_extras_command() {
  static const CommandSpec spec = [] {
    CommandSpec s = bench_command();
    s.help = {"The benchmark programs of the extras (extras/*/bench), as a table and a CSV file",
              "(default build/bench/bench.csv). --quick: small cases."};
    return s;
  }();
  return spec;
}

const CommandSpec& studentify_command() {
  static const CommandSpec spec = [] {
    CommandSpec s;
    s.name = "studentify";
    s.help = {"Regenerate every moduleNN_*/src exercise file from solutions/ (maintainers)."};
    return s;
  }();
  return spec;
}

namespace {

// The suite's tests build copies of the workbook, a release twice in one copy (build/student and
// build/reference). With ccache on PATH, every build the tests start shares one compiler cache,
// build/<preset>/ccache: their configures read CMAKE_CXX_COMPILER_LAUNCHER from the environment,
// and CCACHE_NOHASHDIR lets a second build folder of the same copy reuse the first one's objects
// (only their debug information's build folder differs). CCACHE_BASEDIR (build/<preset>, where the
// tests make their copies) lets the copies share objects too: ccache gives the compiler the paths
// inside it relative to the build folder, the same in every copy (../../module01_kinematics/...),
// which the front end shows as it shows absolute ones (first_errors, warnings_of). A test of odd
// absolute paths (project.graded_kind) unsets it. A launcher of the user's own is kept.
std::vector<std::pair<std::string, std::string>> suite_compiler_cache(const std::string& source_dir,
                                                                      const std::string& preset) {
  if (std::getenv("CMAKE_CXX_COMPILER_LAUNCHER") != nullptr || !tools::on_path("ccache")) return {};
  return {{"CMAKE_CXX_COMPILER_LAUNCHER", "ccache"},
          {"CCACHE_DIR", BuildLayout::of_preset(source_dir, preset).ccache()},
          {"CCACHE_NOHASHDIR", "true"},
          {"CCACHE_BASEDIR", preset_build_dir(source_dir, preset)}};
}

}  // namespace

int run_test(const std::vector<std::string>& args, const Context& context) {
  const ParsedOptions options = parse_options(test_command(), args);
  if (print_usage_if_asked(options, test_command(), context.out)) return 0;
  const std::string preset = options.value("--preset", "ci");
  if (!is_folder(context, "tests") || !context.manifest.instructor) {
    throw UsageError("test runs the project's own test suite, which is in the instructor's copy only (tests/, "
                     "solutions/); to grade your code: ./workbook grade");
  }
  const Clock::time_point start = Clock::now();
  configure(context.source_dir, preset, context.out);
  context.out.flush();
  if (tools::run(Command{{cmake_program(), "--build", preset_build_dir(context.source_dir, preset)}, context.source_dir}) != 0) {
    throw BuildError("building build/" + preset + " failed (the compiler's output above)");
  }
  const double built = seconds_since(start);
  Command ctest{{ctest_program(), "--preset", preset}, context.source_dir};
  ctest.environment = suite_compiler_cache(context.source_dir, preset);
  const int status = tools::run(ctest);
  char line[128];
  std::snprintf(line, sizeof line, "workbook: build %.0f s, tests %.0f s (preset %s)\n", built, seconds_since(start) - built,
                preset.c_str());
  context.out << line;
  return status == 0 ? kExitOk : kExitFailed;
}

int run_studentify(const std::vector<std::string>& args, const Context& context) {
  const ParsedOptions options = parse_options(studentify_command(), args);
  if (print_usage_if_asked(options, studentify_command(), context.out)) return 0;
  if (!is_folder(context, "solutions")) throw UsageError("studentify needs the solutions/ folder");
  context.out.flush();
  return tools::run(
      Command{{cmake_program(), "--build", context.manifest.build_dir, "--target", "studentify"}, context.source_dir});
}

std::vector<BenchRow> parse_bench_csv(const std::string& text, const std::string& origin) {
  constexpr std::string_view kHeader = "group,case,quantity,value,unit";
  std::vector<BenchRow> rows;
  const std::vector<std::string> lines = tools::split_lines(text);
  for (std::size_t n = 0; n < lines.size(); ++n) {
    if (lines[n].empty() || (n == 0 && lines[n] == kHeader)) continue;
    const std::vector<std::string> f = tools::split(lines[n], ',');
    const std::string where = origin + ": line " + std::to_string(n + 1) + ": ";
    if (f.size() != 5) throw StepFailed(where + std::to_string(f.size()) + " fields, not 5: " + lines[n]);
    char* end = nullptr;
    const double value = std::strtod(f[3].c_str(), &end);
    if (f[3].empty() || *end != '\0' || !std::isfinite(value)) {
      throw StepFailed(where + "the value '" + f[3] + "' is not a finite number");
    }
    rows.push_back({f[0], f[1], f[2], f[3], f[4]});
  }
  if (rows.empty()) throw StepFailed(origin + ": no rows");
  return rows;
}

std::string bench_table(const std::string& csv) {
  std::string table;
  std::string targets;
  char line[512];
  const auto add_row = [&](const BenchRow& row) {
    std::snprintf(line, sizeof line, "%-14s %-70s %-28s %12s %s\n", row.group.c_str(), row.name.c_str(),
                  row.quantity.c_str(), row.value.c_str(), row.unit.c_str());
    table += line;
  };
  add_row({"group", "case", "quantity", "value", "unit"});
  for (const BenchRow& row : parse_bench_csv(csv, "the benchmarks' output")) {
    add_row(row);
    if (row.quantity != "ratio_to_target") continue;
    if (targets.empty()) targets = "Speed targets (cost per step / target):\n";
    const bool met = std::strtod(row.value.c_str(), nullptr) <= 1;
    std::snprintf(line, sizeof line, "  %-90s %s\n", (row.group + ": " + row.name).c_str(),
                  (met ? "met (" + row.value + "x)" : "not met: " + row.value + "x the target").c_str());
    targets += line;
  }
  return table + targets;
}

int run_bench(const std::vector<std::string>& args, const Context& context) {
  const bool instructor = context.manifest.instructor;
  const CommandSpec& spec = instructor ? bench_command() : bench_extras_command();
  const ParsedOptions options = parse_options(spec, args);
  if (print_usage_if_asked(options, spec, context.out)) return 0;
  if (!is_folder(context, "solutions")) throw UsageError("bench measures the reference: it needs the solutions/ folder");
  const bool quick = options.has("--quick");
  const std::string out = tools::absolute_path(options.value("--out", "build/bench/bench.csv"), context.source_dir);

  std::string rows;
  if (!quick && !instructor) {
    context.out << "workbook: bench: the student loop needs the instructor's copy (it writes a release); the "
                   "benchmark programs only\n";
  } else if (!quick) {
    rows += student_loop(context);
  }
  if (context.manifest.benchmarks.empty()) throw UsageError("no benchmark programs (the build has no extras)");
  for (const Benchmark& benchmark : context.manifest.benchmarks) {
    context.out << "workbook: bench: " << benchmark.name << " ...\n" << std::flush;
    if (tools::run(Command{{cmake_program(), "--build", context.manifest.build_dir, "--target", benchmark.target},
                           context.source_dir, "/dev/null"}) != 0) {
      throw BuildError("building " + benchmark.target + " failed");
    }
    std::vector<std::string> argv = {benchmark.program};
    if (quick) argv.push_back("--quick");
    int status = 0;
    rows += tools::capture(Command{argv}, status);
    if (status != 0) throw StepFailed(benchmark.target + " failed");
  }
  const std::string csv = "group,case,quantity,value,unit\n" + rows;
  fs::create_directories(fs::path(out).parent_path());
  std::ofstream(out, std::ios::binary | std::ios::trunc) << csv;
  context.out << bench_table(csv) << "workbook: wrote " << out << "\n";
  return 0;
}

}  // namespace fmbd::frontend
