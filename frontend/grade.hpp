#pragma once
// ./workbook grade: builds and grades this tree's code, a student's submission in a pristine copy
// of it, or a whole class of submissions into a gradebook. The options and their messages are
// the command's table (grade_command()); ./workbook help prints them.
//
// One tree: every selected module is built in one build that goes on past errors (its progress
// shown, build.hpp), then each module on its own: a module that does not compile scores 0 with
// its first errors, one whose code the source check (fmbd-vet) refuses scores 0 with its reason,
// the others are graded by the grade driver (fmbd-grade) on the test list of the reference build
// where there is one. The driver prints the score table and writes the results files. The steps
// (a pure plan, the build, the driver's invocation) are in grade_plan.hpp.
//
// A class (--submissions DIR --out OUT): every subfolder of DIR in turn, each graded as a
// submission into OUT/NAME/ (grade.txt, results.json, junit.xml, tasks.csv, logs/), a line each
// as it goes, and OUT/gradebook.csv rebuilt from the tasks.csv files after every submission: a
// row per submission, "submission,score,max_score,status", then a column per module and per
// task. --resume skips the submissions graded already.

#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

#include "context.hpp"
#include "manifest.hpp"
#include "options.hpp"
#include "tables.hpp"

namespace fmbd::frontend {

const CommandSpec& grade_command();

// The variable that hands the tests the hint levels whose formulas their messages may show
// (hint_gate.hpp): the student's own, build/hints.opened of `root`, when the tree itself is graded;
// none (an empty value) for a `submission`, which the instructor's grader grades without formulas.
std::pair<std::string, std::string> hint_levels_environment(const std::string& root, const std::string& submission);

// Runs ./workbook grade in the tree context.source_dir with its arguments; returns the exit status
// (that of the grade driver: 0 when grading ran, 1 under --strict without a full score). Where it
// throws, it writes the failed results first (write_failed_results).
int run_grade(const std::vector<std::string>& args, const Context& context);

// Where grading stopped before the driver wrote its results (a wrong command line, a submission
// that cannot be taken in, a failed build of the grader): when `args` ask for --json FILE (its
// path relative to `root`) and FILE is not there, writes a Gradescope results.json with a score
// of 0 that says why (`reason`), so that a student sees it. Whether it wrote one.
bool write_failed_results(const std::string& root, const std::vector<std::string>& args, const std::string& reason);

// A submission's one-line result (the row of its summary.csv, tables.hpp) from its tasks.csv
// ("module,task,score,max_score,status" rows under a header): the sums of its scores and maxima,
// and its status: "graded", or what kept tests from running normally, per module
// (build_error:M01, rejected:M02, once each) or per task (timed_out:M03T2, crashed:M04T1), in the
// order of the file. Without a row: 0, no maximum, "error" (grading itself failed).
grade::SummaryRow summarise_tasks(const std::string& submission, const std::string& tasks_csv);

// The rows of `rows` that are tasks of the graded items of `manifest` with `capability`, as the
// grade driver lists them from each item's lister (its reference program where it has one, the
// trusted list, else its program). An item whose lister is not built was not graded in this build:
// with `unbuilt`, its id goes there; without, it is a UsageError. Throws UsageError for a name that
// is no capability, StepFailed when the listing fails.
std::vector<grade::TaskRow> rows_of_items(std::vector<grade::TaskRow> rows, const Manifest& manifest,
                                          const std::string& capability, std::vector<std::string>* unbuilt = nullptr);

// `rows` each at its maximum; else each one below it, a line each on `out` ("M01 T2: 1.5 of 3,
// failed"), and a StepFailed that counts them (`which` qualifies the tasks, " of the items with
// classroom"; `where` names their table, " in FILE", or is empty). A StepFailed too for no rows.
void require_full(const std::vector<grade::TaskRow>& rows, const std::string& which, const std::string& where,
                  std::ostream& out);

// OUT/gradebook.csv from OUT/*/summary.csv and OUT/*/tasks.csv (the columns in the order of the
// first tasks.csv that has rows).
void write_gradebook(const std::string& out_dir);

// A gradebook's text (`origin` names it) read back: whether its columns add up. For each
// submission whose module columns do not add up to its score, or the task columns of a module to
// the module's column, a line that says which ("bob: the tasks of M01 add up to 5, M01 is 6");
// none where all do. An empty cell counts 0. Throws grade::TableError (tables.hpp) for a text that
// is not a gradebook: another header, a row of other columns, a cell that is no number.
std::vector<std::string> gradebook_mismatches(const std::string& text, const std::string& origin);

}  // namespace fmbd::frontend
