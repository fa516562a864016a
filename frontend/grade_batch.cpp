#include "grade_batch.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>

#include "csv.hpp"
#include "file_io.hpp"
#include "grade.hpp"
#include "strings.hpp"
#include "submission.hpp"
#include "tables.hpp"
#include "text.hpp"

namespace fmbd::frontend {
namespace {

namespace fs = std::filesystem;

// The row of the summary.csv at `path`; none where it is missing or not one (a grading that
// stopped before writing it).
std::optional<grade::SummaryRow> read_summary(const std::string& path) {
  std::string text;
  if (!tools::read_file(path, text)) return std::nullopt;
  try {
    return grade::parse_summary_csv(text, path);
  } catch (const grade::TableError&) {
    return std::nullopt;
  }
}

// The rows of the tasks.csv at `path`, read by the driver's reader (tables.hpp); none where it is
// missing or not one (grading stopped before the driver wrote it).
std::vector<grade::TaskRow> read_task_rows(const std::string& path) {
  std::string text;
  if (!tools::read_file(path, text)) return {};
  try {
    return grade::parse_tasks_csv(text, path);
  } catch (const grade::TableError&) {
    return {};
  }
}

// The maximum of a summary as the gradebook writes it: empty where there is none.
std::string max_text(const grade::SummaryRow& row) {
  return row.max_score ? grade::format_number(*row.max_score) : "";
}

// "SCORE,MAX_SCORE" of a summary.
std::string points_text(const grade::SummaryRow& row) { return grade::format_number(row.score) + "," + max_text(row); }

}  // namespace

grade::SummaryRow summarise_tasks(const std::string& submission, const std::string& tasks_csv) {
  grade::SummaryRow summary;
  summary.submission = submission;
  const std::vector<grade::TaskRow> rows = read_task_rows(tasks_csv);
  if (rows.empty()) return summary;
  double score = 0;
  double max_score = 0;
  std::string status;
  std::vector<std::string> modules_seen;
  for (const grade::TaskRow& row : rows) {
    score += row.score;
    max_score += row.max_score;
    const std::string& why = row.status;
    std::string item;
    if ((why == "build_error" || why == "rejected") &&
        std::find(modules_seen.begin(), modules_seen.end(), row.module) == modules_seen.end()) {
      modules_seen.push_back(row.module);
      item = why + ":" + row.module;
    } else if (why == "timed_out" || why == "crashed") {
      item = why + ":" + row.id();
    }
    if (!item.empty()) status += (status.empty() ? "" : " ") + item;
  }
  summary.score = score;
  summary.max_score = max_score;
  summary.status = status.empty() ? "graded" : status;
  return summary;
}

namespace {

// `text` with every build path of the submission tree's logs ("ROOT/build/submission/tree/build/
// PRESET/", then "compile/" or "vet/" if there) written "logs/", where the submission's own copies are.
std::string to_logs(std::string text, const std::string& root) {
  const std::string prefix = submission_tree(root) + "/build/";
  for (std::size_t at = text.find(prefix); at != std::string::npos; at = text.find(prefix, at)) {
    std::size_t end = at + prefix.size();
    while (end < text.size() && text[end] >= 'a' && text[end] <= 'z') ++end;
    if (end >= text.size() || text[end] != '/') {
      at = end;
      continue;
    }
    ++end;
    for (const char* sub : {"compile/", "vet/"}) {
      if (text.compare(end, std::string(sub).size(), sub) == 0) end += std::string(sub).size();
    }
    text.replace(at, end - at, "logs/");
    at += 5;
  }
  return text;
}

}  // namespace

// A subfolder at a time into o.out, the gradebook rebuilt after each (grade_batch.hpp).
int grade_class(const std::string& root, const GradeOptions& o, std::ostream& out) {
  SubmissionLock lock(root);
  fs::create_directories(o.out);
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(o.submissions)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_directory() && name[0] != '.') names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  if (names.empty()) throw UsageError("--submissions: no subfolders in '" + o.submissions + "'");
  const std::string total = std::to_string(names.size());
  std::size_t count = 0;
  for (const std::string& name : names) {
    ++count;
    const std::string result = o.out + "/" + name;
    const std::string tag = "[" + std::to_string(count) + "/" + total + "] " + name;
    if (const auto previous = read_summary(result + "/summary.csv"); o.resume && previous) {
      out << "workbook: " << tag << ": graded before (--resume): " << points_text(*previous) << "," << previous->status
          << "\n";
      continue;
    }
    std::error_code error;
    fs::remove_all(result, error);
    fs::create_directories(result + "/logs");
    const auto start = std::chrono::steady_clock::now();
    GradeOptions one = o;  // --strict is for one grading's exit status, not a class's
    one.driver.strict = false;
    one.driver.json = result + "/results.json";
    one.driver.junit = result + "/junit.xml";
    one.driver.csv = result + "/tasks.csv";
    const std::string grade_txt = result + "/grade.txt";
    {
      std::ofstream text(grade_txt);
      try {
        grade_tree(root, one, o.submissions + "/" + name, true, text, grade_txt);
      } catch (const std::exception& failure) {
        text << "workbook: " << failure.what() << "\n";
      }
    }
    // The logs of this submission, kept with its results (the next one overwrites the tree's).
    const std::string builds = submission_tree(root) + "/build";
    for (const auto& preset : fs::directory_iterator(builds, error)) {
      std::vector<fs::path> logs;
      for (const auto& entry : fs::directory_iterator(preset.path(), error)) {
        const std::string file = entry.path().filename().string();
        if (file[0] == 'm' && file.size() > 10 && file.compare(file.size() - 10, 10, ".build.log") == 0) {
          logs.push_back(entry.path());
        }
      }
      for (const char* sub : {"compile", "vet"}) {
        for (const auto& entry : fs::directory_iterator(preset.path() / sub, error)) {
          if (entry.path().extension() == ".txt") logs.push_back(entry.path());
        }
      }
      for (const fs::path& log : logs) {
        fs::copy_file(log, result + "/logs/" + log.filename().string(), fs::copy_options::overwrite_existing, error);
      }
    }
    std::string text;
    tools::read_file(grade_txt, text);
    tools::write_if_changed(grade_txt, to_logs(text, root));
    const grade::SummaryRow summary = summarise_tasks(name, result + "/tasks.csv");
    std::ofstream(result + "/summary.csv") << grade::summary_csv_text(summary);
    const long seconds = static_cast<long>(
        std::chrono::duration_cast<std::chrono::seconds>(std::chrono::steady_clock::now() - start).count());
    out << "workbook: " << tag << ": " << grade::format_number(summary.score) << "/" << max_text(summary) << " "
        << summary.status << " ("
        << seconds << " s; " << grade_txt << ")\n" << std::flush;
    write_gradebook(o.out);
  }
  out << "workbook: graded " << count << " submissions; gradebook: " << o.out << "/gradebook.csv\n";
  return 0;
}

