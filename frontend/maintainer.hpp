#pragma once
// The maintainers' commands of ./workbook, for the instructor's copy (solutions/, tests/, the
// mistake catalogue):
//
//   test [--preset ci|asan|clang-libcxx]   configure build/PRESET once, build it, run its ctest
//                                          preset; the build's and the tests' seconds at the end
//   bench [--quick] [--out FILE.csv]       the student loop (a release built and graded from
//                                          clean, the edit-rebuild-regrade loop, the autograder
//                                          on the reference) and the benchmark programs of the
//                                          manifest: a table, a CSV file and the speed targets
//   studentify                             the exercise files again from solutions/
//
// In a copy with the extras and solutions but no mistake catalogue, bench runs the benchmark
// programs only (bench_extras_command() is its usage there).

#include <string>
#include <vector>

#include "context.hpp"
#include "options.hpp"

namespace fmbd::frontend {

const CommandSpec& test_command();
const CommandSpec& bench_command();
const CommandSpec& bench_extras_command();
const CommandSpec& studentify_command();

int run_test(const std::vector<std::string>& args, const Context& context);
int run_bench(const std::vector<std::string>& args, const Context& context);
int run_studentify(const std::vector<std::string>& args, const Context& context);

// The table ./workbook bench prints of its CSV text ("group,case,quantity,value,unit" rows under
// that header): a line per row in columns, then one line per speed target (quantity
// "ratio_to_target"): met, or how far.
std::string bench_table(const std::string& csv);

// A row of ./workbook bench's CSV, as a benchmark program prints it (extras/support/bench.hpp:
// row()): the value is the text printed, a number.
struct BenchRow {
  std::string group;
  std::string name;  // the column "case"
  std::string quantity;
  std::string value;
  std::string unit;
};

// The rows of a benchmark CSV `text` (a first line "group,case,quantity,value,unit" is its
// header; `origin` names the file in errors). Throws StepFailed for a line without five fields or
// whose value is not a number, and for a text without rows.
std::vector<BenchRow> parse_bench_csv(const std::string& text, const std::string& origin);

}  // namespace fmbd::frontend
