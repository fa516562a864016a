#pragma once
// fmbd-grade's command line (the protocol and the guarantees are in grade.cpp): its one table of
// the option layer (cli.hpp, on CLI11), from which come both the parsing and the help, and the
// options read from it and checked.

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "catalog.hpp"
#include "cli.hpp"
#include "report.hpp"
#include "sandbox.hpp"

namespace fmbd::grade {

// The error of a wrong command line: fmbd-grade says it with the help and exits with status 2.
using cli::UsageError;

// The options, read and checked: what to grade (the test programs, --module, --task), how to run
// it (--timeout, --timings, --jobs, --run-as, --reject, --build-errors) and what to write.
struct Options {
  std::vector<TestProgram> programs;
  std::vector<int> modules;                 // empty: all modules
  std::vector<std::pair<int, Task>> tasks;  // (module, task); empty: all tasks
  bool list_tasks = false;
  double timeout_seconds = 30;
  std::map<std::string, double> reference_seconds;  // "MNN\tname" -> seconds (--timings)
  std::string timings_out_file;
  unsigned jobs = 1;
  std::string json_file;
  std::string junit_file;
  std::string summary_file;
  std::string csv_file;
  std::string hidden_visibility = "after_published";
  std::string earlier_note;  // --earlier-note: ends earlier_stubs_line's line (report.hpp)
  bool quiet = false;
  bool strict = false;
  bool expect_not_implemented = false;
  bool help = false;
  std::optional<Identity> run_as;
  std::map<int, UnrunModule> unrun;  // modules whose tests do not run, and why
};

// The help: the synopsis, the description and the table of options, then the exit statuses.
std::string usage();

// The options of the command line `argv` (argc words, the program's name first). --help sets only
// `help`. Otherwise: each EXE in order, with the LISTER of a --listed-by and the --grades-inputs
// after it; --module N or MNN and --task MnnTk or MnnPk (a task id, common/task_id.hpp);
// --timeout in seconds (above 0, at most a day); --timings read into reference_seconds (by
// module and test name, tables.hpp); --jobs from 1 to 1024 (default: the online CPUs); --run-as
// an unprivileged user, and only as root; --reject and --build-errors N=FILE with FILE's report,
// which must not be blank; --hidden-visibility one of Gradescope's. Across them: at least one
// test program; run as root without --run-as, the tests run as "nobody"; --strict and
// --expect-not-implemented exclude each other. Throws UsageError for the first problem.
Options parse_options(int argc, char** argv);

}  // namespace fmbd::grade
