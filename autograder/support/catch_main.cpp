// The one Catch main of the workbook, compiled once per build.
//
// Protocol with the grade driver (autograder/driver):
//   --fmbd-list           print one line per test case, "name<TAB>[tag][tag]...", then exit 0
//   --fmbd-token-fd N     a completion token (one line) waits on file descriptor N; once the
//                         Catch session has returned with every check passed, the program
//                         prints "fmbd-completion-token: <token>" as its last line and ends
//                         at once with status 0.
//   --fmbd-time-limit S   each test case may run S seconds (0: no limit); beyond that the
//                         program prints "fmbd-time-limit: ..." naming the test case and the
//                         last check it reached and exits with
//                         status 124 (kTimeLimitStatus). The driver passes a little less than its
//                         own timeout; run by hand, the limit is FMBD_TIME_LIMIT or 120 s.
// Its listener also tells the hint gate (hint_gate.hpp) the task of each test case it starts.
// Everything else goes to Catch unchanged (fmbd_cli reads the command line; only drain_token(),
// which runs before any constructor, reads argv itself). This file and grading.hpp are the only
// places that know the Catch version: v2 (one header) or v3 (a library whose own main is not linked),
// after FMBD_CATCH2_MAJOR, which the top-level CMakeLists.txt sets from the Catch2 it finds.
//
// The token is kept from the code under test (issue 17):
//   * drain_token() runs from .preinit_array, before every constructor of the program (those
//     of the static libraries with the student's code included): it reads the token from fd N
//     into a page of its own, closes fd N and makes the page inaccessible (PROT_NONE). A static
//     initialiser, a function-local static or a test finds no descriptor to read, and a search
//     of memory faults on the page. The token is never copied anywhere else.
//   * main() opens the page only after a run in which every check passed, writes the token
//     line with write(2) and calls _exit(), so no atexit handler or destructor runs after it.
//   * A failed run returns normally without the token; an atexit handler that turns its
//     status into 0 does not make it pass.
// Functions of the C library called here could be replaced by a program that defines its own
// `read` or `write`; the source check (tools/vet.cpp) refuses such definitions in exercise files.
#if FMBD_CATCH2_MAJOR >= 3
#include <catch2/catch_session.hpp>
#include <catch2/catch_test_case_info.hpp>
#include <catch2/interfaces/catch_interfaces_registry_hub.hpp>
#include <catch2/interfaces/catch_interfaces_testcase.hpp>
#include <catch2/reporters/catch_reporter_event_listener.hpp>
#include <catch2/reporters/catch_reporter_registrars.hpp>
#else
#define CATCH_CONFIG_RUNNER
#define CATCH_CONFIG_CONSOLE_WIDTH 120
#include <catch2/catch.hpp>
#endif

#include <signal.h>
#include <sys/mman.h>
#include <sys/time.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#endif

#include <cerrno>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "cli.hpp"               // common/: the command line (fmbd_cli)
#include "grading_protocol.hpp"  // common/: the protocol's options and lines, inline
#include "hint_gate.hpp"         // the running test's task, for the messages' formulas

namespace {

using fmbd::protocol::kTokenFdOption;
constexpr std::size_t kMaxTokenBytes = 256;

// Constant-initialised, so it is valid before any constructor runs.
struct TokenPage {
  char* data = nullptr;     // a page of its own, PROT_NONE until print_token_and_exit()
  std::size_t size = 0;     // of the mapping
  std::size_t length = 0;   // of the token
  bool requested = false;   // --fmbd-token-fd was given
};
TokenPage token_page;

// "12" -> 12; -1 for anything else.
int parse_fd(const char* text) {
  int fd = 0;
  if (*text == '\0') return -1;
  for (; *text != '\0'; ++text) {
    if (*text < '0' || *text > '9' || fd > 100000) return -1;
    fd = fd * 10 + (*text - '0');
  }
  return fd;
}

// Runs before any constructor (glibc passes argc, argv and envp to .preinit_array functions).
void drain_token(int argc, char** argv, char** /*envp*/) {
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], kTokenFdOption) != 0) continue;
    token_page.requested = true;
    const int fd = parse_fd(argv[i + 1]);
    if (fd < 0) return;
    const long page_size = ::sysconf(_SC_PAGESIZE);
    const std::size_t size = page_size > 0 ? static_cast<std::size_t>(page_size) : 4096;
    void* page = ::mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (page == MAP_FAILED) {
      ::close(fd);
      return;
    }
    char* data = static_cast<char*>(page);
    std::size_t length = 0;
    while (length < kMaxTokenBytes) {
      const ssize_t got = ::read(fd, data + length, 1);
      if (got < 0 && errno == EINTR) continue;
      if (got != 1 || data[length] == '\n') break;
      ++length;
    }
    data[length] = '\0';
    ::close(fd);
    if (::mprotect(page, size, PROT_NONE) != 0) {
      std::memset(page, 0, size);  // an unsealed token is no token
      length = 0;
    }
    token_page.data = data;
    token_page.size = size;
    token_page.length = length;
    return;
  }
}

