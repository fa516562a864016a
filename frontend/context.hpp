#pragma once
// What every command of ./workbook works on, and the one signature of a command.
//
// main() (main.cpp) reads the course manifest, makes the Context and runs the command of the
// registry (commands.hpp) by its name. Every command is a CommandFunction: it takes its arguments
// (those after its name) and the Context, and returns its exit status; a command that cannot go on
// throws (options.hpp's UsageError and the others, whose exit statuses exit_status.hpp gives). A
// command that runs another one with its output elsewhere passes a Context of its own:
// Context{context.source_dir, context.manifest, other_stream}.

#include <iosfwd>
#include <string>
#include <vector>

#include "manifest.hpp"

namespace fmbd::frontend {

struct Context {
  std::string source_dir;  // the tree (absolute): paths of the manifest are relative to it
  Manifest manifest;       // the course manifest of the tree's build (manifest.hpp)
  std::ostream& out;       // the command's output
};

// A command: its arguments after its name, and what it works on; its exit status.
using CommandFunction = int (*)(const std::vector<std::string>& args, const Context& context);

}  // namespace fmbd::frontend
