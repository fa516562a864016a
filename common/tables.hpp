#pragma once
// The grader's three tables that other programs read back, each format's writer beside its reader
// (the front end's ./workbook inspect, its gradebook and its releases read them through these):
//
//   tasks.csv (fmbd-grade --csv): the header "module,task,score,max_score,status", then a row per
//     task in grading order, "M01,T2,1.5,3,failed": the task's points, its maximum, and the worst
//     status of its tests (report.hpp's status_name). A program that could not be listed has a
//     row of module "other" and task "-", worth 0.
//   summary.csv (./workbook grade --submissions: OUT/NAME/summary.csv): the header
//     "submission,score,max_score,status", then one row, "alice,7.5,9,graded": the submission's
//     points, their maximum (empty where grading failed before any task had a row) and its status
//     (frontend/grade.hpp: summarise_tasks).
//   the timings (fmbd-grade --timings-out; autograder/timings.txt, which --timings reads): a line
//     "MNN<TAB>visible|hidden<TAB>SECONDS<TAB>NAME" per passed test, SECONDS the reference's time
//     (more than 0, at most a day), '#' starting a comment line.
//
// A reader refuses what its writer never writes, naming the file and the line: TableError.

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace fmbd::grade {

// A text that is not in its table's format: what() is "ORIGIN:LINE: what is wrong".
class TableError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One row of tasks.csv.
struct TaskRow {
  std::string module;  // "M01"
  std::string task;    // "T2", "P1"
  double score = 0;
  double max_score = 0;
  std::string status;  // "passed", "failed", ...
  std::string id() const { return module + task; }  // "M01T2"
};

// tasks.csv of `rows`, their numbers written as format_number does (text.hpp): "1.5", "3".
std::string tasks_csv_text(const std::vector<TaskRow>& rows);

// The rows of a tasks.csv text (`origin` names it in errors). An empty text has no rows (the
// driver wrote none). Throws TableError: another header, a row without five fields, a number
// that is none, a row without a status.
std::vector<TaskRow> parse_tasks_csv(std::string_view text, const std::string& origin);

// The one row of summary.csv.
struct SummaryRow {
  std::string submission;           // its folder's name
  double score = 0;
  std::optional<double> max_score;  // none: grading failed before any task had a row
  std::string status = "error";     // "graded", "build_error:M01 timed_out:M02T1", "error"
};

// summary.csv of `row`: the header, then the row, its numbers written as format_number does.
std::string summary_csv_text(const SummaryRow& row);

// The row of a summary.csv text, or none for an empty text. Throws TableError: another header,
// not exactly one row, a row without four fields, a number that is none, an empty submission or
// status.
std::optional<SummaryRow> parse_summary_csv(std::string_view text, const std::string& origin);

// One line of the timings.
struct Timing {
  std::string module;  // "M01"
  bool hidden = false;
  double seconds = 0;
  std::string name;    // the test's name, as the program lists it
};

// The timings file of `timings`: its two comment lines, then a line each.
std::string timings_text(const std::vector<Timing>& timings);

// The timings of a text. Throws TableError for a line that is not a comment or
// "MNN<TAB>visible|hidden<TAB>SECONDS<TAB>NAME" (the message quotes it).
std::vector<Timing> parse_timings(std::string_view text, const std::string& origin);

}  // namespace fmbd::grade
