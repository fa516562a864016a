#pragma once
// The graded items' inputs and the identity in the front end (the tutorial problems,
// problems/problems.hpp, are such items): whose variant a grading uses, the inputs handed to the
// items' programs, and ./workbook problems. Which items these are is the manifest's data (their
// capabilities inputs and needs_identity, manifest.hpp), never their kind.
//
// The identity. An item that needs it takes its numbers from the student's identity, which only the grader
// decides: `--student NAME` or the name remembered by `./workbook problems --student NAME`
// (build/student.name) in one's own tree; the submission folder's name for --submission and each
// subfolder of --submissions (the roster's names); the first user's e-mail address in Gradescope's
// submission metadata (--gradescope-metadata). Nothing in a submission can change it.
//
// Both reach the items' programs through the environment of the grade driver, the two variables
// of the programs' protocol (autograder/driver/grade.cpp): FMBD_STUDENT, the identity, and
// FMBD_ANSWERS_ROOT, the inputs.
//
// The inputs. An item's program reads each of its inputs (moduleNN_*/answers.txt) below
// FMBD_ANSWERS_ROOT: a fresh folder below the system's temporary folder, readable by every user
// (the tests may run as an unprivileged one), holding a copy of each input at its path relative
// to the tree; under --solutions the model answers of the variant instead, in its first input
// (the program's --model-answers).

#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

#include "context.hpp"
#include "manifest.hpp"
#include "options.hpp"

namespace fmbd::frontend {

// The name remembered in `root`'s build/student.name, or "".
std::string remembered_student(const std::string& root);
void remember_student(const std::string& root, const std::string& name);

// The identity in Gradescope's submission_metadata.json: the first user's e-mail address (or
// name). Throws UsageError when the file cannot be read or names no user.
std::string gradescope_identity(const std::string& metadata_file);

// The folder FMBD_ANSWERS_ROOT names, removed with this object.
class StagedAnswers {
 public:
  StagedAnswers();
  ~StagedAnswers();
  StagedAnswers(const StagedAnswers&) = delete;
  StagedAnswers& operator=(const StagedAnswers&) = delete;
  const std::string& folder() const { return folder_; }

 private:
  std::string folder_;
};

// For the graded items with inputs among `items`: their inputs in `staged` (copied from `tree`,
// or the model answers with `model_answers`), and the environment of the grade driver:
// FMBD_ANSWERS_ROOT, and FMBD_STUDENT when `identity` is not empty.
std::vector<std::pair<std::string, std::string>> stage_answers(const std::vector<const GradedItem*>& items,
                                                               const std::string& tree, const std::string& identity,
                                                               bool model_answers, const StagedAnswers& staged);

const CommandSpec& problems_command();
int run_problems(const std::vector<std::string>& args, const Context& context);

}  // namespace fmbd::frontend
