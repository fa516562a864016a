#pragma once
// The hint gate of the failure messages: the one place that decides whether a message may show a
// formula.
//
// A failed check names the likely mistake in words, always. The formula behind it (an
// expression of the task's result) belongs to the last level of the task's hint ladder
// (moduleNN_*/hints.md, level 3, the worked formula): a message shows it only once the student
// has opened that level with ./workbook hint for the task of the running test. Below it, the
// message ends with a pointer to the ladder instead:
//
//   with_formula("your C_q's phi column is A s_bar itself, not its derivative",
//                "d(A s_bar)/dphi = A I~ s_bar")
//     level 0-2:  "your C_q's phi column ... derivative (more: ./workbook hint M01T2)"
//     level 3:    "your C_q's phi column ... derivative; the formula: d(A s_bar)/dphi = A I~ s_bar"
//
// The levels come from the file that FMBD_HINTS_OPENED names (grading_protocol.hpp: the front end
// passes the student's build/hints.opened when it grades the student's own tree, and an empty
// value, no levels, when it grades a submission); unset, from that file of the tree the program was
// built in (FMBD_SOURCE_TREE, a compile definition), as a student runs a test program by hand.
// The task is that of the running test case, from its tags [Mnn][Tk] (the listener in
// catch_main.cpp sets it); a test without them has none, and level 0.
//
// The gate teaches in steps; it does not lock anything: the check sources are in the student's
// copy. Defined in hint_gate.cpp, which fmbd_catch_main compiles into every test program.

#include <string>
#include <string_view>

namespace fmbd::testing {

/// The task ("M01T2") that tags such as "[M01][T2][points=2]" name; "" when they name none.
std::string task_of_tags(std::string_view tags);

/// Sets the task of the running test case ("" for none); the Catch listener calls it.
void set_running_task(std::string task);

/// The task of the running test case ("" when none).
const std::string& running_task();

/// The hint level the student opened for the running task (0: none, or no task).
int running_hint_level();

/// `words`, then `formula` once the running task's last hint level is open, else a pointer to
/// ./workbook hint for the task. An empty `formula` gives `words` unchanged.
std::string with_formula(std::string_view words, std::string_view formula);

}  // namespace fmbd::testing
