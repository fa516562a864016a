#include "hints.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>

#include "grading_protocol.hpp"
#include "strings.hpp"
#include "task_id.hpp"

namespace fmbd::frontend::hints {
namespace {

// The records of `text` as awk reads them: lines without their "\n"; no empty last record.
using fmbd::tools::split_lines;

// awk's $n: the n-th field split on blanks (1-based), or "".
std::string field(const std::string& line, int n) {
  std::size_t pos = 0;
  for (int i = 1;; ++i) {
    pos = line.find_first_not_of(" \t", pos);
    if (pos == std::string::npos) return "";
    const std::size_t end = line.find_first_of(" \t", pos);
    if (i == n) return line.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
    if (end == std::string::npos) return "";
    pos = end;
  }
}

// awk's number of a field: its leading digits ("2x" is 2, "" is 0).
int number_of(const std::string& text) { return std::atoi(text.c_str()); }

using fmbd::tools::is_digits;
using fmbd::tools::starts_with;

// "### Level k", exactly.
bool is_level_heading(const std::string& line) {
  return starts_with(line, "### Level ") && is_digits(std::string_view(line).substr(10));
}

// "## MnnTk", exactly: a task id (task_id.hpp) of the code's tasks, which the ladders are for.
bool is_task_heading(const std::string& line) {
  if (!starts_with(line, "## ")) return false;
  const std::optional<protocol::TaskId> task = protocol::parse_task_id(std::string_view(line).substr(3));
  return task && task->kind == 'T';
}

// "<!-- hint-ceiling: N -->", its N.
std::optional<int> ceiling_note(const std::string& line) {
  constexpr std::string_view head = "<!-- hint-ceiling: ";
  constexpr std::string_view tail = " -->";
  if (!starts_with(line, head) || line.size() < head.size() + tail.size()) return std::nullopt;
  const std::string_view digits = std::string_view(line).substr(head.size(), line.size() - head.size() - tail.size());
  if (line.compare(line.size() - tail.size(), tail.size(), tail) != 0 || !is_digits(digits)) return std::nullopt;
  return number_of(std::string(digits));
}

bool is_blank(const std::string& line) { return line.find_first_not_of(" \t") == std::string::npos; }

}  // namespace

std::vector<Ladder> list_ladders(const std::vector<std::string>& texts) {
  std::vector<Ladder> ladders;
  std::map<std::string, int> levels;
  std::string task;  // awk's variables live across the files
  for (const std::string& text : texts) {
    for (const std::string& line : split_lines(text)) {
      if (is_task_heading(line)) {
        task = field(line, 2);
        ladders.push_back({task, 0});
      } else if (is_level_heading(line) && !task.empty()) {
        levels[task] = number_of(field(line, 3));
      }
    }
  }
  for (Ladder& ladder : ladders) ladder.levels = levels[ladder.task];
  return ladders;
}

int levels_of(std::string_view text, std::string_view task) {
  bool in_task = false;
  int levels = 0;
  for (const std::string& line : split_lines(text)) {
    if (starts_with(line, "## ")) in_task = field(line, 2) == task;
    if (in_task && is_level_heading(line)) levels = number_of(field(line, 3));
  }
  return levels;
}

std::vector<std::string> task_headings(std::string_view text) {
  std::vector<std::string> tasks;
  for (const std::string& line : split_lines(text)) {
    if (starts_with(line, "## M")) tasks.push_back(field(line, 2));
  }
  return tasks;
}

std::string render(std::string_view text, std::string_view task, int upto) {
  std::string out;
  bool in_task = false;
  int level = 0;  // as in awk, it carries over from one ladder to the next
  int blanks = 0;
  for (const std::string& line : split_lines(text)) {
    if (starts_with(line, "## ")) {
      in_task = field(line, 2) == task;
      continue;
    }
    if (!in_task) continue;
    if (is_level_heading(line)) {
      level = number_of(field(line, 3));
      if (level <= upto) {
        out += (level > 1 ? "\n-- " : "-- ") + std::string(task) + ", level " + std::to_string(level) + " --\n";
      }
      blanks = 0;
      continue;
    }
    if (level < 1 || level > upto) continue;
    if (is_blank(line)) {
      ++blanks;
      continue;
    }
    if (blanks > 0) out += "\n";
    blanks = 0;
    out += line + "\n";
  }
  return out;
}

std::optional<int> ceiling(std::string_view text) {
  std::optional<int> found;
  for (const std::string& line : split_lines(text)) {
    if (const auto note = ceiling_note(line)) found = note;
  }
  return found;
}

std::string apply_ceiling(std::string_view text, int ceiling) {
  std::vector<std::string> kept;
  int level = 0;
  const std::vector<std::string> lines = split_lines(text);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    if (starts_with(line, "## ")) level = 0;
    if (is_level_heading(line)) level = number_of(field(line, 3));
    if (level > ceiling) continue;
    kept.push_back(line);
    if (i == 0) {
      kept.emplace_back();
      kept.push_back("<!-- hint-ceiling: " + std::to_string(ceiling) + " -->");
    }
  }
  std::string out;  // cat -s: one empty line where there were several
  bool after_empty = false;
  for (const std::string& line : kept) {
    if (line.empty() && after_empty) continue;
    after_empty = line.empty();
    out += line + "\n";
  }
  return out;
}

int opened_level(std::string_view opened, std::string_view task) { return protocol::opened_hint_level(opened, task); }

std::string with_opened(std::string_view opened, std::string_view task, int level) {
  std::string out;
  for (const std::string& line : split_lines(opened)) {
    if (field(line, 1) != task) out += line + "\n";
  }
  if (level > 0) out += std::string(task) + " " + std::to_string(level) + "\n";
  return out;
}

}  // namespace fmbd::frontend::hints
