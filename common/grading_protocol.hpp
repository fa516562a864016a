#pragma once
// The grading protocol between the grade driver (autograder/driver/grade.cpp, which describes it
// in full) and a test program (autograder/support/catch_main.cpp for the Catch programs; the
// tutorial problems' program, problems/program.cpp): the options, the lines and the escaping that
// both sides write and read, each defined once here.
//
//   PROGRAM --fmbd-list                 one listing line per test: "name<TAB>[tag][tag]..."
//   PROGRAM --fmbd-token-fd N ... SPEC  runs the test SPEC names (a Catch test spec: the name
//                                       quoted, special characters escaped); after a pass its last
//                                       line is "fmbd-completion-token: <token>", the token read
//                                       from descriptor N
//   --fmbd-time-limit S                 the test stops itself after S seconds with a line
//                                       "fmbd-time-limit: ..."
// The fixture of a new kind of graded item (autograder/fixtures/answers/answers_kind.cpp, a course
// of its own: tests/graded_kind_check.sh) speaks it through this library too.

// The constants and listing_line() are inline: catch_main.cpp, an object file linked into every
// test program, uses them without linking this folder's library.

#include <string>
#include <string_view>

#include "task_id.hpp"

namespace fmbd::protocol {

inline constexpr const char* kListOption = "--fmbd-list";
inline constexpr const char* kTokenFdOption = "--fmbd-token-fd";
inline constexpr const char* kTimeLimitOption = "--fmbd-time-limit";

// The completion token's line, "fmbd-completion-token: <token>".
inline constexpr const char* kCompletionTokenPrefix = "fmbd-completion-token: ";
// The line of a test that stopped itself at its time limit starts so.
inline constexpr std::string_view kTimeLimitPrefix = "fmbd-time-limit: ";

// One line of --fmbd-list: "name<TAB>tags\n" (tags: "[M01][T3][points=2]...").
inline std::string listing_line(std::string_view name, std::string_view tags) {
  std::string line(name);
  line += '\t';
  line += tags;
  line += '\n';
  return line;
}

// The tags of a task in a listing line: "[M01][P2][points=3]" for {1, 'P', 2} and "3", the points
// as the program writes them.
std::string task_tags(const TaskId& task, std::string_view points);

// `name` as a Catch v2 test spec that selects exactly that test: quoted, with a backslash
// before each of \ , [ ] * ~ ". Catch v2 cannot select a name that starts with "exclude:"
// and still treats a '*' at either end as a wildcard; no course test is named like that.
std::string catch_test_spec(std::string_view name);

// The test name a spec of catch_test_spec() selects: the quotes removed, each backslash taken as
// escaping the character after it. A bare name is itself.
std::string test_name_of_spec(std::string_view spec);

}  // namespace fmbd::protocol
