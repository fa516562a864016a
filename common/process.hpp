#pragma once
// Child processes of the front end (the build tool, the grade driver, the demos) and of the
// tools (the compiler and nm for fmbd-vet). Each runs from an argv vector, never through a shell,
// so that paths with spaces and quotes pass as they are.
//
// A child inherits the parent's environment (plus `Command::environment`), runs in
// `Command::directory` (empty: the current one) and writes its standard output and error either
// to the parent's own (no `output` file) or both to the file `output` (truncated, or appended
// to with `append`). Its standard input is /dev/null when it writes to a file.

#include <sys/types.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fmbd::tools {

struct Command {
  explicit Command(std::vector<std::string> argv_, std::string directory_ = "", std::string output_ = "",
                   bool append_ = false)
      : argv(std::move(argv_)), directory(std::move(directory_)), output(std::move(output_)), append(append_) {}

  std::vector<std::string> argv;  // argv[0] is looked up on PATH when it holds no '/'
  std::string directory;
  std::string output;             // a file for stdout and stderr; empty: the parent's own
  bool append = false;
  std::vector<std::pair<std::string, std::string>> environment;  // set in the child
};

// A started child. Move-only in spirit: wait for it exactly once (wait() or a poll() that
// reports its end).
struct Child {
  pid_t pid = -1;
};

// Starts `command`. A program that cannot start ends at once with status 127 (its reason in
// `output`, or on stderr).
Child start(const Command& command);

// The exit status of `child` once it has ended: its exit code, 128 + the signal that ended it.
// poll() returns nothing while it runs.
std::optional<int> poll(Child& child);
int wait(Child& child);

// start() then wait().
int run(const Command& command);

// Runs `command` (its `output` ignored) and returns its standard output; `status` receives its
// exit status. Its standard error goes to the parent's.
std::string capture(const Command& command, int& status);

// Whether an executable `program` is in a folder of PATH.
bool on_path(const std::string& program);

}  // namespace fmbd::tools
