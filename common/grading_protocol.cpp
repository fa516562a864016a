#include "grading_protocol.hpp"

namespace fmbd::protocol {

std::string task_tags(const TaskId& task, std::string_view points) {
  return "[" + format_module_id(task.module) + "][" + task.kind + std::to_string(task.number) + "][points=" +
         std::string(points) + "]";
}

std::string catch_test_spec(std::string_view name) {
  constexpr std::string_view kSpecial = "\\,[]*~\"";
  std::string spec = "\"";
  for (const char c : name) {
    if (kSpecial.find(c) != std::string_view::npos) spec += '\\';
    spec += c;
  }
  spec += '"';
  return spec;
}

std::string test_name_of_spec(std::string_view spec) {
  if (spec.size() >= 2 && spec.front() == '"' && spec.back() == '"') spec = spec.substr(1, spec.size() - 2);
  std::string name;
  for (std::size_t i = 0; i < spec.size(); ++i) {
    if (spec[i] == '\\' && i + 1 < spec.size()) ++i;
    name += spec[i];
  }
  return name;
}

}  // namespace fmbd::protocol
