// fmbd-grade: runs the workbook's graded Catch tests, each in its own sandboxed process,
// and reports a score (plain table, Gradescope results.json, JUnit XML).
//
//   fmbd-grade [options] EXE [--listed-by LISTER] [--grades-inputs]...
//
// Its options are a table (command() below), read by the option layer it shares with the front
// end (cli.hpp, on CLI11); --help is made from the same table.
//
// Protocol with a test program (see autograder/support/catch_main.cpp):
//   LISTER --fmbd-list
//       prints one line per test case, "name<TAB>[tag][tag]...", and exits 0. Listing runs
//       student code (static initialisers), so it runs sandboxed like a test. If it fails,
//       the program contributes one failed entry that says why, and grading goes on.
//   EXE --fmbd-token-fd 3 --fmbd-time-limit S --use-colour no --warn NoTests "<escaped name>"
//       runs one test. fd 3 holds a fresh random token; once the Catch session has
//       returned with every check passed, the program prints
//       "fmbd-completion-token: <token>" as its last line. (--warn NoTests makes a name that
//       matches no test a failure.) After S seconds, a little less than the timeout, the
//       program stops itself with status 124 and a line "fmbd-time-limit: ..." that names the
//       last check it reached; the timeout stays the limit for a program that does not.
//   With EXE --listed-by LISTER, only LISTER's list counts: EXE is never asked for its tests, and
//   nothing it prints is read but the completion token of each test.
//   The environment: a program inherits the driver's, TMPDIR replaced by its own temporary
//   directory. Whoever starts the driver may set there, for the programs that read them, the two
//   variables of this protocol (the front end sets them for the graded items whose capabilities
//   ask for them, frontend/manifest.hpp); the driver neither reads nor changes them:
//     FMBD_ANSWERS_ROOT  a folder with a copy of each of the student's inputs (an answers file)
//                        at its path relative to the tree, readable by every user (the tests may
//                        run as another one); unset: the program reads them where it was built
//                        to (the tree's own, as a student runs it by hand)
//     FMBD_STUDENT       the student's identity that the grader trusts, whose numbers the program
//                        grades with; unset or empty: none (the program says that it needs one)
//   The programs read no other variable of the front end's. (FMBD_TIME_LIMIT is for a test
//   program run by hand, catch_main.cpp; --fmbd-time-limit overrides it.)
//
// Guarantees:
//   * A test passes only if its process exited with status 0 AND printed its own token,
//     which it cannot know in advance: exit(0) in the middle of a test, a crash, a forged
//     token line or a hang all fail, each with a one-line reason.
//   * Every test runs in its own process group, session and temporary directory, under
//     a wall-clock timeout and resource limits; its process group is killed when it ends
//     (details in sandbox.hpp). Output is captured up to 64 KiB per test.
//   * With --jobs N, up to N tests run at once; reports are always in the same order
//     (module, task, then listing order), whatever the timing.
//   * With --reject N=FILE, no test of module N runs: each fails with "rejected by the
//     source check: " and the first line of FILE (the report of fmbd-vet), FILE as its
//     output; the table and results.json say so at the top. --build-errors N=FILE does the
//     same for a module that does not compile ("does not compile: ", FILE holding the
//     compiler's first errors), so that a student sees them wherever the results go. Both
//     concern the module's code, so neither touches the tests of a program given with
//     --grades-inputs (EXE --grades-inputs): it declares that it grades the student's inputs (an
//     answers file), not the code. The front end says so of the graded items whose capabilities
//     give them inputs (frontend/manifest.hpp); the driver knows no kind of graded item, and no
//     code of it tests a task's kind letter.
//   * Results files are written by this process only, after all tests ran, each
//     atomically (temporary file + rename). Ctrl-C kills the running tests, writes nothing
//     and exits with 128 + the signal number.
//
// Exit status (as the front end's, frontend/exit_status.hpp): 0 normally (even if tests failed); 1
// when --strict or --expect-not-implemented is not satisfied; 2 on usage errors; 4 on an internal
// error.

#include <signal.h>
#include <sys/prctl.h>
#include <sys/signalfd.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <functional>
#include <map>
#include <sstream>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "catalog.hpp"
#include "cli.hpp"
#include "sandbox.hpp"
#include "report.hpp"
#include "tables.hpp"
#include "text.hpp"
#include "verdict.hpp"

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
        {"--quiet", Kind::flag, "", "", "print only failures and the score line"},
        {"--strict", Kind::flag, "", "", "exit 1 unless every test passed"},
        {"--expect-not-implemented", Kind::flag, "", "", "self-test of the student stubs: exit 0 only if every test\nfailed with \"not implemented\" in its output"},
    };
    return s;
  }();
  return spec;
}

