#pragma once
// Step 2 of grading one tree (grade_plan.hpp): the build of a plan, and the source check of each
// item that built.

#include <iosfwd>
#include <string>
#include <vector>

#include "grade_plan.hpp"

namespace fmbd::frontend {

// The build of `plan` in the tree of `root`: its targets in one build that keeps going past errors
// (both cores stay busy), the grade driver, which must build (else a BuildError), then each item
// on its own, with its outcome, one per plan item, in order:
//  * built: its lister built where it has one (a student's program could print any list), then
//    the source check of its exercise files (its plan's vet_target) passed;
//  * rejected: the source check refused a file; its report (the manifest's vet_report, for the
//    driver's --reject) is said on `out`. A check that could not run (a fault of the build, not of
//    the code) is tried once more after building the item again, then is a BuildError: code that
//    was never checked scores nothing, not 0;
//  * broken: it does not compile; its first errors are shown and kept in its errors_file, and its
//    program removed (never grade a stale build). With its lister at hand, its test list makes
//    every test of the module count as failed, with the errors as their output;
//  * skipped: it does not build and none of the student's files is in it: not graded here.
// The modules that do not compile and those rejected are named at the end, then the warnings of
// the exercise files.
std::vector<ItemOutcome> build_planned(const std::string& root, const GradingPlan& plan, std::ostream& out);

}  // namespace fmbd::frontend
