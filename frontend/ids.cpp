#include "ids.hpp"

#include <cctype>
#include <cstdio>

#include "options.hpp"
#include "strings.hpp"

namespace fmbd::frontend {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

std::string module_id(int module) {
  char text[16];
  std::snprintf(text, sizeof text, "M%02d", module);
  return text;
}

std::pair<std::optional<TaskId>, std::string> normalise_task_id(std::string_view text) {
  std::string id(text);
  for (char& c : id) {
    if (c == 'm') c = 'M';
    if (c == 't') c = 'T';
    if (c == 'p') c = 'P';
  }
  // "M" digit "T" digit...: the module written with one digit.
  if (id.size() >= 4 && id[0] == 'M' && is_digit(id[1]) && (id[2] == 'T' || id[2] == 'P') && is_digit(id[3])) {
    id.insert(1, "0");
  }
  if (!tools::is_task_id(id)) return {std::nullopt, id};
  TaskId task;
  task.module = (id[1] - '0') * 10 + (id[2] - '0');
  task.task = std::stoi(id.substr(4));
  task.id = id;
  return {task, id};
}

TaskId parse_task_id(std::string_view text, std::string_view command) {
  const auto [task, rewritten] = normalise_task_id(text);
  if (!task) {
    throw UsageError(std::string(command) + ": '" + rewritten +
                     "' is not a task id; write it like M01T3 (./workbook hint lists them)");
  }
  return *task;
}

std::optional<int> module_number_of_folder(std::string_view folder) {
  if (folder.size() < 10 || folder.substr(0, 6) != "module" || !is_digit(folder[6]) || !is_digit(folder[7]) ||
      folder[8] != '_') {
    return std::nullopt;
  }
  return (folder[6] - '0') * 10 + (folder[7] - '0');
}

}  // namespace fmbd::frontend