// The help, from the table.
std::string usage() {
  std::string text = "usage: " + cli::synopsis(command()) + "\n\n";
  for (const std::string& line : command().help) text += line + "\n";
  return text + "\noptions:\n" + cli::option_table(command()) +
         "\nexit status: 0 done, 1 --strict/--expect-not-implemented unmet, 2 usage error,\n4 internal error\n";
}

constexpr std::size_t kKiB = 1024;
constexpr std::size_t kTestOutputBytes = 64 * kKiB;       // kept per test
constexpr std::size_t kListingOutputBytes = 1024 * kKiB;  // a test list may be long

struct Options {
  std::vector<TestProgram> programs;
  std::vector<int> modules;                 // empty: all modules
  std::vector<std::pair<int, Task>> tasks;  // (module, task); empty: all tasks
  bool list_tasks = false;
  double timeout_seconds = 30;
  std::map<std::string, double> reference_seconds;  // "MNN\tname" -> seconds (--timings)
  std::string timings_out_file;
  unsigned jobs = 1;
  std::string json_file;
  std::string junit_file;
  std::string summary_file;
  std::string csv_file;
  std::string hidden_visibility = "after_published";
  bool quiet = false;
  bool strict = false;
  bool expect_not_implemented = false;
  bool help = false;
  std::optional<Identity> run_as;
  std::map<int, UnrunModule> unrun;  // modules whose tests do not run, and why
};

using cli::UsageError;

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

// SIGINT, SIGTERM and SIGHUP are blocked and arrive through a signalfd, which the process
// runner polls; so an interruption needs no signal handler and no global flag. Test
// processes get an empty signal mask back before they exec.
class InterruptChannel {
 public:
  InterruptChannel() {
    ::sigemptyset(&signals_);
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) ::sigaddset(&signals_, signal);
    if (::sigprocmask(SIG_BLOCK, &signals_, &previous_) == 0) {
      fd_ = ::signalfd(-1, &signals_, SFD_CLOEXEC);
    }
    if (fd_ < 0) ::sigprocmask(SIG_SETMASK, &previous_, nullptr);  // fall back to the defaults
  }
  InterruptChannel(const InterruptChannel&) = delete;
  InterruptChannel& operator=(const InterruptChannel&) = delete;
  ~InterruptChannel() {
    if (fd_ >= 0) {
      ::close(fd_);
      ::sigprocmask(SIG_SETMASK, &previous_, nullptr);
    }
  }

  int fd() const { return fd_; }

  // The signal that arrived (consumed, so that it is not delivered again later).
  int take_signal() const {
    signalfd_siginfo info{};
    if (::read(fd_, &info, sizeof info) != static_cast<ssize_t>(sizeof info)) return SIGINT;
    return static_cast<int>(info.ssi_signo);
  }

 private:
  sigset_t signals_{};
  sigset_t previous_{};
  int fd_ = -1;
};

struct Interrupted {
  int signal;
};

std::vector<Outcome> run_or_throw(const std::vector<std::vector<std::string>>& commands,
                                  const Limits& limits, unsigned jobs,
                                  const InterruptChannel& interrupts) {
  auto outcomes = run_sandboxed(commands, limits, jobs, interrupts.fd());
  if (!outcomes) throw Interrupted{interrupts.take_signal()};
  return *std::move(outcomes);
}

bool selected(const TestCase& test, const Options& options) {
  const auto& modules = options.modules;
  const auto& tasks = options.tasks;
  const bool module_selected =
      modules.empty() ||
      (test.module && std::find(modules.begin(), modules.end(), *test.module) != modules.end());
  const bool task_selected =
      tasks.empty() || (test.module && test.task &&
                        std::find(tasks.begin(), tasks.end(),
                                  std::make_pair(*test.module, *test.task)) != tasks.end());
  return module_selected && task_selected;
}

TestResult listing_failure(const TestProgram& program, const std::string& reason) {
  TestResult result;
  const std::size_t slash = program.lister.find_last_of('/');
  result.test.executable = program.executable;
  result.test.name =
      program.lister.substr(slash == std::string::npos ? 0 : slash + 1) + ": listing the tests";
  result.test.points = 0;
  result.reason = shorten(single_line(reason), kMaxReasonLength);
  result.status = Status::crashed;
  return result;
}

