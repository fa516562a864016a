#pragma once
// The graded tests: which programs to run, what they list, and how each test is invoked.
//
// The test list that programs print, and its reader: listing.hpp.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "listing.hpp"
#include "sandbox.hpp"

namespace fmbd::grade {

// A test program: `executable` runs the tests, `lister` lists them (the arguments
// `EXE --listed-by LISTER`, each path as it is; the lister is EXE itself without one). An
// instructor may list from a trusted build so that a student build cannot hide tests.
struct TestProgram {
  std::string executable;
  std::string lister;
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

// The command that runs exactly `test`, with its completion token on fd 3; a name that
// matches no test fails. The program stops itself after `time_limit_seconds` (a little less
// than the driver's timeout), naming the last check it reached.
std::vector<std::string> test_command(const TestCase& test, double time_limit_seconds);

// `name` as a Catch v2 test spec that selects exactly that test: quoted, with a backslash
// before each of \ , [ ] * ~ ". Catch v2 cannot select a name that starts with "exclude:"
// and still treats a '*' at either end as a wildcard; no course test is named like that.
std::string catch_test_spec(std::string_view name);

}  // namespace fmbd::grade
