#pragma once
// A student's submission graded in a pristine copy of this tree (./workbook grade --submission,
// --submissions), and the lock that keeps two such gradings of one copy apart.

#include <iosfwd>
#include <string>
#include <vector>

#include "manifest.hpp"

namespace fmbd::frontend {

// One grading of submissions at a time in a copy (they share build/submission/tree): an
// exclusive flock(2) on build/submission.lock, which holds the holder's process number. The
// system releases it when the process ends, however it ends. Throws BuildError (build.hpp) with
// the holder's number when another process holds it.
class SubmissionLock {
 public:
  explicit SubmissionLock(const std::string& root);
  ~SubmissionLock();
  SubmissionLock(const SubmissionLock&) = delete;
  SubmissionLock& operator=(const SubmissionLock&) = delete;

 private:
  int fd_ = -1;
};

// The folder where a submission is graded: ROOT/build/submission/tree.
std::string submission_tree(const std::string& root);

// build/submission/tree becomes a copy of the tree `root` with the exercise files of
// `submission`, each found as SUBMISSION/moduleNN_x/src/NAME or, failing that, as the first file
// named NAME below SUBMISSION (in path order), and its answers files (the graded items' inputs),
// each found at its path or at it below a folder of SUBMISSION (a missing one is taken out of the
// copy). Everything else is this tree's, without build/,
// out/ and .git. A missing exercise file keeps its skeleton (its tasks fail as "not implemented")
// and is named when its module is among `modules` (empty: all); the other files of the submission
// are named as ignored (the first ten). Only the files that differ are written, so that a rebuild
// compiles only what changed. Returns the tree.
std::string prepare_submission(const std::string& root, const std::string& submission, const Manifest& manifest,
                               const std::vector<int>& modules, std::ostream& out);

}  // namespace fmbd::frontend
