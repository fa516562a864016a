#pragma once
// Grading once the options are read (options.hpp): listing the tests of each program, running the
// selected ones in the sandbox (sandbox.hpp), judging them (verdict.hpp) and reporting
// (report.hpp). grade.cpp has the protocol and the guarantees.

#include "options.hpp"

namespace fmbd::grade {

// The user asked to stop (SIGINT, SIGTERM or SIGHUP, `signal`): the running tests were killed and
// nothing was written.
struct Interrupted {
  int signal;
};

// Grades as `options` say and returns the exit status:
//  * the tests are listed by each program's lister (sandboxed like a test; one that cannot be
//    listed is a failed entry worth 0, with the reason, also when the tests' user cannot enter the
//    program's folders), then selected (--module, --task) and sorted by module and task;
//  * --list-tasks prints "MNN TK POINTS" per selected task instead of grading: 0, or 1 when a
//    program could not be listed;
//  * else every test of a module that runs runs alone (its timeout from --timings, at most
//    --timeout; the program stops itself a little before it); a module under --reject or
//    --build-errors fails unrun with its reason, except for the programs that grade the student's
//    inputs. The table goes to stdout (the notes on the unrun modules above it), and each
//    results file asked for is written atomically: --summary, --json, --junit, --csv, and
//    --timings-out with the time of each passed test, rounded up to a hundredth;
//  * 0, or 1 when --strict sees a failed test (or none) or --expect-not-implemented a test that
//    did not fail with "not implemented".
// Throws Interrupted when the user stops it, std::system_error when the sandbox cannot work.
int grade(const Options& options);

}  // namespace fmbd::grade
