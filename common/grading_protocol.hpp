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
//   FMBD_HINTS_OPENED=FILE              the hint levels the student opened (below): a failure
//                                       message shows a task's formula only at its last level
//
// The fixture of a new kind of graded item (autograder/fixtures/answers/answers_kind.cpp, a course
// of its own: tests/graded_kind_check.sh) speaks it through this library too.

// The constants and listing_line() are inline: catch_main.cpp, an object file linked into every
// test program, uses them without linking this folder's library.

#include <algorithm>
#include <cstddef>
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

// The hint levels a student opened, as ./workbook hint writes them (build/hints.opened, one
// "TASK LEVEL" line per task, blank-separated) and a test program reads them: the file that
// FMBD_HINTS_OPENED names; set but empty, none (the instructor's grader, for every submission);
// unset, the file of the tree the program was built in (a test program run by hand).
inline constexpr const char* kHintsOpenedVariable = "FMBD_HINTS_OPENED";
// Below the tree: where ./workbook hint keeps them.
inline constexpr const char* kHintsOpenedFile = "build/hints.opened";
// The level of every hint ladder that holds the worked formula: its last (tests/hints_check.sh
// keeps every ladder at three levels).
inline constexpr int kFormulaHintLevel = 3;

// The level opened for `task` ("M01T2") in the text of a hints.opened file: the second field of
// the last line whose first field is `task`, its leading digits ("2x" is 2); 0 when no line names
// the task.
inline int opened_hint_level(std::string_view opened, std::string_view task) {
  int level = 0;
  while (!opened.empty()) {
    const std::size_t newline = opened.find('\n');
    std::string_view line = opened.substr(0, newline);
    opened = newline == std::string_view::npos ? std::string_view() : opened.substr(newline + 1);
    std::string_view fields[2];
    for (std::string_view& field : fields) {
      const std::size_t begin = line.find_first_not_of(" \t");
      line = begin == std::string_view::npos ? std::string_view() : line.substr(begin);
      const std::size_t end = std::min(line.find_first_of(" \t"), line.size());
      field = line.substr(0, end);
      line.remove_prefix(end);
    }
    if (fields[0] != task) continue;
    level = 0;
    for (const char c : fields[1]) {
      if (c < '0' || c > '9' || level > 1000) break;
      level = level * 10 + (c - '0');
    }
  }
  return level;
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