// The selected tests in grading order, and one failed result for each program that could
// not be listed.
struct Catalog {
  std::vector<TestCase> tests;
  std::vector<TestResult> listing_failures;
};

// `text` quoted for a POSIX shell where it needs it.
std::string shell_word(const std::string& text) {
  if (!text.empty() && text.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789/._+-") ==
                           std::string::npos)
    return text;
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// Root runs the tests as an unprivileged user (--run-as), who may not be able to enter the folders
// of the course (a home folder of mode 700, say): then a test cannot read its files there, and a
// program that lists its tests from such a file lists none. Checked before listing: per program,
// the folders that user cannot enter and how to fix it (empty: none), each said once on stderr.
std::vector<std::string> check_access(const Options& options) {
  std::vector<std::string> problems(options.programs.size());
  if (!options.run_as) return problems;
  std::vector<std::string> said;
  for (std::size_t i = 0; i < options.programs.size(); ++i) {
    std::vector<std::string> closed = folders_closed_to(options.programs[i].lister, *options.run_as);
    for (const std::string& folder : folders_closed_to(options.programs[i].executable, *options.run_as))
      if (std::find(closed.begin(), closed.end(), folder) == closed.end()) closed.push_back(folder);
    if (closed.empty()) continue;
    std::string names;
    std::string words;
    for (const std::string& folder : closed) {
      names += (names.empty() ? "" : ", ") + folder;
      words += " " + shell_word(folder);
    }
    problems[i] = "the tests run as the user " + options.run_as->name + " (the grader runs as root), who cannot enter " +
                  names + "; fix: chmod o+rx" + words + ", or grade as a normal user (not root)";
    if (std::find(said.begin(), said.end(), problems[i]) == said.end()) {
      std::cerr << "fmbd-grade: " << problems[i] << "\n";
      said.push_back(problems[i]);
    }
  }
  return problems;
}

Catalog list_tests(const Options& options, const InterruptChannel& interrupts) {
  const std::vector<std::string> access_problems = check_access(options);
  std::vector<std::vector<std::string>> commands;
  for (const TestProgram& program : options.programs) commands.push_back(listing_command(program));
  const Limits limits{options.timeout_seconds, kListingOutputBytes, options.run_as, {}};
  const std::vector<Outcome> outcomes = run_or_throw(commands, limits, options.jobs, interrupts);

  Catalog catalog;
  for (std::size_t i = 0; i < options.programs.size(); ++i) {
    Listing listing = parse_listing(options.programs[i], outcomes[i], options.timeout_seconds);
    // A listing that failed where the tests' user cannot reach the program's folder: that is why
    // a program that ran lists nothing (it reads its list from there); another failure (a missing
    // program, a crash) is said first, the folder after it.
    if (!listing.error.empty() && !access_problems[i].empty()) {
      listing.error = listing.ran_and_listed_none ? access_problems[i] : listing.error + "; " + access_problems[i];
    }
    if (!listing.error.empty()) {
      TestResult failure = listing_failure(options.programs[i], listing.error);
      failure.output = shorten(outcomes[i].output, kTestOutputBytes);
      failure.seconds = outcomes[i].seconds;
      catalog.listing_failures.push_back(std::move(failure));
    }
    for (TestCase& test : listing.tests) {
      if (selected(test, options)) catalog.tests.push_back(std::move(test));
    }
  }
  // A test without module or task sorts first, like a program that could not be listed.
  std::stable_sort(catalog.tests.begin(), catalog.tests.end(),
                   [](const TestCase& a, const TestCase& b) {
                     return std::tie(a.module, a.task) < std::tie(b.module, b.task);
                   });
  return catalog;
}

// Why the module of `test` does not run, or nullptr.
const UnrunModule* unrun(const TestCase& test, const Options& options) {
  // A program of the student's inputs (--grades-inputs) grades an answers file, not the module's
  // code: a property of the program that the front end passes, not of a kind (the header says why).
  if (!test.module || test.grades_inputs) return nullptr;
  const auto found = options.unrun.find(*test.module);
  return found == options.unrun.end() ? nullptr : &found->second;
}

// "rejected by the source check: " or "does not compile: ", and the first non-empty line of
// the module's report.
std::string unrun_reason(const UnrunModule& module) {
  std::istringstream lines(module.report);
  std::string line;
  while (std::getline(lines, line) && line.find_first_not_of(" \t\r") == std::string::npos) {
  }
  const char* what = module.status == Status::rejected ? "rejected by the source check: " : "does not compile: ";
  return shorten(single_line(what + line), kMaxReasonLength);
}

// The command that runs `test` alone, its program's path relative to the current directory
// when it lies below it.
std::string rerun_command(const TestCase& test) {
  std::string program = test.executable;
  char cwd[4096];
  if (::getcwd(cwd, sizeof cwd) != nullptr) {
    const std::string prefix = std::string(cwd) + "/";
    if (starts_with(program, prefix)) program = "./" + program.substr(prefix.size());
  }
  return program + " " + catch_test_spec(test.name);
}

// How a test that ran ended, for the gradebook.
Status status_of(const Outcome& outcome, const Verdict& verdict) {
  if (verdict.passed) return Status::passed;
  if (outcome.ending == Ending::timed_out || stopped_by_time_limit(outcome)) return Status::timed_out;
  if (contains_ignoring_case(verdict.reason, "not implemented")) return Status::not_implemented;
  if (outcome.ending == Ending::exited && outcome.status == 1) return Status::failed;  // Catch's failed checks
  return Status::crashed;
}

std::string timings_key(const TestCase& test) { return module_label(test.module) + "\t" + test.name; }

// A test's timeout: a generous multiple of the reference's own time for it (--timings), with a
// floor for machines slower than the one that measured it, and never beyond --timeout. A looping
// test then costs seconds, not the whole --timeout. Tests the timings do not list get --timeout.
constexpr double kTimeoutMultiple = 20;
constexpr double kTimeoutFloor = 5;

double test_timeout(const TestCase& test, const Options& options) {
  const auto reference = options.reference_seconds.find(timings_key(test));
  if (reference == options.reference_seconds.end()) return options.timeout_seconds;
  return std::min(options.timeout_seconds, std::max(kTimeoutFloor, kTimeoutMultiple * reference->second));
}

// Runs every test whose module can run; the tests of a rejected or uncompiled module fail
// with its reason, unrun.
std::vector<TestResult> run_tests(const std::vector<TestCase>& tests, const Options& options,
                                  const InterruptChannel& interrupts) {
  std::vector<std::vector<std::string>> commands;
  commands.reserve(tests.size());
  Limits limits{options.timeout_seconds, kTestOutputBytes, options.run_as, {}};
  for (const TestCase& test : tests) {
    if (unrun(test, options)) continue;
    // The test stops itself a little before the driver's timeout, to name the last check it reached.
    const double timeout = test_timeout(test, options);
    const double margin = std::min(3.0, std::max(0.5, 0.1 * timeout));
    commands.push_back(test_command(test, std::max(0.5 * timeout, timeout - margin)));
    limits.command_timeouts.push_back(timeout);
  }
  const std::vector<Outcome> outcomes = run_or_throw(commands, limits, options.jobs, interrupts);

  std::vector<TestResult> results;
  std::size_t next = 0;
  for (const TestCase& test : tests) {
    if (const UnrunModule* module = unrun(test, options)) {
      results.push_back({test, false, unrun_reason(*module), module->report, 0, module->status, ""});
      continue;
    }
    const double timeout = limits.command_timeouts[next];
    const Outcome& outcome = outcomes[next++];
    const Verdict verdict = judge(outcome, timeout);
    const Status status = status_of(outcome, verdict);
    const bool rerun = status == Status::crashed || status == Status::timed_out;
    results.push_back({test, verdict.passed, verdict.reason, outcome.output, outcome.seconds, status,
                       rerun ? rerun_command(test) : ""});
  }
  return results;
}

// One line per module that did not run, for the top of the table; for results.json, where
// nothing else shows them, with the compiler's errors below it.
std::vector<std::string> unrun_notes(const Options& options, bool with_build_errors) {
  std::vector<std::string> notes;
  for (const auto& [module, why] : options.unrun) {
    std::string note = module_label(module) + " scores 0: " + unrun_reason(why);
    if (with_build_errors && why.status == Status::build_error) note += "\n" + why.report;
    notes.push_back(note);
  }
  return notes;
}

// --expect-not-implemented: every test must fail, and say "not implemented".
bool all_not_implemented(const std::vector<TestResult>& results) {
  bool ok = !results.empty();
  if (results.empty()) std::cout << "expect-not-implemented: no tests were graded\n";
  for (const TestResult& result : results) {
    const bool stub_failure =
        !result.passed && (contains_ignoring_case(result.reason, "not implemented") ||
                           contains_ignoring_case(result.output, "not implemented"));
    if (stub_failure) continue;
    ok = false;
    std::cout << "expect-not-implemented: " << module_label(result.test.module) << " "
              << task_label(result.test.task) << " " << single_line(result.test.name) << ": "
              << (result.passed ? "passed, but it should fail with \"not implemented\""
                                : "failed without \"not implemented\": " + result.reason)
              << "\n";
  }
  return ok;
}

// --list-tasks: the points of each selected task, in grading order.
int print_tasks(const Catalog& catalog) {
  for (const TestResult& failure : catalog.listing_failures) {
    std::cerr << "fmbd-grade: " << failure.test.name << ": " << failure.reason << "\n";
  }
  std::vector<std::tuple<std::optional<int>, std::optional<Task>, double>> tasks;
  for (const TestCase& test : catalog.tests) {
    if (tasks.empty() || std::get<0>(tasks.back()) != test.module ||
        std::get<1>(tasks.back()) != test.task) {
      tasks.emplace_back(test.module, test.task, 0.0);
    }
    std::get<2>(tasks.back()) += test.points;
  }
  for (const auto& [module, task, points] : tasks) {
    std::cout << module_label(module) << " " << task_label(task) << " " << format_number(points)
              << "\n";
  }
  return catalog.listing_failures.empty() ? 0 : 1;
}

int grade(const Options& options) {
  const auto start = std::chrono::steady_clock::now();
  const InterruptChannel interrupts;

  Catalog catalog = list_tests(options, interrupts);
  if (options.list_tasks) return print_tasks(catalog);
  std::vector<TestResult> results = std::move(catalog.listing_failures);
  for (TestResult& result : run_tests(catalog.tests, options, interrupts)) {
    results.push_back(std::move(result));
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::vector<std::string> notes = unrun_notes(options, false);
  std::string header;
  for (const std::string& note : notes) header += note + "\n";
  std::cout << header << format_table(results, options.quiet) << std::flush;
  if (!options.summary_file.empty()) {
    write_file_atomically(options.summary_file, header + format_table(results, false));
  }
  if (!options.json_file.empty()) {
    write_file_atomically(options.json_file,
                          gradescope_json(results, seconds, options.hidden_visibility, unrun_notes(options, true)));
  }
  if (!options.junit_file.empty()) {
    write_file_atomically(options.junit_file, junit_xml(results, seconds));
  }
  if (!options.csv_file.empty()) write_file_atomically(options.csv_file, task_csv(results));
  if (!options.timings_out_file.empty()) {
    std::vector<Timing> timings;
    for (const TestResult& result : results) {
      if (!result.passed) continue;
      const double hundredths = std::ceil(std::max(result.seconds, 0.01) * 100);  // rounded up, for stable files
      timings.push_back({module_label(result.test.module), result.test.hidden, hundredths / 100, result.test.name});
    }
    write_file_atomically(options.timings_out_file, timings_text(timings));
  }

  const Totals all = totals(results);
  if (options.strict) {
    if (all.failed == 0 && !results.empty()) return 0;
    std::cout << "strict: "
              << (results.empty() ? "no tests were graded"
                                  : std::to_string(all.failed) + " of " +
                                        std::to_string(results.size()) + " tests failed")
              << "\n";
    return 1;
  }
  if (options.expect_not_implemented) return all_not_implemented(results) ? 0 : 1;
  return 0;
}

}  // namespace
}  // namespace fmbd::grade

int main(int argc, char** argv) {
  using namespace fmbd::grade;
  // The driver holds the tokens of the running tests: no process of the same user may read
  // its memory (/proc/PID/mem) or descriptors.
  ::prctl(PR_SET_DUMPABLE, 0);
  try {
    const Options options = parse_options(argc, argv);
    if (options.help) {
      std::cout << usage();
      return 0;
    }
    return grade(options);
  } catch (const UsageError& error) {
    std::cerr << "fmbd-grade: " << error.what() << "\n\n" << usage();
    return 2;
  } catch (const Interrupted& interrupted) {
    std::cerr
        << "fmbd-grade: interrupted; the running tests were killed and no results were written\n";
    return 128 + interrupted.signal;
  } catch (const std::exception& error) {
    std::cerr << "fmbd-grade: internal error: " << error.what() << '\n';
    return 4;
  }
}
