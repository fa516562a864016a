#pragma once
// The graded tests: which programs to run, what they list, and how each test is invoked.
//
// A test program lists its tests with `PROGRAM --fmbd-list`: one line per test case,
// "name<TAB>[tag][tag]...". The tags that matter for grading are
//   [Mnn]       module number           (missing: the test belongs to no module)
//   [Tk]        task number             (missing: no task)
//   [Pk]        number of a task of the student's inputs, such as a tutorial problem (MnnPk
//               beside MnnTk): the test grades an answers file, not the module's code
//   [points=p]  weight, p >= 0          (missing: 1 point)
//   [hidden]    a hidden test (Gradescope shows it only after publication)
// and are read case-insensitively; other tags are ignored.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sandbox.hpp"

namespace fmbd::grade {

// A test program: `executable` runs the tests, `lister` lists them (the arguments
// `EXE --listed-by LISTER`, each path as it is; the lister is EXE itself without one). An
// instructor may list from a trusted build so that a student build cannot hide tests.
struct TestProgram {
  std::string executable;
  std::string lister;
};

// A task of a module: a task of the code ('T', "T3") or of the student's inputs, such as a
// tutorial problem ('P', "P2"). The letter is part of the task id, which the program's listing
// gives (its tags), whatever the kind of graded item: no code of the driver tests a kind. The
// code's tasks come first, then those of the inputs, each by number.
struct Task {
  char kind = 'T';
  int number = 0;

  friend bool operator==(const Task& a, const Task& b) { return a.kind == b.kind && a.number == b.number; }
  friend bool operator!=(const Task& a, const Task& b) { return !(a == b); }
  friend bool operator<(const Task& a, const Task& b) {
    return a.kind != b.kind ? a.kind == 'T' : a.number < b.number;
  }
};

struct TestCase {
  std::string executable;
  std::string name;
  std::optional<int> module;
  std::optional<Task> task;
  double points = 1;
  bool hidden = false;
};

// What listing one program produced: its tests, or why there are none (`error` is then
// a one-line reason such as "test program failed before any test ran: ...").
struct Listing {
  std::vector<TestCase> tests;
  std::string error;
  bool ran_and_listed_none = false;  // the program ran and printed no test (error says so)
};

std::vector<std::string> listing_command(const TestProgram& program);
Listing parse_listing(const TestProgram& program, const Outcome& outcome, double timeout_seconds);

// Reads the grading tags into `test`; returns an error message for a malformed tag list.
std::optional<std::string> apply_tags(std::string_view tags, TestCase& test);

// The command that runs exactly `test`, with its completion token on fd 3; a name that
// matches no test fails. The program stops itself after `time_limit_seconds` (a little less
// than the driver's timeout), naming the last check it reached.
std::vector<std::string> test_command(const TestCase& test, double time_limit_seconds);

// `name` as a Catch v2 test spec that selects exactly that test: quoted, with a backslash
// before each of \ , [ ] * ~ ". Catch v2 cannot select a name that starts with "exclude:"
// and still treats a '*' at either end as a wildcard; no course test is named like that.
std::string catch_test_spec(std::string_view name);

// "M01" for module 1, "other" for tests without a module; "T2" or "P2", or "-" without a task.
std::string module_label(const std::optional<int>& module);
std::string task_label(const std::optional<Task>& task);

}  // namespace fmbd::grade
