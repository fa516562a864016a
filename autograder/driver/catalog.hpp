#pragma once
// The graded tests: which programs to run, what they list, and how each test is invoked.
//
// The test list that programs print, and its reader: listing.hpp.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "grading_protocol.hpp"
#include "listing.hpp"
#include "sandbox.hpp"

namespace fmbd::grade {

// A test program: `executable` runs the tests, `lister` lists them (the arguments
// `EXE --listed-by LISTER`, each path as it is; the lister is EXE itself without one). An
// instructor may list from a trusted build so that a student build cannot hide tests.
// `grades_inputs` (`EXE --grades-inputs`): it grades the student's inputs (an answers file), not
// the module's code, so a module's --reject or --build-errors leaves its tests alone.
struct TestProgram {
  std::string executable;
  std::string lister;
  bool grades_inputs = false;
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

// `name` as a Catch v2 test spec that selects exactly that test (the protocol's escaping).
using protocol::catch_test_spec;

}  // namespace fmbd::grade
