#include "ids.hpp"

#include <cctype>

#include "options.hpp"

namespace fmbd::frontend {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

std::pair<std::optional<WrittenTask>, std::string> normalise_task_id(std::string_view text) {
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
  const std::optional<protocol::TaskId> task = protocol::parse_task_id(id);
  if (!task) return {std::nullopt, id};
  return {WrittenTask{*task, id}, id};
}

WrittenTask parse_task_id(std::string_view text, std::string_view command) {
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
