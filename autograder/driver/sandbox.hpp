#pragma once
// Running untrusted test programs, each in its own sandboxed process (POSIX, Linux).
//
// For every command, run_sandboxed()
//   * forks; the child calls only async-signal-safe functions until it execs, and
//       - starts a new session, so that it leads a fresh process group,
//       - reads stdin from /dev/null and writes stdout and stderr into one pipe,
//       - finds on fd 3 a pipe holding a fresh random completion token and a newline
//         (16 bytes from /dev/urandom in hex; never in argv or the environment),
//       - has every other descriptor closed,
//       - runs in a fresh temporary directory (also exported as TMPDIR),
//       - has an empty signal mask and default signal dispositions,
//       - runs under resource limits: CPU time timeout+1 s, address space 4 GiB (not
//         when the driver is built with AddressSanitizer), file size 64 MiB, no core
//         files, at most 512 processes for the user (this limit does not bind root);
//       - runs as the unprivileged user of `Limits::run_as` if one is given (the driver
//         must then be root): supplementary groups dropped, gid and uid set before exec.
//         The test programs are then copied into a directory that user can read, and
//         the temporary directory is handed to that user;
//   * reads the pipe with poll(), keeping the first `max_output_bytes` bytes and
//     discarding the rest, while watching the whole stream for the completion-token line;
//   * kills the whole process group when the wall-clock timeout expires and, in any case,
//     as soon as the child has exited, so that nothing the test started survives it (a
//     process that leaves the group with setsid() escapes; RLIMIT_CPU still bounds it),
//     and reaps the group's orphans, which the driver adopts as a child subreaper;
//   * starts a test that could not start because its user had too many processes (EAGAIN:
//     the tests share one user, and another test may be a fork bomb) again once no other
//     test runs, and only then reports it as not started;
//   * removes the temporary directory recursively.

#include <sys/types.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "grading_protocol.hpp"

namespace fmbd::grade {

// An unprivileged account the test processes run as.
struct Identity {
  std::string name;
  uid_t uid = 0;
  gid_t gid = 0;
};

// The account `name`, or std::nullopt if it does not exist.
std::optional<Identity> find_identity(const std::string& name);

// The folders on the way to the file `path` (its own folder and every one above it) that `who`
// may not enter, outermost first, judged by their owner, group and mode bits as a test process
// of `who` would be (supplementary groups dropped; ACLs are not read). A test program is
// copied for `who`, but the files it reads beside it (an answer key, say) stay where they are.
std::vector<std::string> folders_closed_to(const std::string& path, const Identity& who);

struct Limits {
  double timeout_seconds = 30;                            // wall clock, per process
  std::size_t max_output_bytes = std::size_t{64} * 1024;  // output kept per process
  std::optional<Identity> run_as;                         // drop root to this account
  std::vector<double> command_timeouts;  // per command, where given: replaces timeout_seconds
};

enum class Ending {
  exited,            // `status` is the exit status
  killed_by_signal,  // `status` is the signal number
  timed_out,         // killed by the driver after `Limits::timeout_seconds`
  could_not_start,   // `error` says why (for example, the program does not exist)
};

// Whether the output contained the line "fmbd-completion-token: <token>".
enum class TokenSeen {
  none,      // no completion-token line at all
  matching,  // the line with this process's token
  wrong,     // only completion-token lines with some other token
};

struct Outcome {
  Ending ending = Ending::could_not_start;
  int status = 0;
  TokenSeen token = TokenSeen::none;
  std::string output;  // stdout and stderr interleaved, without the matching token line;
                       // ends with "[output truncated] ..." when bytes were discarded
  bool truncated = false;
  double seconds = 0;  // wall clock
  std::string error;
};

// The line a test program prints, followed by its token, once its checks have run.
using protocol::kCompletionTokenPrefix;  // common/grading_protocol.hpp

// Runs every command (argv; argv[0] is a path to the program, relative paths are taken
// from the current directory), at most `jobs` processes at a time, and returns the
// outcomes in the order of `commands`.
//
// `interrupt_fd` is a descriptor (a signalfd) that becomes readable when the user asks
// to stop, or -1. When it becomes readable, every running process is killed, its
// directory removed, and the result is std::nullopt.
//
// Throws std::system_error when the driver itself cannot work (no pipes, no fork, no
// temporary directory, no /dev/urandom): that is an infrastructure failure, not a test's.
std::optional<std::vector<Outcome>> run_sandboxed(
    const std::vector<std::vector<std::string>>& commands, const Limits& limits, unsigned jobs,
    int interrupt_fd);

}  // namespace fmbd::grade
