#include "catalog.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <locale>
#include <sstream>

#include "text.hpp"
#include "verdict.hpp"

namespace fmbd::grade {
namespace {

std::string file_name(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

std::vector<std::string> listing_command(const TestProgram& program) {
  return {program.lister, protocol::kListOption};
}

Listing parse_listing(const TestProgram& program, const Outcome& outcome, double timeout_seconds) {
  Listing listing;
  const auto fail = [&listing](const std::string& reason) {
    listing.tests.clear();
    listing.error = reason;
    return listing;
  };
  if (outcome.ending != Ending::exited || outcome.status != 0) {
    return fail("test program failed before any test ran: " +
                explain_failure(outcome, timeout_seconds));
  }
  if (outcome.truncated) return fail("test program printed a test list that is too long");

  ParsedList parsed = parse_test_list(outcome.output, program.executable);
  if (!parsed.error.empty()) return fail(parsed.error);
  listing.tests = std::move(parsed.tests);
  for (TestCase& test : listing.tests) test.grades_inputs = program.grades_inputs;
  if (listing.tests.empty()) {
    listing.ran_and_listed_none = true;
    listing.error = "test program " + file_name(program.lister) + " lists no tests";
  }
  return listing;
}

std::vector<std::string> test_command(const TestCase& test, double time_limit_seconds) {
  // Without "--warn NoTests", Catch v2 exits 0 when the spec matches no test at all. The compact
  // reporter writes each failed check on one line, unwrapped (verdict.cpp reads it).
  return {test.executable, protocol::kTokenFdOption, "3", protocol::kTimeLimitOption, format_number(time_limit_seconds),
          "--reporter", "compact", "--use-colour", "no", "--warn", "NoTests", catch_test_spec(test.name)};
}

}  // namespace fmbd::grade
