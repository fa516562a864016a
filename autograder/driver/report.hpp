#pragma once
// Reporting graded results: the plain table for people, results.json for Gradescope,
// JUnit XML for CI. All three list the results in the order given (by module, task, then
// listing order); the driver sorts them before reporting.

#include <string>
#include <vector>

#include "catalog.hpp"

namespace fmbd::grade {

struct TestResult {
  TestCase test;  // a program that could not be listed appears as one pseudo-test
                  // worth 0 points, without module or task
  bool passed = false;
  std::string reason;  // one line; empty when passed
  std::string output;  // what the test printed (at most 64 KiB and a truncation note)
  double seconds = 0;
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
// `failures_only` leaves out the passing tests and the module lines.
std::string format_table(const std::vector<TestResult>& results, bool failures_only);

// Gradescope's results.json. `hidden_visibility` is the visibility of [hidden] tests; `notes`
// (one line each, e.g. why a module was rejected) follow the summary in the top-level output.
std::string gradescope_json(const std::vector<TestResult>& results, double seconds,
                            const std::string& hidden_visibility,
                            const std::vector<std::string>& notes = {});

// JUnit XML: one <testsuite> per module, one <testcase classname="M01.T2"> per test.
std::string junit_xml(const std::vector<TestResult>& results, double seconds);

// Writes `content` to a temporary file next to `path`, then renames it over `path`, so a
// reader never sees a half-written file. Throws std::system_error on failure.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace fmbd::grade
