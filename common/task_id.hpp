#pragma once
// Task ids, the one rule of the workbook for them (TASK(...) markers, the tests' tags, hints, the
// gradebook, the grade driver's --task): "M", the module in two digits, a kind letter, the task's
// number in one or two digits. "M01T3" is task 3 of module 1's code, "M01P2" its tutorial problem
// 2 (a task of the student's inputs), "M08T12".
//
// The kind letters are the protocol's, not kinds of graded items: which tests a build error
// touches is a property of the program that lists them (the grade driver's --grades-inputs), never
// of a letter.

#include <optional>
#include <string>
#include <string_view>

namespace fmbd::protocol {

// The kind letters of a task id, in the order their tasks are reported: the code's tasks ('T'),
// then those of the student's inputs ('P').
inline constexpr std::string_view kTaskKinds = "TP";

struct TaskId {
  int module = 0;   // 0..99
  char kind = 'T';  // one of kTaskKinds
  int number = 0;   // 0..99

  friend bool operator==(const TaskId& a, const TaskId& b) {
    return a.module == b.module && a.kind == b.kind && a.number == b.number;
  }
  friend bool operator!=(const TaskId& a, const TaskId& b) { return !(a == b); }
};

// Whether `kind` is one of kTaskKinds.
bool is_task_kind(char kind);

// `id` read strictly: "M", two digits, a letter of kTaskKinds, one or two digits; nothing for
// anything else ("m01t3", "M1T3", "M01X3", "M01T123", " M01T3"). "M01T03" is task 3.
std::optional<TaskId> parse_task_id(std::string_view id);

// "M01T3" for {1, 'T', 3}: the module in two digits, the number without a leading zero.
std::string format_task_id(const TaskId& task);

// "M01" for 1, "M12" for 12.
std::string format_module_id(int module);

// Orders tasks of one module as they are reported: by kind (kTaskKinds), then by number.
bool task_before(char kind_a, int number_a, char kind_b, int number_b);

}  // namespace fmbd::protocol
