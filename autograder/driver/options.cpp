#include "options.hpp"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "tables.hpp"
#include "text.hpp"

namespace fmbd::grade {
namespace {

// The driver's command line: its one entry of the option layer (cli.hpp), from which come the
// parsing and the help.
const cli::Command& command() {
  static const cli::Command spec = [] {
    using cli::Kind;
    cli::Command s;
    s.name = "fmbd-grade";
    s.is_program = true;
    s.positional = "EXE";
    s.max_positionals = -1;
    s.synopsis = "[options] EXE [--listed-by LISTER] [--grades-inputs]...";
    s.help = {"Runs every graded test of each test program EXE in its own sandboxed process and prints",
              "a score table. LISTER (default: EXE) is the program whose --fmbd-list output names the",
              "tests, e.g. a trusted build of the same tests; --listed-by follows the EXE it lists.",
              "Paths are taken as they are (they may hold '@', spaces or any other character)."};
    s.options = {
        {"--listed-by", Kind::repeatable, "LISTER", "a program", "the program that lists the tests of the EXE before it"},
        {"--grades-inputs", Kind::flag, "", "", "the EXE before it grades the student's inputs (an answers\nfile), not the module's code: --reject and --build-errors\nleave its tests alone"},
        {"--module", Kind::repeatable, "N", "a number", "grade only tests tagged [MN] (repeatable; N or MN)"},
        {"--task", Kind::repeatable, "MNTK", "a task", "grade only the tests of task K of module N (repeatable;\ne.g. M03T2; M01P2: its tutorial problem 2)"},
        {"--list-tasks", Kind::flag, "", "", "print one line \"MNN TK POINTS\" per selected task (the points\nof its tests) instead of grading"},
        {"--timeout", Kind::value, "SEC", "a number", "wall-clock limit per test process (default 30)"},
        {"--timings", Kind::repeatable, "FILE", "a file name", "the reference's seconds per test (lines \"MNN<TAB>visible|hidden\n<TAB>SECONDS<TAB>NAME\", from --timings-out): a listed test's\nlimit is 20 times its reference time, at least 5 s, at most\n--timeout"},
        {"--timings-out", Kind::value, "FILE", "a file name", "write the seconds of every passed test in that form"},
        {"--jobs", Kind::value, "N", "a number", "test processes run at once (default: online CPUs)"},
        {"--json", Kind::value, "FILE", "a file name", "write Gradescope results.json to FILE"},
        {"--junit", Kind::value, "FILE", "a file name", "write JUnit XML to FILE"},
        {"--summary", Kind::value, "FILE", "a file name", "write the score table to FILE"},
        {"--reject", Kind::repeatable, "N=FILE", "N=FILE", "do not run module N's tests: each fails as \"rejected by the\nsource check\" with the first line of FILE (a report of\nfmbd-vet) as its reason and FILE as its output (repeatable);\nthe tests of an EXE --grades-inputs still run (also with\n--build-errors)"},
        {"--build-errors", Kind::repeatable, "N=FILE", "N=FILE", "module N does not compile: its tests fail unrun as \"does not\ncompile\", FILE (the first compiler errors) as their output"},
        {"--csv", Kind::value, "FILE", "a file name", "write one line per task: module,task,score,max_score,status\n(status: the worst of its tests, see report.hpp)"},
        {"--hidden-visibility", Kind::value, "V", "a value", "Gradescope visibility of [hidden] tests: hidden,\nafter_due_date, after_published (default), visible"},
        {"--run-as", Kind::value, "USER", "a user name", "run the tests as USER (the driver must be root; default\nwhen root: nobody); test programs are copied for USER"},
        {"--earlier-note", Kind::value, "TEXT", "a text", "where a test failed on an earlier module's task not implemented\nyet, the line under the table that names those tasks ends\nwith TEXT (the front end's advice)"},
        {"--quiet", Kind::flag, "", "", "print only failures and the score line"},
        {"--strict", Kind::flag, "", "", "exit 1 unless every test passed"},
        {"--expect-not-implemented", Kind::flag, "", "", "self-test of the student stubs: exit 0 only if every test\nfailed with \"not implemented\" in its output"},
    };
    return s;
  }();
  return spec;
}

std::optional<long> parse_whole_number(const std::string& text) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos ||
      text.size() > 9) {
    return std::nullopt;
  }
  return std::stol(text);
}

