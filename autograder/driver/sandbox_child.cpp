#include "sandbox_child.hpp"

#include <fcntl.h>
#include <grp.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/types.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>

#include "errno_error.hpp"
#include "text.hpp"

extern char** environ;

namespace fmbd::grade {
namespace {

namespace fs = std::filesystem;

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kBuiltWithAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kBuiltWithAddressSanitizer = true;
#else
constexpr bool kBuiltWithAddressSanitizer = false;
#endif
#else
constexpr bool kBuiltWithAddressSanitizer = false;
#endif

constexpr rlim_t kMiB = rlim_t{1024} * 1024;
constexpr rlim_t kAddressSpaceLimit = 4096 * kMiB;
constexpr rlim_t kFileSizeLimit = 64 * kMiB;
constexpr rlim_t kProcessLimit = 512;

constexpr int kTokenFd = 3;   // where the test program finds its completion token
constexpr int kReportFd = 4;  // child -> parent: why exec failed (close-on-exec)
constexpr int kFirstFreeFd = 5;

// Each limit as requested, but never above the current hard limit (an unprivileged
// process may not raise it).
std::vector<ResourceLimit> resource_limits(const Limits& limits) {
  const auto cpu = static_cast<rlim_t>(std::ceil(limits.timeout_seconds)) + 1;
  std::vector<ResourceLimit> wanted = {
      {RLIMIT_CPU, {cpu, cpu + 1}},  // SIGXCPU first, SIGKILL one second later
      {RLIMIT_FSIZE, {kFileSizeLimit, kFileSizeLimit}},
      {RLIMIT_CORE, {0, 0}},
      {RLIMIT_NPROC, {kProcessLimit, kProcessLimit}},
  };
  if (!kBuiltWithAddressSanitizer) {  // ASan reserves terabytes of address space
    wanted.push_back({RLIMIT_AS, {kAddressSpaceLimit, kAddressSpaceLimit}});
  }
  for (ResourceLimit& limit : wanted) {
    rlimit current{};
    if (::getrlimit(limit.resource, &current) != 0) throw_errno("getrlimit");
    if (current.rlim_max != RLIM_INFINITY) {
      limit.value.rlim_max = std::min(limit.value.rlim_max, current.rlim_max);
      limit.value.rlim_cur = std::min(limit.value.rlim_cur, current.rlim_max);
    }
  }
  return wanted;
}


void close_descriptors_from(int first, int max_fd) noexcept {
#ifdef SYS_close_range
  if (::syscall(SYS_close_range, static_cast<unsigned>(first), ~0U, 0U) == 0) return;
#endif
  for (int fd = first; fd < max_fd; ++fd) ::close(fd);
}

[[noreturn]] void report_and_exit(int report_fd, ChildFailure::Step step) noexcept {
  const ChildFailure failure{step, errno};
  [[maybe_unused]] const ssize_t ignored = ::write(report_fd, &failure, sizeof failure);
  ::_exit(127);
}

}  // namespace

ExecPlan make_exec_plan(const std::vector<std::string>& argv, const std::string& directory,
                        const Limits& limits) {
  ExecPlan plan;
  plan.argv_storage = argv;
  plan.argv_storage.at(0) = fs::absolute(argv.at(0)).string();  // the child changes directory
  for (char** variable = environ; *variable != nullptr; ++variable) {
    if (!starts_with(*variable, "TMPDIR=")) plan.env_storage.emplace_back(*variable);
  }
  plan.env_storage.push_back("TMPDIR=" + directory);
  for (std::string& arg : plan.argv_storage) plan.argv.push_back(arg.data());
  plan.argv.push_back(nullptr);
  for (std::string& variable : plan.env_storage) plan.envp.push_back(variable.data());
  plan.envp.push_back(nullptr);
  plan.directory = directory;
  plan.limits = resource_limits(limits);
  if (limits.run_as) {
    plan.drop_privileges = true;
    plan.uid = limits.run_as->uid;
    plan.gid = limits.run_as->gid;
  }
  rlimit files{};
  if (::getrlimit(RLIMIT_NOFILE, &files) == 0 && files.rlim_cur != RLIM_INFINITY) {
    plan.max_fd = static_cast<int>(std::min<rlim_t>(files.rlim_cur, 1 << 20));
  }
  return plan;
}
[[noreturn]] void exec_in_sandbox(const ExecPlan& plan) noexcept {
  sigset_t no_signals;
  ::sigemptyset(&no_signals);
  ::sigprocmask(SIG_SETMASK, &no_signals, nullptr);
  struct sigaction default_action {};
  default_action.sa_handler = SIG_DFL;
  for (int signal = 1; signal < NSIG; ++signal) ::sigaction(signal, &default_action, nullptr);

  if (::setsid() < 0) report_and_exit(plan.report_fd, ChildFailure::new_session);

  // Move the inherited descriptors out of the way of 0..4 first, then place them.
  const int output = ::fcntl(plan.output_fd, F_DUPFD, kFirstFreeFd);
  const int token = ::fcntl(plan.token_fd, F_DUPFD, kFirstFreeFd);
  const int report = ::fcntl(plan.report_fd, F_DUPFD_CLOEXEC, kFirstFreeFd);
  if (output < 0 || token < 0 || report < 0)
    report_and_exit(plan.report_fd, ChildFailure::redirection);
  const int null = ::open("/dev/null", O_RDONLY);
  if (null < 0 || ::dup2(null, STDIN_FILENO) < 0 || ::dup2(output, STDOUT_FILENO) < 0 ||
      ::dup2(output, STDERR_FILENO) < 0 || ::dup2(token, kTokenFd) < 0 ||
      ::dup2(report, kReportFd) < 0 || ::fcntl(kReportFd, F_SETFD, FD_CLOEXEC) < 0) {
    report_and_exit(report, ChildFailure::redirection);
  }
  close_descriptors_from(kFirstFreeFd, plan.max_fd);

  if (::chdir(plan.directory.c_str()) != 0)
    report_and_exit(kReportFd, ChildFailure::change_directory);
  for (const ResourceLimit& limit : plan.limits) {
    if (::setrlimit(limit.resource, &limit.value) != 0) {  // RLIMIT_AS on macOS, for one: run without
      constexpr char kNotice[] = "fmbd-grade: notice: a resource limit is not available here; the test runs without it\n";
      [[maybe_unused]] const ssize_t ignored = ::write(STDERR_FILENO, kNotice, sizeof kNotice - 1);
    }
  }
  if (plan.drop_privileges &&
      (::setgroups(0, nullptr) != 0 || ::setgid(plan.gid) != 0 || ::setuid(plan.uid) != 0 || ::setuid(0) == 0))
    report_and_exit(kReportFd, ChildFailure::identity);
  ::execve(plan.argv[0], plan.argv.data(), plan.envp.data());
  report_and_exit(kReportFd, ChildFailure::exec);
}

std::string describe(const ChildFailure& failure, const std::string& program) {
  const std::string reason = std::strerror(failure.error);
  switch (failure.step) {
    case ChildFailure::new_session:
      return "cannot start a new session: " + reason;
    case ChildFailure::redirection:
      return "cannot set up the descriptors: " + reason;
    case ChildFailure::change_directory:
      return "cannot enter the temporary directory: " + reason;
    case ChildFailure::resource_limit:
      return "cannot set resource limits: " + reason;
    case ChildFailure::identity:
      return "cannot switch to the unprivileged user: " + reason;
    case ChildFailure::exec:
      return "cannot execute " + program + ": " + reason;
  }
  return "cannot start " + program;
}

}  // namespace fmbd::grade
