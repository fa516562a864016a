#pragma once
// Module and task ids as the workbook writes them: "M01" for module 1, "M01T3" for its third
// task, "M01P2" for its second tutorial problem. A student may write a task as M1T3, m01t3 or
// M01T3; they all name M01T3.

#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "task_id.hpp"

namespace fmbd::frontend {

// A task as a student named it: the task (common/task_id.hpp), and its id as rewritten
// ("M01T3"; "M01T03" as a student wrote it, which names no task of the hint ladders).
struct WrittenTask {
  protocol::TaskId task;
  std::string id;
};

// "M01" for 1, "M12" for 12.
inline std::string module_id(int module) { return protocol::format_module_id(module); }

// The task named by `text` after the workbook's rule: every 'm', 't' and 'p' upper-cased, a one-digit
// module ("M1T3") given its leading zero; then it must be a task id (protocol::parse_task_id). The
// second member is that rewritten text, which a refusal quotes.
std::pair<std::optional<WrittenTask>, std::string> normalise_task_id(std::string_view text);

// The task named by `text`, or nothing.
inline std::optional<WrittenTask> task_id(std::string_view text) { return normalise_task_id(text).first; }

// The task named by `text` (normalise_task_id), or a UsageError from `command`:
// "hint: 'X' is not a task id; write it like M01T3 (./workbook hint lists them)".
WrittenTask parse_task_id(std::string_view text, std::string_view command);

}  // namespace fmbd::frontend
