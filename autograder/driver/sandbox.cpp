#include "sandbox.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string_view>
#include <system_error>
#include <utility>

#include "errno_error.hpp"
#include "output_capture.hpp"
#include "sandbox_child.hpp"

// The parent side of run_sandboxed; the child's, between fork() and exec(), is sandbox_child.cpp.

namespace fmbd::grade {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// How long the killed members of a test's process group get to exit before the driver moves on.
constexpr std::chrono::seconds kKillGrace{2};

// While output flows (or nothing happens) the loop still wakes up this often to notice
// children that exited while a grandchild keeps the pipe open; after end-of-file it
// polls faster, because the child's exit is then imminent.
constexpr std::chrono::milliseconds kIdleTick{100};
constexpr std::chrono::milliseconds kExitTick{2};

// Reading: at most this much per process and wake-up, so that one process flooding its
// pipe cannot starve the others; and at most this much after a process has exited.
constexpr std::size_t kReadChunk = std::size_t{64} * 1024;
constexpr std::size_t kReadBudget = 16 * kReadChunk;
constexpr std::size_t kDrainBudget = 128 * kReadChunk;

// Owns one file descriptor.
class FileDescriptor {
 public:
  FileDescriptor() = default;
  explicit FileDescriptor(int fd) : fd_(fd) {}
  FileDescriptor(FileDescriptor&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}
  FileDescriptor& operator=(FileDescriptor&& other) noexcept {
    if (this != &other) {
      close();
      fd_ = std::exchange(other.fd_, -1);
    }
    return *this;
  }
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  ~FileDescriptor() { close(); }

  int get() const { return fd_; }
  bool is_open() const { return fd_ >= 0; }
  void close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }

 private:
  int fd_ = -1;
};

struct Pipe {
  FileDescriptor read_end;
  FileDescriptor write_end;
};

// Both ends close-on-exec, so that no other child inherits them across exec.
Pipe make_pipe() {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw_errno("pipe2");
  return {FileDescriptor(fds[0]), FileDescriptor(fds[1])};
}

void write_all(int fd, std::string_view data) {
  while (!data.empty()) {
    const ssize_t n = ::write(fd, data.data(), data.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw_errno("write");
    data.remove_prefix(static_cast<std::size_t>(n));
  }
}

// Reads up to `size` bytes, retrying on EINTR. Returns the count, 0 at end of file.
std::size_t read_fully(int fd, void* buffer, std::size_t size) {
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::read(fd, static_cast<char*>(buffer) + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw_errno("read");
    if (n == 0) break;
    done += static_cast<std::size_t>(n);
  }
  return done;
}

// 16 random bytes in hex: the secret a test process must echo to prove it finished.
std::string fresh_token() {
  const FileDescriptor urandom(::open("/dev/urandom", O_RDONLY | O_CLOEXEC));
  if (!urandom.is_open()) throw_errno("open /dev/urandom");
  unsigned char bytes[16];
  if (read_fully(urandom.get(), bytes, sizeof bytes) != sizeof bytes) {
    throw std::system_error(EIO, std::generic_category(), "read /dev/urandom");
  }
  static constexpr char kHex[] = "0123456789abcdef";
  std::string token;
  for (const unsigned char byte : bytes) {
    token += kHex[byte >> 4];
    token += kHex[byte & 0xF];
  }
  return token;
}

// Makes every directory below `dir` accessible to its owner (a test may have left
// read-only directories behind, which would stop the removal).
void make_removable(const fs::path& dir) {
  std::error_code ec;
  fs::permissions(dir, fs::perms::owner_all, fs::perm_options::add, ec);
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->symlink_status(ec).type() == fs::file_type::directory) make_removable(it->path());
  }
}

