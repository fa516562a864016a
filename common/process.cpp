#include "process.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>

extern char** environ;

namespace fmbd::tools {
namespace {

// In the child, before exec: only async-signal-safe calls.
// output_fd: stdout (and stderr too with `both`), or -1 for the parent's own.
// envp: the child's environment, or null for the parent's.
[[noreturn]] void exec_child(const Command& command, char* const* argv, char** envp, int output_fd, bool both) {
  if (!command.directory.empty() && ::chdir(command.directory.c_str()) != 0) {
    const char* what = "cannot change to the folder of a command\n";
    (void)!::write(2, what, std::strlen(what));
    ::_exit(127);
  }
  if (output_fd >= 0) {
    const int null = ::open("/dev/null", O_RDONLY);
    if (null >= 0) ::dup2(null, 0);
    ::dup2(output_fd, 1);
    if (both) ::dup2(output_fd, 2);
  }
  if (envp != nullptr) environ = envp;  // a pointer assignment: safe here, and execvp searches PATH with it
  ::execvp(argv[0], argv);
  const char* what = "cannot run ";
  (void)!::write(2, what, std::strlen(what));
  (void)!::write(2, argv[0], std::strlen(argv[0]));
  (void)!::write(2, "\n", 1);
  ::_exit(127);
}

int decode(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return 127;
}

Child start_with(const Command& command, int output_fd, bool both) {
  std::vector<char*> argv;
  for (const std::string& arg : command.argv) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);
  // The child's environment, made before fork (no allocation after it): the parent's with
  // command.environment set; the parent's own environment is never changed.
  std::vector<std::string> entries;
  std::vector<char*> envp;
  if (!command.environment.empty()) {
    for (char** entry = environ; *entry != nullptr; ++entry) {
      const std::string text = *entry;
      const std::string name = text.substr(0, text.find('='));
      const bool replaced = std::any_of(command.environment.begin(), command.environment.end(),
                                        [&name](const auto& variable) { return variable.first == name; });
      if (!replaced) entries.push_back(text);
    }
    for (const auto& [name, value] : command.environment) entries.push_back(name + "=" + value);
    for (std::string& entry : entries) envp.push_back(entry.data());
    envp.push_back(nullptr);
  }
  const pid_t pid = command.argv.empty() ? -1 : ::fork();
  if (pid == 0) exec_child(command, argv.data(), envp.empty() ? nullptr : envp.data(), output_fd, both);
  return Child{pid};
}

}  // namespace

Child start(const Command& command) {
  int fd = -1;
  if (!command.output.empty()) {
    fd = ::open(command.output.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC | (command.append ? O_APPEND : O_TRUNC),
                0644);
    if (fd < 0) return Child{-1};
  }
  Child child = start_with(command, fd, true);
  if (fd >= 0) ::close(fd);
  return child;
}

std::optional<int> poll(Child& child) {
  if (child.pid < 0) return 127;
  int status = 0;
  pid_t done = 0;
  while ((done = ::waitpid(child.pid, &status, WNOHANG)) < 0 && errno == EINTR) {
  }
  if (done == 0) return std::nullopt;
  child.pid = -1;
  return done < 0 ? 127 : decode(status);
}

int wait(Child& child) {
  if (child.pid < 0) return 127;
  int status = 0;
  pid_t done = 0;
  while ((done = ::waitpid(child.pid, &status, 0)) < 0 && errno == EINTR) {
  }
  child.pid = -1;
  return done < 0 ? 127 : decode(status);
}

int run(const Command& command) {
  Child child = start(command);
  return wait(child);
}

std::string capture(const Command& command, int& status) {
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) {
    status = 127;
    return "";
  }
  ::fcntl(pipe_fds[0], F_SETFD, FD_CLOEXEC);
  ::fcntl(pipe_fds[1], F_SETFD, FD_CLOEXEC);
  Child child = start_with(command, pipe_fds[1], false);
  ::close(pipe_fds[1]);
  std::string text;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(pipe_fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(pipe_fds[0]);
  status = wait(child);
  return text;
}

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::string folders = path ? path : "";
  for (std::size_t from = 0; from <= folders.size();) {
    const std::size_t to = std::min(folders.find(':', from), folders.size());
    const std::string folder = folders.substr(from, to - from);
    if (!folder.empty() && ::access((folder + "/" + program).c_str(), X_OK) == 0) return true;
    from = to + 1;
  }
  return false;
}

}  // namespace fmbd::tools
