#pragma once
// ./workbook grade: builds and grades this tree's code, a student's submission in a pristine copy
// of it, or a whole class of submissions into a gradebook. The options and their messages are
// the command's table (grade_command()); ./workbook help prints them.
//
// One tree: every selected module is built in one build that goes on past errors (its progress
// shown, build.hpp), then each module on its own: a module that does not compile scores 0 with
// its first errors, one whose code the source check (fmbd-vet) refuses scores 0 with its reason,
// the others are graded by the grade driver (fmbd-grade) on the test list of the reference build
// where there is one. The driver prints the score table and writes the results files.
//
// A class (--submissions DIR --out OUT): every subfolder of DIR in turn, each graded as a
// submission into OUT/NAME/ (grade.txt, results.json, junit.xml, tasks.csv, logs/), a line each
// as it goes, and OUT/gradebook.csv rebuilt from the tasks.csv files after every submission: a
// row per submission, "submission,score,max_score,status", then a column per module and per
// task. --resume skips the submissions graded already.

#include <iosfwd>
#include <string>
#include <vector>

#include "options.hpp"

namespace fmbd::frontend {

const CommandSpec& grade_command();

// Runs ./workbook grade in the tree `root` with its arguments; returns the exit status (that of
// the grade driver: 0 when grading ran, 1 under --strict without a full score).
int run_grade(const std::string& root, const std::vector<std::string>& args, std::ostream& out);

// OUT/gradebook.csv from OUT/*/summary.csv and OUT/*/tasks.csv (the columns in the order of the
// first tasks.csv that has rows).
void write_gradebook(const std::string& out_dir);

}  // namespace fmbd::frontend