std::optional<double> parse_seconds(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(value > 0) || value > 86400) return std::nullopt;
  return value;
}

unsigned online_cpus() {
  const long count = ::sysconf(_SC_NPROCESSORS_ONLN);
  return count > 0 ? static_cast<unsigned>(count) : 1U;
}

// --module N or MNN.
std::optional<int> parse_module(const std::string& text) {
  const bool prefixed = !text.empty() && (text[0] == 'M' || text[0] == 'm');
  const auto module = parse_whole_number(prefixed ? text.substr(1) : text);
  return module ? std::optional<int>(static_cast<int>(*module)) : std::nullopt;
}

// --task MnnTk or MnnPk: a task id (common/task_id.hpp), the same rule for every kind.
std::optional<std::pair<int, Task>> parse_task(const std::string& text) {
  const std::optional<protocol::TaskId> task = protocol::parse_task_id(text);
  if (!task) return std::nullopt;
  return std::make_pair(task->module, Task{task->kind, task->number});
}

// --timings FILE (tables.hpp) into `seconds`, by timings_key.
void read_timings(const std::string& file, std::map<std::string, double>& seconds) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw UsageError{"--timings: cannot read " + file};
  std::ostringstream text;
  text << in.rdbuf();
  try {
    for (const Timing& timing : parse_timings(text.str(), file)) {
      seconds[timing.module + "\t" + timing.name] = timing.seconds;
    }
  } catch (const TableError& error) {
    throw UsageError{std::string("--timings: ") + error.what()};
  }
}

// --reject N=REPORT and --build-errors N=REPORT: module N's tests do not run, with the report.
void read_unrun(const std::string& option, const std::string& text, Options& options) {
  const std::size_t equals = text.find('=');
  const std::optional<int> module = equals == std::string::npos ? std::nullopt : parse_module(text.substr(0, equals));
  if (!module) throw UsageError{"invalid value for " + option + ": '" + text + "'"};
  const std::string path = text.substr(equals + 1);
  std::ifstream file(path);
  std::ostringstream report;
  report << file.rdbuf();
  if (!file || report.str().find_first_not_of(" \t\r\n") == std::string::npos)
    throw UsageError{option + ": cannot read a report from '" + path + "'"};
  options.unrun[*module] = UnrunModule{option == "--reject" ? Status::rejected : Status::build_error, report.str()};
}

// --run-as USER: an unprivileged user, and only as root.
Identity run_as_user(const std::string& name) {
  if (::geteuid() != 0) throw UsageError{"--run-as needs root (the driver switches to " + name + ")"};
  const std::optional<Identity> user = find_identity(name);
  if (!user) throw UsageError{"--run-as: no user '" + name + "' on this system"};
  if (user->uid == 0) throw UsageError{"--run-as: '" + name + "' is root; give an unprivileged user"};
  return *user;
}

UsageError invalid(const std::string& option, const std::string& text) {
  return UsageError{"invalid value for " + option + ": '" + text + "'"};
}

// The test programs, in order: each EXE, and the LISTER of a --listed-by and a --grades-inputs
// after it.
void read_programs(const cli::Parsed& parsed, Options& options) {
  for (const auto& [name, value] : parsed.sequence) {
    if (name == command().positional) {
      options.programs.push_back({value, value, false});
    } else if (name == "--grades-inputs") {
      if (options.programs.empty()) {
        throw UsageError{"--grades-inputs follows the test program it describes: EXE --grades-inputs"};
      }
      options.programs.back().grades_inputs = true;
    } else if (name == "--listed-by") {
      if (options.programs.empty() || options.programs.back().lister != options.programs.back().executable)
        throw UsageError{"--listed-by LISTER follows the test program it lists: EXE --listed-by LISTER"};
      options.programs.back().lister = value;
    }
  }
}

