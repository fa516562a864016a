#pragma once
// Reporting graded results: the plain table for people, results.json for Gradescope,
// JUnit XML for CI. All three list the results in the order given (by module, task, then
// listing order); the driver sorts them before reporting.

#include <string>
#include <vector>

#include "catalog.hpp"

namespace fmbd::grade {

// How a test ended, from best to worst. A task's status is the worst of its tests'.
enum class Status {
  passed,
  failed,           // a check failed (Catch's status 1)
  not_implemented,  // a stub's "not implemented yet"
  crashed,          // a signal, another exit status, no completion token, or no listing
  timed_out,
  rejected,         // not run: the source check refused the module (--reject)
  build_error,      // not run: the module does not compile (--build-errors)
};

// "passed", "failed", "not_implemented", "crashed", "timed_out", "rejected", "build_error".
const char* status_name(Status status);

// A module whose tests are not run: why (rejected or build_error), and the report that says
// where (the source check's findings, or the compiler's first errors).
struct UnrunModule {
  Status status = Status::rejected;
  std::string report;
};

struct TestResult {
  TestCase test;  // a program that could not be listed appears as one pseudo-test
                  // worth 0 points, without module or task
  bool passed = false;
  std::string reason;  // one line; empty when passed
  std::string output;  // what the test printed (at most 64 KiB and a truncation note)
  double seconds = 0;
  Status status = Status::failed;
  std::string rerun;  // for a crash, a timeout or a cut reason: the command that runs this test alone
};

struct Totals {
  double score = 0;
  double max_score = 0;
  std::size_t passed = 0;
  std::size_t failed = 0;
};

Totals totals(const std::vector<TestResult>& results);

// The table grouped by module, e.g.
//   M01  ..........................................................  12/20
//     T1  3/3  PASS  planar rotation is orthonormal
//     T2  0/4  FAIL  revolute joint: C_q matches finite differences  -- not implemented yet: ...
//   Score: 12/20
// A crashed or timed-out test gets a second line, "run it alone: COMMAND".
// `failures_only` leaves out the passing tests and the module lines.
std::string format_table(const std::vector<TestResult>& results, bool failures_only);

// The line under the table where tests failed because a task of an earlier module than theirs is
// not implemented yet (the stub's "not implemented yet: M02T3 ..."), e.g. "Tests of M07 failed on
// earlier modules' tasks not implemented yet: M02T3, M02T4. " and `advice`; "" where none did.
std::string earlier_stubs_line(const std::vector<TestResult>& results, const std::string& advice);

// Gradescope's results.json. `hidden_visibility` is the visibility of [hidden] tests; `notes`
// (one line each, e.g. why a module was rejected) follow the summary in the top-level output.
// stdout_visibility is "hidden": the run's stdout is the build log of the whole grader (it
// names the hidden tests); everything a student needs, compiler errors included, is in the
// output of the tests and the top level.
std::string gradescope_json(const std::vector<TestResult>& results, double seconds,
                            const std::string& hidden_visibility,
                            const std::vector<std::string>& notes = {});

// The results.json of a grading that did not run (the front end's, where grading stops, and
// Gradescope's run_autograder's, where the grader itself did not run: ./workbook grade
// --failed-results): a score of 0, no tests, and `output` saying why; stdout hidden as above.
std::string failed_results_json(const std::string& output);

// JUnit XML: one <testsuite> per module, one <testcase classname="M01.T2"> per test; a
// failure's type attribute is its status_name().
std::string junit_xml(const std::vector<TestResult>& results, double seconds);

// One CSV line per task, "M01,T2,3,4,failed", under the header
// "module,task,score,max_score,status": the task's points and the worst status of its tests.
std::string task_csv(const std::vector<TestResult>& results);

// Writes `content` to a temporary file next to `path` (making its folders), then renames it
// over `path`, so a reader never sees a half-written file. Throws std::system_error on failure.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace fmbd::grade
