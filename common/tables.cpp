#include "tables.hpp"

#include <cmath>
#include <cstdlib>
#include <optional>

#include "csv.hpp"
#include "text.hpp"

namespace fmbd::grade {
namespace {

constexpr std::string_view kTasksHeader = "module,task,score,max_score,status";
constexpr std::string_view kSummaryHeader = "submission,score,max_score,status";
constexpr std::string_view kTimingsForm = "MNN<TAB>visible|hidden<TAB>SECONDS<TAB>NAME";

// The lines of `text`, each without its line feed (and carriage return).
std::vector<std::string_view> lines_of(std::string_view text) {
  std::vector<std::string_view> lines;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
  }
  return lines;
}

// `text` as a finite number, the whole of it.
std::optional<double> number_of(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value)) return std::nullopt;
  return value;
}

TableError error_at(const std::string& origin, std::size_t line, const std::string& what) {
  return TableError(origin + ":" + std::to_string(line) + ": " + what);
}

}  // namespace

std::string tasks_csv_text(const std::vector<TaskRow>& rows) {
  std::string text = std::string(kTasksHeader) + "\n";
  for (const TaskRow& row : rows) {
    text += csv::row({row.module, row.task, format_number(row.score), format_number(row.max_score), row.status});
  }
  return text;
}

std::vector<TaskRow> parse_tasks_csv(std::string_view text, const std::string& origin) {
  std::vector<TaskRow> rows;
  const std::vector<std::string_view> lines = lines_of(text);
  if (lines.empty()) return rows;
  if (lines.front() != kTasksHeader) {
    throw error_at(origin, 1, "not a table of tasks: its header is not " + std::string(kTasksHeader));
  }
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].empty()) continue;
    const std::vector<std::string> fields = csv::split(lines[i]);
    const std::optional<double> score = fields.size() == 5 ? number_of(fields[2]) : std::nullopt;
    const std::optional<double> max_score = fields.size() == 5 ? number_of(fields[3]) : std::nullopt;
    if (!score || !max_score || fields[0].empty() || fields[1].empty() || fields[4].empty()) {
      throw error_at(origin, i + 1, "expected MODULE,TASK,SCORE,MAX_SCORE,STATUS, got: " + std::string(lines[i]));
    }
    rows.push_back({fields[0], fields[1], *score, *max_score, fields[4]});
  }
  return rows;
}

std::string summary_csv_text(const SummaryRow& row) {
  return std::string(kSummaryHeader) + "\n" +
         csv::row({row.submission, format_number(row.score), row.max_score ? format_number(*row.max_score) : "",
                   row.status});
}

std::optional<SummaryRow> parse_summary_csv(std::string_view text, const std::string& origin) {
  std::vector<std::string_view> lines = lines_of(text);
  while (!lines.empty() && lines.back().empty()) lines.pop_back();
  if (lines.empty()) return std::nullopt;
  if (lines.front() != kSummaryHeader) {
    throw error_at(origin, 1, "not a submission's summary: its header is not " + std::string(kSummaryHeader));
  }
  if (lines.size() != 2) {
    throw error_at(origin, 2, "expected one row under the header, got " + std::to_string(lines.size() - 1));
  }
  const std::vector<std::string> fields = csv::split(lines[1]);
  const std::optional<double> score = fields.size() == 4 ? number_of(fields[1]) : std::nullopt;
  const std::optional<double> max_score = fields.size() == 4 ? number_of(fields[2]) : std::nullopt;
  if (!score || (!max_score && !fields[2].empty()) || fields[0].empty() || fields[3].empty()) {
    throw error_at(origin, 2, "expected SUBMISSION,SCORE,MAX_SCORE,STATUS, got: " + std::string(lines[1]));
  }
  return SummaryRow{fields[0], *score, max_score, fields[3]};
}

std::string timings_text(const std::vector<Timing>& timings) {
  std::string text =
      "# The reference's seconds per graded test (fmbd-grade --timings-out): a test's timeout is\n"
      "# 20 times its time here, at least 5 s (fmbd-grade --timings). A release keeps the visible ones.\n";
  for (const Timing& timing : timings) {
    text += timing.module + '\t' + (timing.hidden ? "hidden" : "visible") + '\t' + format_number(timing.seconds) +
            '\t' + timing.name + '\n';
  }
  return text;
}

std::vector<Timing> parse_timings(std::string_view text, const std::string& origin) {
  std::vector<Timing> timings;
  const std::vector<std::string_view> lines = lines_of(text);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string_view line = lines[i];
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> fields;
    for (std::size_t start = 0; fields.size() < 4;) {  // the name is the rest: it may hold a tab
      const std::size_t tab = fields.size() < 3 ? line.find('\t', start) : std::string_view::npos;
      fields.emplace_back(line.substr(start, tab == std::string_view::npos ? std::string_view::npos : tab - start));
      if (tab == std::string_view::npos) break;
      start = tab + 1;
    }
    const std::optional<double> seconds = fields.size() == 4 ? number_of(fields[2]) : std::nullopt;
    if (!seconds || !(*seconds > 0) || *seconds > 86400 || fields[0].empty() || fields[3].empty() ||
        (fields[1] != "visible" && fields[1] != "hidden")) {
      throw error_at(origin, i + 1, "expected " + std::string(kTimingsForm) + ", got: " + std::string(line));
    }
    timings.push_back({fields[0], fields[1] == "hidden", *seconds, fields[3]});
  }
  return timings;
}

}  // namespace fmbd::grade