void write_gradebook(const std::string& out_dir) {
  std::vector<std::string> folders;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(out_dir, error)) {
    if (entry.is_directory()) folders.push_back(entry.path().string());
  }
  std::sort(folders.begin(), folders.end());
  // The columns: the modules, then the tasks, of the first submission graded in full.
  std::vector<std::string> modules;
  std::vector<std::pair<std::string, std::string>> tasks;  // (module, module + task)
  for (const std::string& folder : folders) {
    const std::vector<grade::TaskRow> rows = read_task_rows(folder + "/tasks.csv");
    if (rows.empty()) continue;
    for (const grade::TaskRow& row : rows) {
      if (std::find(modules.begin(), modules.end(), row.module) == modules.end()) modules.push_back(row.module);
      tasks.emplace_back(row.module, row.id());
    }
    break;
  }
  std::vector<std::string> header{"submission", "score", "max_score", "status"};
  header.insert(header.end(), modules.begin(), modules.end());
  for (const auto& task : tasks) header.push_back(task.second);
  std::string text = csv::row(header);
  for (const std::string& folder : folders) {
    const std::optional<grade::SummaryRow> summary = read_summary(folder + "/summary.csv");
    if (!summary) continue;
    std::vector<std::string> row{summary->submission, grade::format_number(summary->score), max_text(*summary),
                                 summary->status};
    std::map<std::string, double> module_points;
    std::map<std::string, std::string> task_points;
    for (const grade::TaskRow& task : read_task_rows(folder + "/tasks.csv")) {
      module_points[task.module] += task.score;
      task_points[task.id()] = grade::format_number(task.score);
    }
    for (const std::string& module : modules) {
      row.push_back(module_points.count(module) ? grade::format_number(module_points[module]) : "");
    }
    for (const auto& task : tasks) row.push_back(task_points.count(task.second) ? task_points[task.second] : "");
    text += csv::row(row);
  }
  const std::string path = out_dir + "/gradebook.csv";
  std::ofstream(path + ".new") << text;
  fs::rename(path + ".new", path, error);
}