// A fresh directory under $TMPDIR (or /tmp), removed recursively on destruction.
class TemporaryDirectory {
 public:
  TemporaryDirectory() {
    const char* base = std::getenv("TMPDIR");
    std::string pattern = (base != nullptr && *base != '\0') ? base : "/tmp";
    pattern += "/fmbd-grade.XXXXXX";
    if (::mkdtemp(pattern.data()) == nullptr) throw_errno("mkdtemp");
    path_ = std::move(pattern);
  }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  ~TemporaryDirectory() {
    std::error_code ec;
    fs::remove_all(path_, ec);
    if (!ec) return;
    make_removable(path_);
    fs::remove_all(path_, ec);
    if (ec)
      std::cerr << "fmbd-grade: warning: cannot remove " << path_ << ": " << ec.message() << '\n';
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// Reaps the killed members of process group `group` that were reparented to the driver (a
// child subreaper): until they are reaped they still count against the user's process limit,
// and a fork bomb's remains would keep the next test from starting. It never blocks for long: a
// process that left the group and joins it again after the kill is killed again, and one that
// still lives after kKillGrace is left to its CPU limit.
void reap_group(pid_t group) noexcept {
  const Clock::time_point give_up = Clock::now() + kKillGrace;
  for (;;) {
    const pid_t reaped = ::waitpid(-group, nullptr, WNOHANG);
    if (reaped > 0 || (reaped < 0 && errno == EINTR)) continue;
    if (reaped < 0 || Clock::now() >= give_up) return;  // none left (ECHILD), or out of time
    ::kill(-group, SIGKILL);
    ::usleep(1000);
  }
}

// A started test process. The destructor kills its process group and reaps it if that
// has not happened yet (interruption, exceptions), so no process outlives the driver's
// bookkeeping.
class RunningProcess {
 public:
  RunningProcess(std::size_t index, pid_t pid, FileDescriptor output,
                 std::unique_ptr<TemporaryDirectory> directory, const std::string& token,
                 const Limits& limits, Clock::time_point start)
      : index_(index),
        pid_(pid),
        output_(std::move(output)),
        directory_(std::move(directory)),
        capture_(token, limits.max_output_bytes),
        start_(start),
        deadline_(start + std::chrono::duration_cast<Clock::duration>(
                              std::chrono::duration<double>(limits.timeout_seconds))) {}
  RunningProcess(const RunningProcess&) = delete;
  RunningProcess& operator=(const RunningProcess&) = delete;
  ~RunningProcess() {
    if (pid_ > 0) {
      ::kill(-pid_, SIGKILL);
      while (::waitpid(pid_, nullptr, 0) < 0 && errno == EINTR) {
      }
      reap_group(pid_);
    }
  }

  std::size_t index() const { return index_; }
  int output_fd() const { return output_.get(); }
  Clock::time_point deadline() const { return deadline_; }

  // Reads what is available without blocking, at most `budget` bytes.
  void read_available(std::size_t budget = kReadBudget) {
    std::array<char, kReadChunk> buffer;
    while (output_.is_open() && budget > 0) {
      const ssize_t n = ::read(output_.get(), buffer.data(), std::min(buffer.size(), budget));
      if (n < 0 && errno == EINTR) continue;
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return;
      if (n <= 0) {  // end of file (or an error, which ends the stream just the same)
        output_.close();
        return;
      }
      capture_.append(std::string_view(buffer.data(), static_cast<std::size_t>(n)));
      budget -= static_cast<std::size_t>(n);
    }
  }

  // Whether the child has exited, without reaping it: as long as it is a zombie, its
  // process id and therefore its process group id cannot be reused.
  bool has_exited() const {
    siginfo_t info{};
    while (::waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT) != 0) {
      if (errno != EINTR) throw_errno("waitid");
    }
    return info.si_pid != 0;
  }

  // Kills the process group, reaps the child and collects the rest of the output.
  Outcome finish(bool timed_out) {
    const Clock::time_point end = Clock::now();
    ::kill(-pid_, SIGKILL);
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0) {
      if (errno != EINTR) throw_errno("waitpid");
    }
    reap_group(pid_);
    pid_ = -1;
    // What the child wrote is in the pipe; anything beyond the budget can only come from
    // a process that escaped the group.
    read_available(kDrainBudget);
    output_.close();

    Outcome outcome;
    if (timed_out) {
      outcome.ending = Ending::timed_out;
    } else if (WIFSIGNALED(status)) {
      outcome.ending = Ending::killed_by_signal;
      outcome.status = WTERMSIG(status);
    } else {
      outcome.ending = Ending::exited;
      outcome.status = WEXITSTATUS(status);
    }
    outcome.output = capture_.finish();
    outcome.token = capture_.token_seen();
    outcome.truncated = capture_.truncated();
    outcome.seconds = std::chrono::duration<double>(end - start_).count();
    return outcome;
  }

