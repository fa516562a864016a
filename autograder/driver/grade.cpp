// fmbd-grade: runs the workbook's graded Catch tests, each in its own sandboxed process,
// and reports a score (plain table, Gradescope results.json, JUnit XML).
//
//   fmbd-grade [options] EXE [--listed-by LISTER] [--grades-inputs]...
//
// Its options are a table (command() in options.cpp), read by the option layer it shares with
// the front end (cli.hpp, on CLI11); --help is made from the same table.
//
// Protocol with a test program (see autograder/support/catch_main.cpp):
//   LISTER --fmbd-list
//       prints one line per test case, "name<TAB>[tag][tag]...", and exits 0. Listing runs
//       student code (static initialisers), so it runs sandboxed like a test. If it fails,
//       the program contributes one failed entry that says why, and grading goes on.
//   EXE --fmbd-token-fd 3 --fmbd-time-limit S --use-colour no --warn NoTests "<escaped name>"
//       runs one test. fd 3 holds a fresh random token; once the Catch session has
//       returned with every check passed, the program prints
//       "fmbd-completion-token: <token>" as its last line. (--warn NoTests makes a name that
//       matches no test a failure.) After S seconds, a little less than the timeout, the
//       program stops itself with status 124 and a line "fmbd-time-limit: ..." that names the
//       last check it reached; the timeout stays the limit for a program that does not.
//   With EXE --listed-by LISTER, only LISTER's list counts: EXE is never asked for its tests, and
//   nothing it prints is read but the completion token of each test.
//   The environment: a program inherits the driver's, TMPDIR replaced by its own temporary
//   directory. Whoever starts the driver may set there, for the programs that read them, the three
//   variables of this protocol (the front end sets the first two for the graded items whose
//   capabilities ask for them, frontend/manifest.hpp, the third always); the driver neither reads
//   nor changes them:
//     FMBD_ANSWERS_ROOT  a folder with a copy of each of the student's inputs (an answers file)
//                        at its path relative to the tree, readable by every user (the tests may
//                        run as another one); unset: the program reads them where it was built
//                        to (the tree's own, as a student runs it by hand)
//     FMBD_STUDENT       the student's identity that the grader trusts, whose numbers the program
//                        grades with; unset or empty: none (the program says that it needs one)
//     FMBD_HINTS_OPENED  the hint levels the student opened (common/grading_protocol.hpp), up to
//                        which a failure message may show a task's formula; empty: none (the
//                        front end's value for a submission); unset: the tree's own, by hand
//   The programs read no other variable of the front end's. (FMBD_TIME_LIMIT is for a test
//   program run by hand, catch_main.cpp; --fmbd-time-limit overrides it.)
//
// Guarantees:
//   * A test passes only if its process exited with status 0 AND printed its own token,
//     which it cannot know in advance: exit(0) in the middle of a test, a crash, a forged
//     token line or a hang all fail, each with a one-line reason.
//   * Every test runs in its own process group, session and temporary directory, under
//     a wall-clock timeout and resource limits; its process group is killed when it ends
//     (details in sandbox.hpp). Output is captured up to 64 KiB per test.
//   * With --jobs N, up to N tests run at once; reports are always in the same order
//     (module, task, then listing order), whatever the timing.
//   * With --reject N=FILE, no test of module N runs: each fails with "rejected by the
//     source check: " and the first line of FILE (the report of fmbd-vet), FILE as its
//     output; the table and results.json say so at the top. --build-errors N=FILE does the
//     same for a module that does not compile ("does not compile: ", FILE holding the
//     compiler's first errors), so that a student sees them wherever the results go. Both
//     concern the module's code, so neither touches the tests of a program given with
//     --grades-inputs (EXE --grades-inputs): it declares that it grades the student's inputs (an
//     answers file), not the code. The front end says so of the graded items whose capabilities
//     give them inputs (frontend/manifest.hpp); the driver knows no kind of graded item, and no
//     code of it tests a task's kind letter.
//   * Results files are written by this process only, after all tests ran, each
//     atomically (temporary file + rename). Ctrl-C kills the running tests, writes nothing
//     and exits with 128 + the signal number.
//
// Exit status (as the front end's, frontend/exit_status.hpp): 0 normally (even if tests failed); 1
// when --strict or --expect-not-implemented is not satisfied; 2 on usage errors; 4 on an internal
// error.

#include <sys/prctl.h>

#include <exception>
#include <iostream>

#include "options.hpp"
#include "run.hpp"

int main(int argc, char** argv) {
  using namespace fmbd::grade;
  // The driver holds the tokens of the running tests: no process of the same user may read
  // its memory (/proc/PID/mem) or descriptors.
  ::prctl(PR_SET_DUMPABLE, 0);
  try {
    const Options options = parse_options(argc, argv);
    if (options.help) {
      std::cout << usage();
      return 0;
    }
    return grade(options);
  } catch (const UsageError& error) {
    std::cerr << "fmbd-grade: " << error.what() << "\n\n" << usage();
    return 2;
  } catch (const Interrupted& interrupted) {
    std::cerr
        << "fmbd-grade: interrupted; the running tests were killed and no results were written\n";
    return 128 + interrupted.signal;
  } catch (const std::exception& error) {
    std::cerr << "fmbd-grade: internal error: " << error.what() << '\n';
    return 4;
  }
}
