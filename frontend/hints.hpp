#pragma once
// The hint ladders of the modules (moduleNN_*/hints.md) as ./workbook hint reads them and
// ./workbook release trims them.
//
// A ladder file is Markdown:
//   # Module 1 hints                         (anything before the first task)
//   <!-- hint-ceiling: 2 -->                 (a release's note: the ladders stop at level 2)
//   ## M01T1                                 a task's ladder
//   ### Level 1                              its levels, in order, each up to the next heading
//   ...
// A "## " heading whose second word is not a task id ends a ladder too. The functions below keep
// the exact rules of the awk programs that ./workbook used, line by line (a "### Level k" line is
// exactly that; blank lines inside a level are kept only between text).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fmbd::frontend::hints {

// The tasks of one or more ladder files read one after the other, in order, each with its top
// level (the number of the last "### Level k" under it; 0 when it has none). A task named twice
// is listed twice.
struct Ladder {
  std::string task;
  int levels = 0;
};
std::vector<Ladder> list_ladders(const std::vector<std::string>& texts);

// The top level of `task` in `text` (0: the file has no ladder for it).
int levels_of(std::string_view text, std::string_view task);

// The second word of every "## M..." heading, in order: the tasks a refusal names.
std::vector<std::string> task_headings(std::string_view text);

// The levels 1..upto of `task`, each under "-- TASK, level k --" (a blank line before every
// heading but the first), as ./workbook hint prints them; every line ends in "\n".
std::string render(std::string_view text, std::string_view task, int upto);

// The ceiling that a release noted in `text` ("<!-- hint-ceiling: N -->"), or nothing.
std::optional<int> ceiling(std::string_view text);

// `text` with the levels above `ceiling` (>= 1) left out, the ceiling noted after its first line,
// and runs of empty lines squeezed to one: a release's hints.md.
std::string apply_ceiling(std::string_view text, int ceiling);

// The opened levels of a student (build/hints.opened): one "TASK LEVEL" line per task.
// opened_level: the level of the last line of `task` (0: none). with_opened: `opened` without
// the lines of `task`, then "TASK LEVEL" when level > 0.
int opened_level(std::string_view opened, std::string_view task);
std::string with_opened(std::string_view opened, std::string_view task, int level);

}  // namespace fmbd::frontend::hints
