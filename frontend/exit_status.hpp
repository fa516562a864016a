#pragma once
// The exit statuses of ./workbook (and of fmbd-workbook, which it runs), so that a script can
// tell a typo from a failed build and from failed tests:
//
//   0  done (for grade: the grade was given, whatever the score, unless --strict)
//   1  a step ran and failed: tests failed (test, grade --strict), a demo or a benchmark failed
//   2  a wrong command line, or a command that cannot go on here (UsageError)
//   3  configuring or building failed, or the build's course manifest is unreadable (BuildError,
//      ManifestError)
//   4  any other error (a file that cannot be written, an archive that cannot be packed)
//
// docs/building.md, "Exit status", documents the same table; `./workbook help` prints it.
#include <exception>
#include <stdexcept>

namespace fmbd::frontend {

enum ExitStatus : int { kExitOk = 0, kExitFailed = 1, kExitUsage = 2, kExitBuild = 3, kExitError = 4 };

// A step that ran and failed (a demo, a benchmark, a grading inside bench): what() is the message
// for "workbook: ", exit status 1.
class StepFailed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The exit status for an error that ends a command, by its type (the table above).
int exit_status_of(const std::exception& error);

// The table above as the help prints it.
const char* exit_status_help();

}  // namespace fmbd::frontend