#if defined(__APPLE__)
// Mach-O has no .preinit_array. dyld passes argc, argv and envp to initialisers as well; this one
// runs among the first of the program's own, but not surely before those of the linked code.
__attribute__((constructor(101))) void fmbd_drain_token(int argc, char** argv, char** envp) {
  drain_token(argc, argv, envp);
}
#else
__attribute__((section(".preinit_array"), used)) void (*const fmbd_drain_token)(int, char**, char**) =
    drain_token;
#endif

bool write_all(const char* data, std::size_t length) {
  while (length > 0) {
    const ssize_t written = ::write(STDOUT_FILENO, data, length);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return false;
    data += written;
    length -= static_cast<std::size_t>(written);
  }
  return true;
}

// After a run in which every check passed: the token line, then the end of the process.
[[noreturn]] void print_token_and_exit() {
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
#if defined(__SANITIZE_ADDRESS__)
  // _exit() skips LeakSanitizer's check at exit: a leak fails the test as it did before.
  if (__lsan_do_recoverable_leak_check() != 0) ::_exit(23);
#endif
  const bool ok = token_page.data != nullptr && token_page.length > 0 &&
                  ::mprotect(token_page.data, token_page.size, PROT_READ) == 0;
  const char* prefix = fmbd::protocol::kCompletionTokenPrefix;
  if (!ok || !write_all("\n", 1) || !write_all(prefix, std::strlen(prefix)) ||
      !write_all(token_page.data, token_page.length) || !write_all("\n", 1)) {
    ::_exit(1);
  }
  ::_exit(0);
}

// The per-test time limit. Everything the signal handler reads is a fixed buffer, written
// between checks by the listener below, so that the handler only calls write() and _exit().
constexpr int kTimeLimitStatus = 124;
constexpr double kTimeLimitByHand = 120;
struct TimeLimit {
  double seconds = 0;
  char seconds_text[32] = {};
  char test[256] = {};
  char check[320] = {};  // "the last check it reached is at FILE:LINE", or empty
};
TimeLimit time_limit;

void copy_text(char* to, std::size_t size, const char* a, const char* b = "", const char* c = "") {
  std::snprintf(to, size, "%s%s%s", a, b, c);
}

// FILE:LINE with FILE from its "autograder/" on (the course's own path), else as given.
void copy_location(const Catch::SourceLineInfo& where) {
  const char* file = std::strstr(where.file, "autograder/");
  char line[32];
  std::snprintf(line, sizeof line, ":%lu", static_cast<unsigned long>(where.line));
  char location[288];
  copy_text(location, sizeof location, file != nullptr ? file : where.file, line);
  copy_text(time_limit.check, sizeof time_limit.check, "the last check it reached is at ", location);
}

void write_text(const char* text) {
  for (std::size_t length = std::strlen(text); length > 0;) {
    const ssize_t written = ::write(STDOUT_FILENO, text, length);
    if (written <= 0) return;
    text += written;
    length -= static_cast<std::size_t>(written);
  }
}

extern "C" void on_time_limit(int) {
  write_text("\n");
  write_text(fmbd::protocol::kTimeLimitPrefix.data());  // a literal: NUL-terminated
  write_text("the test case \"");
  write_text(time_limit.test);
  write_text("\" ran longer than ");
  write_text(time_limit.seconds_text);
  write_text(" s (a loop that does not end?), ");
  write_text(time_limit.check[0] != '\0' ? time_limit.check : "before its first check");
  write_text("\n");
  ::_exit(kTimeLimitStatus);
}

void arm_time_limit(double seconds) {
  itimerval timer{};
  timer.it_value.tv_sec = static_cast<time_t>(seconds);
  timer.it_value.tv_usec = static_cast<suseconds_t>((seconds - static_cast<double>(timer.it_value.tv_sec)) * 1e6);
  ::setitimer(ITIMER_REAL, &timer, nullptr);
}

#if FMBD_CATCH2_MAJOR >= 3
using ListenerBase = Catch::EventListenerBase;
#else
using ListenerBase = Catch::TestEventListenerBase;
#endif

class TimeLimitListener : public ListenerBase {
 public:
  using ListenerBase::ListenerBase;
  void testCaseStarting(const Catch::TestCaseInfo& info) override {
    fmbd::testing::set_running_task(fmbd::testing::task_of_tags(info.tagsAsString()));
    copy_text(time_limit.test, sizeof time_limit.test, info.name.c_str());
    time_limit.check[0] = '\0';
    if (time_limit.seconds > 0) arm_time_limit(time_limit.seconds);
  }
  // Catch2 v2 calls this once the check's expression is evaluated, v3 before: either way the
  // last check the test reached.
  void assertionStarting(const Catch::AssertionInfo& info) override { copy_location(info.lineInfo); }
  void testCaseEnded(const Catch::TestCaseStats& stats) override {
    arm_time_limit(0);
    ListenerBase::testCaseEnded(stats);
  }
};
CATCH_REGISTER_LISTENER(TimeLimitListener)