namespace {

// A cell of the gradebook as a number: an empty one is 0 (a submission graded without that module
// or task); nothing where it is none.
std::optional<double> points_of(const std::string& cell) {
  if (cell.empty()) return 0.0;
  char* end = nullptr;
  const double value = std::strtod(cell.c_str(), &end);
  if (*end != '\0' || !std::isfinite(value)) return std::nullopt;
  return value;
}

// The gradebook's columns after the first four: for each, the module column it is a task of
// (one before it of which it is the name and more: M01T2 of M01), or itself for a module.
std::vector<std::size_t> owners_of(const std::vector<std::string>& header) {
  std::vector<std::size_t> owner(header.size());
  for (std::size_t i = 4; i < header.size(); ++i) {
    owner[i] = i;
    for (std::size_t m = 4; m < i && owner[i] == i; ++m) {
      const bool task_of_m = header[i].size() > header[m].size() && tools::starts_with(header[i], header[m]);
      if (owner[m] == m && task_of_m) owner[i] = m;
    }
  }
  return owner;
}

// Whether a column and the sum of `cells` columns agree, each written to a thousandth
// (format_number): within half a thousandth per column.
bool same_points(double column, double sum, std::size_t cells) {
  return std::abs(column - sum) <= 5e-4 * static_cast<double>(cells + 1) + 1e-9;
}

}  // namespace

std::vector<std::string> gradebook_mismatches(const std::string& text, const std::string& origin) {
  const std::vector<std::string> lines = tools::split_lines(text);
  const std::vector<std::string> header = lines.empty() ? std::vector<std::string>{} : csv::split(lines.front());
  if (header.size() < 4 || header[0] != "submission" || header[1] != "score" || header[2] != "max_score" ||
      header[3] != "status") {
    throw grade::TableError(origin + ":1: not a gradebook: its header does not start with "
                            "submission,score,max_score,status");
  }
  const std::vector<std::size_t> owner = owners_of(header);
  std::vector<std::string> mismatches;
  for (std::size_t l = 1; l < lines.size(); ++l) {
    if (lines[l].empty()) continue;
    const std::vector<std::string> row = csv::split(lines[l]);
    std::vector<double> points(row.size(), 0.0);  // the status column (3) counts 0
    bool numbers = row.size() == header.size();
    for (std::size_t i = 1; i < row.size() && numbers; ++i) {
      const std::optional<double> value = i == 3 ? 0.0 : points_of(row[i]);
      numbers = value.has_value();
      points[i] = value.value_or(0);
    }
    if (!numbers) {
      throw grade::TableError(origin + ":" + std::to_string(l + 1) + ": expected the " + std::to_string(header.size()) +
                              " columns of the header, points after the status, got: " + lines[l]);
    }
    // Per module column: the sum of its tasks and their number; at 1: of the modules.
    std::vector<double> sums(row.size(), 0.0);
    std::vector<std::size_t> cells(row.size(), 0);
    for (std::size_t i = 4; i < row.size(); ++i) {
      const std::size_t sum = owner[i] == i ? 1 : owner[i];
      sums[sum] += points[i];
      ++cells[sum];
    }
    if (!same_points(points[1], sums[1], cells[1])) {
      mismatches.push_back(row[0] + ": the modules add up to " + grade::format_number(sums[1]) + ", the score is " +
                           row[1]);
    }
    for (std::size_t m = 4; m < row.size(); ++m) {
      if (owner[m] == m && cells[m] > 0 && !same_points(points[m], sums[m], cells[m])) {
        mismatches.push_back(row[0] + ": the tasks of " + header[m] + " add up to " + grade::format_number(sums[m]) +
                             ", " + header[m] + " is " + grade::format_number(points[m]));
      }
    }
  }
  return mismatches;
}

}  // namespace fmbd::frontend