// What to grade: --module, --task.
void read_selection(const cli::Parsed& parsed, Options& options) {
  for (const std::string& text : parsed.all("--module")) {
    const std::optional<int> module = parse_module(text);
    if (!module) throw invalid("--module", text);
    options.modules.push_back(*module);
  }
  for (const std::string& text : parsed.all("--task")) {
    const auto task = parse_task(text);
    if (!task) throw invalid("--task", text);
    options.tasks.push_back(*task);
  }
}

// How to run the tests: --timeout, --timings, --jobs, --run-as, --reject, --build-errors.
void read_limits(const cli::Parsed& parsed, Options& options) {
  if (parsed.has("--timeout")) {
    const auto seconds = parse_seconds(parsed.value("--timeout"));
    if (!seconds) throw invalid("--timeout", parsed.value("--timeout"));
    options.timeout_seconds = *seconds;
  }
  for (const std::string& file : parsed.all("--timings")) read_timings(file, options.reference_seconds);
  if (parsed.has("--jobs")) {
    const auto jobs = parse_whole_number(parsed.value("--jobs"));
    if (!jobs || *jobs < 1 || *jobs > 1024) throw invalid("--jobs", parsed.value("--jobs"));
    options.jobs = static_cast<unsigned>(*jobs);
  }
  if (parsed.has("--run-as")) options.run_as = run_as_user(parsed.value("--run-as"));
  for (const char* option : {"--reject", "--build-errors"}) {
    for (const std::string& text : parsed.all(option)) read_unrun(option, text, options);
  }
}

// What to write: the results files, --hidden-visibility, and the flags.
void read_outputs(const cli::Parsed& parsed, Options& options) {
  options.timings_out_file = parsed.value("--timings-out");
  options.json_file = parsed.value("--json");
  options.junit_file = parsed.value("--junit");
  options.summary_file = parsed.value("--summary");
  options.csv_file = parsed.value("--csv");
  options.earlier_note = parsed.value("--earlier-note");
  if (parsed.has("--hidden-visibility")) {
    options.hidden_visibility = parsed.value("--hidden-visibility");
    if (!is_visibility(options.hidden_visibility)) throw invalid("--hidden-visibility", options.hidden_visibility);
  }
  options.list_tasks = parsed.has("--list-tasks");
  options.quiet = parsed.has("--quiet");
  options.strict = parsed.has("--strict");
  options.expect_not_implemented = parsed.has("--expect-not-implemented");
}

// The checks across options, once all are read.
void check_options(Options& options) {
  if (options.programs.empty()) throw UsageError{"no test program given"};
  // Root runs student code only as an unprivileged user: resource limits such as the
  // process count do not bind root, and root could change any file.
  if (!options.run_as && ::geteuid() == 0) {
    options.run_as = find_identity("nobody");
    if (!options.run_as || options.run_as->uid == 0)
      throw UsageError{"running as root: give an unprivileged user for the tests with --run-as USER"};
  }
  if (options.strict && options.expect_not_implemented) {
    throw UsageError{"--strict and --expect-not-implemented exclude each other"};
  }
}

}  // namespace

// The help, from the table.
std::string usage() {
  std::string text = "usage: " + cli::synopsis(command()) + "\n\n";
  for (const std::string& line : command().help) text += line + "\n";
  return text + "\noptions:\n" + cli::option_table(command()) +
         "\nexit status: 0 done, 1 --strict/--expect-not-implemented unmet, 2 usage error,\n4 internal error\n";
}

Options parse_options(int argc, char** argv) {
  Options options;
  options.jobs = online_cpus();
  const cli::Parsed parsed = cli::parse(command(), std::vector<std::string>(argv + 1, argv + argc));
  if (parsed.help) {
    options.help = true;
    return options;
  }
  read_programs(parsed, options);
  read_selection(parsed, options);
  read_limits(parsed, options);
  read_outputs(parsed, options);
  check_options(options);
  return options;
}

}  // namespace fmbd::grade