 private:
  std::size_t index_;
  pid_t pid_;
  FileDescriptor output_;
  std::unique_ptr<TemporaryDirectory> directory_;  // removed after the process is gone
  OutputCapture capture_;
  Clock::time_point start_;
  Clock::time_point deadline_;
};

// Either a running process or the outcome of one that could not start.
struct Started {
  std::unique_ptr<RunningProcess> process;
  Outcome failure;
  bool busy = false;  // the user had too many processes (EAGAIN): worth trying again alone
};

Started start_process(std::size_t index, const std::vector<std::string>& argv,
                      const Limits& limits) {
  const std::string token = fresh_token();
  auto directory = std::make_unique<TemporaryDirectory>();
  if (limits.run_as && ::chown(directory->path().c_str(), limits.run_as->uid, limits.run_as->gid) != 0)
    throw_errno("chown");
  Pipe output = make_pipe();
  Pipe token_pipe = make_pipe();
  Pipe report = make_pipe();
  write_all(token_pipe.write_end.get(), token + "\n");  // far below the pipe's capacity
  token_pipe.write_end.close();

  ExecPlan plan = make_exec_plan(argv, directory->path(), limits);
  plan.output_fd = output.write_end.get();
  plan.token_fd = token_pipe.read_end.get();
  plan.report_fd = report.write_end.get();

  if (::fcntl(output.read_end.get(), F_SETFL, O_NONBLOCK) != 0) throw_errno("fcntl");

  const Clock::time_point start = Clock::now();
  const pid_t pid = ::fork();
  if (pid < 0) throw_errno("fork");
  if (pid == 0) exec_in_sandbox(plan);

  output.write_end.close();
  token_pipe.read_end.close();
  report.write_end.close();

  // The report pipe closes on a successful exec; otherwise the child says what failed.
  ChildFailure failure{};
  if (read_fully(report.read_end.get(), &failure, sizeof failure) == sizeof failure) {
    while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
    }
    Started started;
    started.failure.ending = Ending::could_not_start;
    started.failure.error = describe(failure, plan.argv_storage[0]);
    started.busy = failure.error == EAGAIN;
    return started;
  }
  Started started;
  started.process = std::make_unique<RunningProcess>(index, pid, std::move(output.read_end),
                                                     std::move(directory), token, limits, start);
  return started;
}

using ProcessList = std::vector<std::unique_ptr<RunningProcess>>;

// Sleeps until some output arrives, a deadline passes, the next tick is due, or the user
// interrupts. Returns false on interruption.
bool wait_for_activity(const ProcessList& running, int interrupt_fd) {
  std::vector<pollfd> watched;
  Clock::duration wait = kIdleTick;
  const Clock::time_point now = Clock::now();
  for (const auto& process : running) {
    if (process->output_fd() >= 0) {
      watched.push_back({process->output_fd(), POLLIN, 0});
    } else {
      wait = std::min<Clock::duration>(wait, kExitTick);
    }
    wait = std::min(wait, std::max(Clock::duration::zero(), process->deadline() - now));
  }
  if (interrupt_fd >= 0) watched.push_back({interrupt_fd, POLLIN, 0});
  // Round up, so that the loop does not spin just before a deadline.
  const auto milliseconds = std::chrono::ceil<std::chrono::milliseconds>(wait).count();
  if (::poll(watched.data(), watched.size(), static_cast<int>(milliseconds)) < 0) {
    if (errno == EINTR) return true;
    throw_errno("poll");
  }
  return interrupt_fd < 0 || (watched.back().revents & POLLIN) == 0;
}

}  // namespace

