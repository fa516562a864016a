#include "task_id.hpp"

#include <cstdio>

namespace fmbd::protocol {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

bool is_task_kind(char kind) { return kind != '\0' && kTaskKinds.find(kind) != std::string_view::npos; }

std::optional<TaskId> parse_task_id(std::string_view id) {
  if ((id.size() != 5 && id.size() != 6) || id[0] != 'M' || !is_digit(id[1]) || !is_digit(id[2]) ||
      !is_task_kind(id[3]) || !is_digit(id[4]) || (id.size() == 6 && !is_digit(id[5]))) {
    return std::nullopt;
  }
  TaskId task;
  task.module = (id[1] - '0') * 10 + (id[2] - '0');
  task.kind = id[3];
  task.number = id.size() == 5 ? id[4] - '0' : (id[4] - '0') * 10 + (id[5] - '0');
  return task;
}

std::string format_task_id(const TaskId& task) {
  return format_module_id(task.module) + task.kind + std::to_string(task.number);
}

std::string format_module_id(int module) {
  char text[16];
  std::snprintf(text, sizeof text, "M%02d", module);
  return text;
}

bool task_before(char kind_a, int number_a, char kind_b, int number_b) {
  if (kind_a != kind_b) return kTaskKinds.find(kind_a) < kTaskKinds.find(kind_b);
  return number_a < number_b;
}

}  // namespace fmbd::protocol
