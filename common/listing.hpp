#pragma once
// The test list a test program prints, read (the one reader of that format; the grade driver
// and ./workbook inspect listing use it).
//
// A test program lists its tests with `PROGRAM --fmbd-list`: one line per test case,
// "name<TAB>[tag][tag]...". The tags that matter for grading are
//   [Mnn]       module number           (missing: the test belongs to no module)
//   [Tk]        task number             (missing: no task)
//   [Pk]        number of a task of the student's inputs, such as a tutorial problem (MnnPk
//               beside MnnTk); each kind letter of a task id (common/task_id.hpp) is a tag
//   [points=p]  weight, p >= 0          (missing: 1 point)
//   [hidden]    a hidden test (Gradescope shows it only after publication)
// and are read case-insensitively; other tags are ignored.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "task_id.hpp"

namespace fmbd::grade {

// A task of a module: a task of the code ('T', "T3") or of the student's inputs, such as a
// tutorial problem ('P', "P2"). The letter is part of the task id (common/task_id.hpp), which the
// program's listing gives (its tags), whatever the kind of graded item: no code of the driver
// tests a kind. The tasks are ordered as task ids are reported (protocol::task_before).
struct Task {
  char kind = 'T';
  int number = 0;

  friend bool operator==(const Task& a, const Task& b) { return a.kind == b.kind && a.number == b.number; }
  friend bool operator!=(const Task& a, const Task& b) { return !(a == b); }
  friend bool operator<(const Task& a, const Task& b) {
    return protocol::task_before(a.kind, a.number, b.kind, b.number);
  }
};

struct TestCase {
  std::string executable;
  std::string name;
  std::optional<int> module;
  std::optional<Task> task;
  double points = 1;
  bool hidden = false;
  // Its program grades the student's inputs, not the module's code (fmbd-grade's --grades-inputs):
  // a module's --reject or --build-errors does not touch it.
  bool grades_inputs = false;
};

// The tests of the test list `text` that the program `executable` printed (`error` empty), or
// the reason it is malformed, naming the line ("line 3: expected name<TAB>tags: ...").
struct ParsedList {
  std::vector<TestCase> tests;
  std::string error;
};
ParsedList parse_test_list(std::string_view text, const std::string& executable);

// Reads the grading tags into `test`; returns an error message for a malformed tag list.
std::optional<std::string> apply_tags(std::string_view tags, TestCase& test);

// "M01" for module 1, "other" for tests without a module; "T2" or "P2", or "-" without a task.
std::string module_label(const std::optional<int>& module);
std::string task_label(const std::optional<Task>& task);

}  // namespace fmbd::grade
