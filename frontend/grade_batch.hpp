#pragma once
// Grading a class of submissions (./workbook grade --submissions DIR --out OUT, grade.hpp), one
// tree per submission.

#include <iosfwd>
#include <string>

#include "grade_plan.hpp"

namespace fmbd::frontend {

// Grades one tree and returns the grade driver's exit status: the root's own where `submission`
// is empty, else the submission (a folder or a zip) taken into a pristine copy of the root, under
// the submission lock unless the caller holds it (`locked`). It configures the tree, reads its
// course manifest, plans (grade_plan.hpp), builds (grade_build.hpp) and runs the driver; with
// --require-full, it then checks those items' tasks in the driver's table of tasks. `output`:
// where the driver writes (empty: the terminal). In grade.cpp.
int grade_tree(const std::string& root, const GradeOptions& options, const std::string& submission, bool locked,
               std::ostream& out, const std::string& output);

// Grades every subfolder of o.submissions (hidden ones aside) in name order, each as a submission
// into o.out/NAME/ (grade.txt, results.json, junit.xml, tasks.csv, summary.csv, and logs/ with the
// build and source-check logs, their paths in grade.txt written "logs/"), under the submission
// lock; a line each on `out`, and o.out/gradebook.csv rebuilt after each. A grading that throws is
// said in its grade.txt and the class goes on; --strict is left out (it is for one grading's exit
// status). With o.resume, a submission with a summary.csv is skipped. Returns 0; a UsageError for
// a folder without subfolders.
int grade_class(const std::string& root, const GradeOptions& o, std::ostream& out);

}  // namespace fmbd::frontend
