#pragma once
// ./workbook inspect FORMAT FILE: the project's own files read for scripts (the project's tests,
// Gradescope's setup.sh), each by the code that writes it, so that no script parses one itself:
//
//   inspect tasks FILE         a table of tasks (grade --csv, a class's NAME/tasks.csv; written and
//                              read by common/tables.hpp), with one of
//                                --sum score|max_score   the column's sum
//                                --count                 the number of tasks
//                                --full                  every task at its maximum; those that are
//                                                        not are named ("M01 T2: 1 of 3, failed")
//                              and optionally --of CAPABILITY: only the tasks of the graded items
//                              with that capability of the course manifest (manifest.hpp), as
//                              the grade driver lists them (--list-tasks) from the items' built
//                              programs; --manifest FILE: the manifest of the build that graded
//                              (default: this copy's, build/student/course.json)
//   inspect gradebook FILE     a class's gradebook.csv (grade.hpp): whether its columns add up,
//                              naming each submission whose do not
//   inspect timings FILE       autograder/timings.txt (tables.hpp): "MNN<TAB>NAME" per timed test,
//                              the key by which the driver finds its time
//   inspect policy FILE --rule RULE   the release policy (release.hpp): RULE's arguments, a line
//                              each
//   inspect classroom FILE     a GitHub Classroom workflow (classroom.hpp): its command-grader
//                              steps, "ID<TAB>MAX_SCORE<TAB>COMMAND" each, or --count of them, or
//                              --sum max_score of their points
//   inspect listing FILE       a test program's --fmbd-list output (common/listing.hpp,
//                              the grade driver's reader): "MNN<TAB>NAME" per test
//   inspect bench FILE         a benchmark CSV (maintainer.hpp): "N rows"
//
// Exit status (exit_status.hpp): 0 done; 1 the check failed (a gradebook that does not add up,
// a task below its maximum, or none selected, for --full) or FILE is not in its format; 2 a wrong
// command line, a FILE that cannot be read, or a program that lists the tasks not built.

#include <string>
#include <vector>

#include "context.hpp"
#include "options.hpp"

namespace fmbd::frontend {

const CommandSpec& inspect_command();
int run_inspect(const std::vector<std::string>& args, const Context& context);

}  // namespace fmbd::frontend
