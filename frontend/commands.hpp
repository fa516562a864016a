#pragma once
// The commands of ./workbook: the registry, each command with its option table (options.hpp) and
// the function that runs it; the help is made from it. The students' commands:
// grade (grade.hpp), hint, handin, demo (demo.hpp) and classroom (classroom.hpp); the maintainers':
// test, bench and studentify (maintainer.hpp), release and gradescope (release.hpp), inspect
// (inspect.hpp); and help.
// Those of this file:
//
//   hint [TASK] [--reset]    the hint ladder of a task, one level more per call; without TASK the
//                            tasks and the levels opened (build/hints.opened, "TASK LEVEL" lines)
//   handin [--out FILE.zip]  the exercise files of the manifest that this copy has, as a zip
//                            (default handin.zip in the tree), packed by `cmake -E tar`
//
// Their output and messages are those ./workbook has always printed. A command that cannot go
// on throws UsageError (options.hpp) with the message main() prints after "workbook: " (exit 2).

#include <iosfwd>
#include <string>
#include <vector>

#include "context.hpp"
#include "manifest.hpp"
#include "options.hpp"

namespace fmbd::frontend {

const CommandSpec& hint_command();
const CommandSpec& handin_command();

// Whom a command is for: the help lists the maintainers' commands only in the instructor's copy.
enum class Audience { students, maintainers };

// One command of the registry: its table, whom it is for, and what runs it (with the arguments
// after its name; returns the exit status).
struct CommandEntry {
  const CommandSpec& (*spec)();
  Audience audience;
  CommandFunction run;
};

// Every command, in the order of the help.
const std::vector<CommandEntry>& registry();

// Every command's table, in the order of the registry.
std::vector<const CommandSpec*> commands();

// ./workbook help for the copy at `source_dir`: the usage line, every command's usage_text (the
// maintainers' commands only in the instructor's copy, `instructor`: the course manifest's;
// bench's short form in another copy with the extras and solutions), and the job count with its
// reason.
std::string help_text(const std::string& source_dir, bool instructor);

// Runs the command `name` of the registry (or help) with its arguments; returns the exit status.
// With -h or --help it prints the command's usage (usage_text) and returns 0. An unknown command:
// the help on stderr, exit status 2.
int run_command(const std::string& name, const std::vector<std::string>& args, const Context& context);

int run_hint(const std::vector<std::string>& args, const Context& context);
int run_handin(const std::vector<std::string>& args, const Context& context);

}  // namespace fmbd::frontend
