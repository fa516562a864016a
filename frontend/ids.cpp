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

}  // namespace fmbd::frontend
