#pragma once
// The commands of ./workbook that the front end runs, each with its option table (options.hpp):
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

#include "manifest.hpp"
#include "options.hpp"

namespace fmbd::frontend {

// What a command works on.
struct Context {
  std::string source_dir;  // the tree (absolute): paths of the manifest are relative to it
  Manifest manifest;
  std::ostream& out;       // the command's output
};

const CommandSpec& hint_command();
const CommandSpec& handin_command();

// The commands, by name, in the order of the usage text.
std::vector<const CommandSpec*> commands();

// Runs the command `name` with its arguments; returns the exit status. With -h or --help it
// prints the command's usage (usage_text) and returns 0.
int run_command(const std::string& name, const std::vector<std::string>& args, const Context& context);

int run_hint(const std::vector<std::string>& args, const Context& context);
int run_handin(const std::vector<std::string>& args, const Context& context);

}  // namespace fmbd::frontend
