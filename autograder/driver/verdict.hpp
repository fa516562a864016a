#pragma once
// Deciding whether a test passed, and saying in one line why not.
//
// A test PASSES only if its process exited normally with status 0 AND printed the line
// "fmbd-completion-token: <its own token>". The token proves that the Catch session
// returned: a test that calls exit(0) early, or prints a guessed token, fails.

#include <string>
#include <string_view>

#include "sandbox.hpp"

namespace fmbd::grade {

struct Verdict {
  bool passed = false;
  std::string reason;  // one line (fitted_line); empty when passed
  bool cut = false;    // the reason left something of the test's message out
};

// A reason that fits in kMaxReasonLength bytes is whole. A longer one keeps what tells the
// student what is wrong: its "; "-separated parts' heads (a hint whole, a compared quantity's
// label up to its ": ", a failed expression before its expansion) stay whole up to
// kMaxNamedLength bytes in all; only the values after them are cut ("...", in order: the first
// quantity's values keep 80 bytes at least, the context logged after it yields first), and the line ends
// with kWholeMessagePointer (the table then shows the command that runs the test alone).
inline constexpr std::size_t kMaxReasonLength = 420;
inline constexpr std::size_t kMaxNamedLength = 900;
inline constexpr std::string_view kWholeMessagePointer = " [cut: run the test alone for the whole message]";

// `text` as a reason: one line, fitted as above.
std::string fitted_line(std::string_view text);

Verdict judge(const Outcome& outcome, double timeout_seconds);

// The test program stopped itself at its time limit (status 124 and its "fmbd-time-limit:" line).
bool stopped_by_time_limit(const Outcome& outcome);

// How the process ended, for example "timed out after 30 s",
// "killed by signal SIGSEGV (segmentation fault)", "aborted (SIGABRT)",
// "exited with status 3".
std::string describe_ending(const Outcome& outcome, double timeout_seconds);

// describe_ending(), followed by " -- " and the failure_detail() of the output when there
// is one that says more than the ending itself.
std::string explain_failure(const Outcome& outcome, double timeout_seconds);

// The most informative line of a test's output (Catch's compact reporter), or "" when there
// is none. In order of preference: a message containing "not implemented yet" (the workbook's
// stub exception); a sanitizer's report (UBSan "runtime error", else an ASan/LSan "SUMMARY");
// a failed assert(); the exception that ended the test case; Catch's note that no test
// matched; for the first failed check, its messages (the hint first, then INFO and CAPTURE
// context, fatal signal) if any, otherwise the failed expression and its expansion.
std::string failure_detail(std::string_view output);

}  // namespace fmbd::grade
