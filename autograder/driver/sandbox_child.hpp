#pragma once
// The child side of run_sandboxed (sandbox.hpp): how a test process is set up between fork() and
// exec(). Everything it needs is prepared before fork() (make_exec_plan): between fork() and
// exec() it calls only async-signal-safe functions (no malloc, no iostreams), which is what POSIX
// guarantees to work in the child of a process that might have threads.

#include <sys/resource.h>
#include <sys/types.h>

#include <string>
#include <vector>

#include "sandbox.hpp"

namespace fmbd::grade {

struct ResourceLimit {
  int resource;
  rlimit value;
};

// What went wrong in the child before exec; sent to the parent through the report descriptor
// (fd 4 in the child, close-on-exec), whose closing without a report means that exec succeeded.
struct ChildFailure {
  enum Step : int { new_session, redirection, change_directory, resource_limit, identity, exec } step;
  int error;
};

// What the child does, prepared by the parent: the program (argv[0] absolute) and its arguments,
// the environment, the temporary directory, the resource limits, the descriptors it places and
// the user it becomes.
struct ExecPlan {
  std::vector<std::string> argv_storage;
  std::vector<std::string> env_storage;
  std::vector<char*> argv;
  std::vector<char*> envp;
  std::string directory;
  std::vector<ResourceLimit> limits;
  int output_fd = -1;  // becomes stdout and stderr
  int token_fd = -1;   // becomes fd 3, where the test program finds its completion token
  int report_fd = -1;  // becomes fd 4, the report descriptor
  int max_fd = 1024;   // for closing descriptors when close_range() is unavailable
  bool drop_privileges = false;
  uid_t uid = 0;
  gid_t gid = 0;
};

// The plan of running `argv` in `directory` under `limits`: argv[0] made absolute (the child
// changes directory), the driver's environment with TMPDIR set to `directory`, the resource limits
// (CPU time timeout+1 s, then SIGKILL a second later; file size 64 MiB; no core files; 512
// processes; address space 4 GiB unless the driver is built with AddressSanitizer), each never
// above the current hard limit, and the user of `limits.run_as`, if any. The descriptors are left
// for the caller to set. Throws std::system_error when the limits cannot be read.
ExecPlan make_exec_plan(const std::vector<std::string>& argv, const std::string& directory, const Limits& limits);

// In the child after fork(): an empty signal mask and default dispositions, a new session, stdin
// from /dev/null, stdout and stderr to output_fd, the token on fd 3, the report on fd 4, every
// other descriptor closed; then the temporary directory, the resource limits (one that cannot be
// set is said on stderr, and the test runs without it), the user, and exec. Where a step fails,
// it writes a ChildFailure to the report descriptor and exits with status 127.
[[noreturn]] void exec_in_sandbox(const ExecPlan& plan) noexcept;

// Why the child could not start `program`, from its report, in a few words.
std::string describe(const ChildFailure& failure, const std::string& program);

}  // namespace fmbd::grade