std::optional<std::vector<Outcome>> run_sandboxed(
    const std::vector<std::vector<std::string>>& given_commands, const Limits& limits, unsigned jobs,
    int interrupt_fd) {
  // An unprivileged user may not reach the programs where they were built (a home folder, say):
  // run copies from a directory that everybody may read and nobody but root may change.
  std::vector<std::vector<std::string>> copied_commands;
  std::unique_ptr<TemporaryDirectory> programs;
  if (limits.run_as) {
    programs = std::make_unique<TemporaryDirectory>();
    fs::permissions(programs->path(), fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                          fs::perms::others_read | fs::perms::others_exec);
    std::vector<std::pair<std::string, std::string>> copies;  // original -> copy
    for (std::vector<std::string> command : given_commands) {
      std::string& program = command.at(0);
      auto known = std::find_if(copies.begin(), copies.end(), [&](const auto& c) { return c.first == program; });
      if (known == copies.end()) {
        const fs::path copy = fs::path(programs->path()) /
                              (std::to_string(copies.size()) + "-" + fs::path(program).filename().string());
        std::error_code ec;
        fs::copy_file(program, copy, ec);
        if (!ec) fs::permissions(copy, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                           fs::perms::others_read | fs::perms::others_exec, ec);
        // A program that cannot be copied keeps its path: exec then reports the problem.
        copies.emplace_back(program, ec ? program : copy.string());
        known = copies.end() - 1;
      }
      program = known->second;
      copied_commands.push_back(std::move(command));
    }
  }
  const std::vector<std::vector<std::string>>& commands = limits.run_as ? copied_commands : given_commands;
  // Orphans of a test process (a fork bomb's children) are reparented to the driver, which
  // reaps them with their group (reap_group). Without this (before Linux 3.4) init reaps them.
  ::prctl(PR_SET_CHILD_SUBREAPER, 1);
  std::vector<Outcome> outcomes(commands.size());
  ProcessList running;  // destroyed (killed, reaped, cleaned up) on every way out
  std::size_t next = 0;
  // Tests that could not start because the user had too many processes: all tests run as one
  // user, so another test's fork bomb can cause that. Each is tried again once nothing else runs.
  std::deque<std::size_t> deferred;
  const auto launch = [&](std::size_t index, bool may_defer) {
    Limits own = limits;
    if (index < limits.command_timeouts.size()) own.timeout_seconds = limits.command_timeouts[index];
    Started started = start_process(index, commands[index], own);
    if (started.process) {
      running.push_back(std::move(started.process));
    } else if (started.busy && may_defer) {
      deferred.push_back(index);
    } else {
      outcomes[index] = std::move(started.failure);
    }
  };
  while (next < commands.size() || !deferred.empty() || !running.empty()) {
    while (running.size() < std::max(jobs, 1U) && next < commands.size()) launch(next++, true);
    if (running.empty() && !deferred.empty()) {
      launch(deferred.front(), false);
      deferred.pop_front();
    }
    if (running.empty()) continue;
    if (!wait_for_activity(running, interrupt_fd)) return std::nullopt;

    const Clock::time_point now = Clock::now();
    for (auto it = running.begin(); it != running.end();) {
      RunningProcess& process = **it;
      process.read_available();
      const bool exited = process.has_exited();
      if (exited || now >= process.deadline()) {
        outcomes[process.index()] = process.finish(/*timed_out=*/!exited);
        it = running.erase(it);
      } else {
        ++it;
      }
    }
  }
  return outcomes;
}

}  // namespace fmbd::grade
