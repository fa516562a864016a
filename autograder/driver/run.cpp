#include "run.hpp"

#include <signal.h>
#include <sys/signalfd.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "catalog.hpp"
#include "sandbox.hpp"
#include "report.hpp"
#include "tables.hpp"
#include "text.hpp"
#include "verdict.hpp"

namespace fmbd::grade {
namespace {

constexpr std::size_t kKiB = 1024;
constexpr std::size_t kTestOutputBytes = 64 * kKiB;       // kept per test
constexpr std::size_t kListingOutputBytes = 1024 * kKiB;  // a test list may be long

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
  result.reason = fitted_line(reason);
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
  return fitted_line(what + line);
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
    // A crash, a timeout, or a message cut for the table: the command that shows all of it.
    const bool rerun = status == Status::crashed || status == Status::timed_out || verdict.cut;
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

}  // namespace

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
  const std::string earlier = earlier_stubs_line(results, options.earlier_note);
  std::cout << header << format_table(results, options.quiet) << earlier << std::flush;
  if (!options.summary_file.empty()) {
    write_file_atomically(options.summary_file, header + format_table(results, false) + earlier);
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

}  // namespace fmbd::grade