// "--fmbd-time-limit" or FMBD_TIME_LIMIT: seconds, or nothing when `text` is not a number >= 0.
bool parse_seconds(const char* text, double& seconds) {
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(value >= 0) || value > 86400) return false;
  seconds = value;
  return true;
}

int list_tests() {
#if FMBD_CATCH2_MAJOR >= 3
  for (const Catch::TestCaseInfo* test : Catch::getRegistryHub().getTestCaseRegistry().getAllInfos()) {
    std::cout << fmbd::protocol::listing_line(test->name, test->tagsAsString());
  }
#else
  for (const Catch::TestCase& test : Catch::getRegistryHub().getTestCaseRegistry().getAllTests()) {
    std::cout << fmbd::protocol::listing_line(test.name, test.tagsAsString());
  }
#endif
  return 0;
}

// The Catch main's own options (grading_protocol.hpp) and, for v3, the v2 options the driver
// passes and v3 spells otherwise; everything else goes to Catch (rest), in its order.
fmbd::cli::Command command_line() {
  using fmbd::cli::Kind;
  using fmbd::protocol::kListOption;
  using fmbd::protocol::kTimeLimitOption;
  fmbd::cli::Command command = fmbd::cli::program("", {{kListOption, Kind::flag, "", "", ""},
                                                       {kTimeLimitOption, Kind::value, "S", "seconds", ""},
                                                       {kTokenFdOption, Kind::value, "N", "a file descriptor", ""}},
                                                  "", 0, "");
#if FMBD_CATCH2_MAJOR >= 3
  command.options.push_back({"--use-colour", Kind::value, "yes|no|auto", "a value", ""});
  command.options.push_back({"--warn", Kind::value, "WHAT", "a value", ""});
#endif
  command.passes_unknown = true;
  return command;
}

// Catch's command line: the program's name, the options translated for v3, then the rest.
std::vector<std::string> catch_arguments(const char* program, const fmbd::cli::Parsed& parsed) {
  std::vector<std::string> args{program};
#if FMBD_CATCH2_MAJOR >= 3
  if (parsed.has("--use-colour")) {  // v2's option; v3 calls it --colour-mode
    const std::string colour = parsed.value("--use-colour");
    args.insert(args.end(), {"--colour-mode", colour == "no" ? "none" : colour == "yes" ? "ansi" : "default"});
  }
  for (const std::string& warning : parsed.all("--warn")) {
    // v2's warning for a spec that matches nothing; v3 fails a run without tests anyway.
    args.insert(args.end(), {"--warn", warning == "NoTests" ? "UnmatchedTestSpec" : warning});
  }
#endif
  args.insert(args.end(), parsed.rest.begin(), parsed.rest.end());
  return args;
}

}  // namespace

int main(int argc, char* argv[]) {
  time_limit.seconds = kTimeLimitByHand;
  if (const char* by_hand = std::getenv("FMBD_TIME_LIMIT"); by_hand != nullptr && !parse_seconds(by_hand, time_limit.seconds)) {
    std::cerr << "FMBD_TIME_LIMIT: give seconds (0: no limit), not '" << by_hand << "'\n";
    return 2;
  }
  fmbd::cli::Parsed parsed;
  try {
    parsed = fmbd::cli::parse(command_line(), std::vector<std::string>(argv + (argc > 0 ? 1 : 0), argv + argc));
  } catch (const fmbd::cli::UsageError& error) {
    std::cerr << error.what() << "\n";
    return 2;
  }
  // --fmbd-token-fd was drained by drain_token() before any constructor.
  if (parsed.has(fmbd::protocol::kTimeLimitOption)) {
    const std::string seconds = parsed.value(fmbd::protocol::kTimeLimitOption);
    if (!parse_seconds(seconds.c_str(), time_limit.seconds)) {
      std::cerr << "--fmbd-time-limit: give seconds (0: no limit), not '" << seconds << "'\n";
      return 2;
    }
  }
  if (parsed.has(fmbd::protocol::kListOption)) return list_tests();
  if (time_limit.seconds > 0) {
    std::snprintf(time_limit.seconds_text, sizeof time_limit.seconds_text, "%g", time_limit.seconds);
    struct sigaction action {};
    action.sa_handler = on_time_limit;
    ::sigaction(SIGALRM, &action, nullptr);
  }

  std::vector<std::string> args = catch_arguments(argv[0], parsed);
  std::vector<char*> pointers;
  for (std::string& arg : args) pointers.push_back(arg.data());
  const int failed = Catch::Session().run(static_cast<int>(pointers.size()), pointers.data());
  if (failed == 0 && token_page.requested) print_token_and_exit();
  return failed == 0 ? 0 : 1;
}
