#include "verdict.hpp"

#include <algorithm>

#include <signal.h>

#include <vector>

#include "text.hpp"

namespace fmbd::grade {
namespace {

struct SignalDescription {
  int number;
  const char* name;
  const char* meaning;
};

constexpr SignalDescription kSignals[] = {
    {SIGABRT, "SIGABRT", "aborted"},
    {SIGSEGV, "SIGSEGV", "segmentation fault"},
    {SIGBUS, "SIGBUS", "bus error"},
    {SIGFPE, "SIGFPE", "arithmetic error, e.g. integer division by zero"},
    {SIGILL, "SIGILL", "illegal instruction"},
    {SIGKILL, "SIGKILL", "killed, perhaps out of memory or over the CPU time limit"},
    {SIGXCPU, "SIGXCPU", "CPU time limit exceeded"},
    {SIGXFSZ, "SIGXFSZ", "file size limit exceeded"},
    {SIGTERM, "SIGTERM", "terminated"},
    {SIGPIPE, "SIGPIPE", "broken pipe"},
    {SIGTRAP, "SIGTRAP", "trace or breakpoint trap"},
    {SIGSYS, "SIGSYS", "bad system call"},
    {SIGALRM, "SIGALRM", "alarm clock"},
    {SIGHUP, "SIGHUP", "hangup"},
    {SIGINT, "SIGINT", "interrupted"},
    {SIGQUIT, "SIGQUIT", "quit"},
    {SIGUSR1, "SIGUSR1", "user signal 1"},
    {SIGUSR2, "SIGUSR2", "user signal 2"},
};

const SignalDescription* find_signal(int number) {
  for (const SignalDescription& signal : kSignals) {
    if (signal.number == number) return &signal;
  }
  return nullptr;
}

std::string describe_signal(int number) {
  if (number == SIGABRT) return "aborted (SIGABRT)";
  if (const SignalDescription* signal = find_signal(number)) {
    return std::string("killed by signal ") + signal->name + " (" + signal->meaning + ")";
  }
  return "killed by signal " + std::to_string(number);
}

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  while (!text.empty()) {
    const std::size_t newline = text.find('\n');
    lines.push_back(text.substr(0, newline));
    if (newline == std::string_view::npos) break;
    text.remove_prefix(newline + 1);
  }
  return lines;
}

// Catch wraps a message longer than its lines onto more lines of the same indentation, breaking
// at a space (which it drops) or after punctuation. A line was wrapped if the next line's first
// word would not have fitted after it. The line width is CATCH_CONFIG_CONSOLE_WIDTH - 1: 119 under
// Catch2 v2 (catch_main.cpp sets 120), but fixed when a Catch2 v3 library is built (80 by
// default). Catch draws its separators ("----", "====") across the whole width, so the output
// itself tells the width.
constexpr std::size_t kDefaultCatchLineWidth = 119;

std::size_t catch_line_width(const std::vector<std::string_view>& lines) {
  for (const std::string_view line : lines) {
    const char c = line.empty() ? ' ' : line.front();
    if ((c == '-' || c == '=') && line.size() >= 40 && line.find_first_not_of(c) == std::string_view::npos) {
      return line.size();
    }
  }
  return kDefaultCatchLineWidth;
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Appends `next`, the continuation of a wrapped line, to `line`: with the space that Catch
// dropped, except inside a number ("0." + "25") or next to a bracket.
void append_continuation(std::string& line, std::string_view next) {
  if (line.empty() || next.empty()) {
    line += next;
    return;
  }
  const char last = line.back(), first = next.front();
  const bool inside_number =
      (last == '.' || last == ',' || last == 'e' || last == '-') && is_digit(first) && line.size() >= 2 &&
      is_digit(line[line.size() - 2]);
  const bool bracket = last == '(' || last == '[' || last == '{' || first == ')' || first == ']' || first == '}';
  if (!inside_number && !bracket) line += ' ';
  line += next;
}

// The lines of a Catch section (indented by two or more spaces), wrapped lines joined again.
class SectionLines {
 public:
  explicit SectionLines(std::size_t width) : width_(width) {}
  void add(std::string_view raw) {
    const std::string_view text = trim(raw);
    const std::size_t first_word = std::min(text.find(' '), text.size());
    if (!lines_.empty() && previous_length_ + 1 + first_word > width_) {
      append_continuation(lines_.back(), text);
    } else {
      lines_.emplace_back(text);
    }
    previous_length_ = raw.size();
  }
  std::vector<std::string>& lines() { return lines_; }

 private:
  std::size_t width_;
  std::vector<std::string> lines_;
  std::size_t previous_length_ = 0;
};

std::string join(const std::vector<std::string>& parts, std::string_view separator) {
  std::string out;
  for (const std::string& part : parts) {
    if (!out.empty()) out += separator;
    out += part;
  }
  return out;
}

// Summarises a Catch failure block, which looks like
//   path/file.cpp:12: FAILED:
//     CHECK( a == b )
//   with expansion:
//     1 == 2
//   with messages:
//     hint: ...
// Section headings start in column 0, their contents are indented; a blank line ends it.
std::string summarise_failed_block(const std::vector<std::string_view>& lines, std::size_t first) {
  const std::size_t width = catch_line_width(lines);
  SectionLines expression_lines(width), expansion_lines(width), message_lines(width);
  SectionLines* section = &expression_lines;
  bool exception = false;
  for (std::size_t i = first; i < lines.size() && !trim(lines[i]).empty(); ++i) {
    const std::string_view line = lines[i];
    if (line[0] != ' ') {
      if (line.find("expansion") != std::string_view::npos) {
        section = &expansion_lines;
      } else if (line.find("message") != std::string_view::npos ||
                 line.find("fatal error condition") != std::string_view::npos) {
        section = &message_lines;
        exception = line.find("unexpected exception") != std::string_view::npos;
      } else {
        section = nullptr;
      }
    } else if (section != nullptr) {
      section->add(line);
    }
  }
  std::vector<std::string>& messages = message_lines.lines();
  // An unexpected exception's message comes last, after the context logged before it; the
  // test's hint at the likely mistake goes before that context too.
  if (exception && !messages.empty()) {
    messages.back() = "unexpected exception: " + messages.back();
    std::rotate(messages.begin(), messages.end() - 1, messages.end());
  }
  const auto hint = std::find_if(messages.begin(), messages.end(),
                                 [](const std::string& m) { return starts_with(m, "hint:"); });
  std::rotate(messages.begin(), hint, messages.end());
  if (!messages.empty()) return join(messages, "; ");
  std::string summary = join(expression_lines.lines(), " ");
  if (!expansion_lines.lines().empty()) summary += " with expansion: " + join(expansion_lines.lines(), " ");
  return summary;
}

std::string one_line(std::string_view text) { return shorten(single_line(text), kMaxReasonLength); }

constexpr std::string_view kTimeLimitLine = "fmbd-time-limit: ";

}  // namespace

bool stopped_by_time_limit(const Outcome& outcome) {
  return outcome.ending == Ending::exited && outcome.status == 124 &&
         outcome.output.find(kTimeLimitLine) != std::string::npos;
}

std::string describe_ending(const Outcome& outcome, double timeout_seconds) {
  switch (outcome.ending) {
    case Ending::exited:
      return "exited with status " + std::to_string(outcome.status);
    case Ending::killed_by_signal:
      return describe_signal(outcome.status);
    case Ending::timed_out:
      return "timed out after " + format_number(timeout_seconds) + " s";
    case Ending::could_not_start:
      return outcome.error;
  }
  return "ended in an unknown way";
}

std::string failure_detail(std::string_view output) {
  const std::vector<std::string_view> lines = split_lines(output);
  const auto first_line = [&lines](auto matches) -> std::string {
    for (const std::string_view line : lines) {
      if (matches(line)) return std::string(trim(line));
    }
    return "";
  };
  const auto contains = [](std::string_view line, std::string_view fragment) {
    return line.find(fragment) != std::string_view::npos;
  };

  std::string detail = first_line(
      [](std::string_view line) { return contains_ignoring_case(line, "not implemented yet"); });
  if (detail.empty()) {  // UndefinedBehaviorSanitizer
    detail = first_line([&](std::string_view line) { return contains(line, ": runtime error: "); });
  }
  if (detail.empty()) {  // AddressSanitizer, LeakSanitizer, ...
    detail = first_line([&](std::string_view line) {
      return starts_with(line, "SUMMARY: ") && contains(line, "Sanitizer");
    });
    if (!detail.empty()) detail.erase(0, std::string_view("SUMMARY: ").size());
  }
  if (detail.empty()) {  // assert()
    detail = first_line([&](std::string_view line) { return contains(line, ": Assertion `"); });
  }
  for (std::size_t i = 0; detail.empty() && i + 1 < lines.size(); ++i) {
    if (trim(lines[i]) == "due to unexpected exception with message:") {
      SectionLines message(catch_line_width(lines));
      for (std::size_t k = i + 1; k < lines.size() && !trim(lines[k]).empty(); ++k) message.add(lines[k]);
      detail = "unexpected exception: " + join(message.lines(), "; ");
    }
  }
  if (detail.empty()) {
    detail = first_line(
        [](std::string_view line) { return starts_with(line, "No test cases matched"); });
  }
  for (std::size_t i = 0; detail.empty() && i < lines.size(); ++i) {
    const std::string_view line = trim(lines[i]);
    if (line.size() >= 7 && line.substr(line.size() - 7) == "FAILED:") {
      detail = summarise_failed_block(lines, i + 1);
    }
  }
  return detail;
}

namespace {

// Where Catch last was when a fatal signal came: "FILE:LINE" of its "FILE:LINE: FAILED:" line
// followed by "due to a fatal error condition:" (the last check reached, or the test case), from
// its "autograder/" on (else without the build's "../"); "" when there is none.
std::string fatal_location(std::string_view output) {
  const std::vector<std::string_view> lines = split_lines(output);
  for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
    const std::size_t failed = lines[i].rfind(": FAILED:");
    if (failed == std::string_view::npos || trim(lines[i + 1]) != "due to a fatal error condition:") continue;
    std::string_view where = lines[i].substr(0, failed);
    const std::size_t course = where.find("autograder/");  // the course's own path, not the build's
    if (course != std::string_view::npos) where.remove_prefix(course);
    while (starts_with(where, "../")) where.remove_prefix(3);
    return std::string(where);
  }
  return "";
}

// The parts of a "; "-joined detail that do not mention `fragment`.
std::string without_parts_mentioning(const std::string& detail, std::string_view fragment) {
  std::string kept;
  for (std::size_t start = 0; start <= detail.size();) {
    std::size_t end = detail.find("; ", start);
    if (end == std::string::npos) end = detail.size();
    const std::string part = detail.substr(start, end - start);
    if (!part.empty() && part.find(fragment) == std::string::npos) kept += (kept.empty() ? "" : "; ") + part;
    start = end + 2;
  }
  return kept;
}

}  // namespace

std::string explain_failure(const Outcome& outcome, double timeout_seconds) {
  const std::string ending = describe_ending(outcome, timeout_seconds);
  if (outcome.ending != Ending::exited && outcome.ending != Ending::killed_by_signal) return ending;
  std::string detail = failure_detail(outcome.output);
  if (outcome.ending == Ending::killed_by_signal) {
    // Catch's own report of a fatal signal repeats the ending; what it adds is where the test
    // was and the messages logged before the crash.
    const SignalDescription* signal = find_signal(outcome.status);
    if (signal != nullptr) detail = without_parts_mentioning(detail, signal->name);
    const std::string where = fatal_location(outcome.output);
    if (!where.empty()) detail = "last reached " + where + (detail.empty() ? "" : "; " + detail);
  }
  return detail.empty() ? ending : ending + " -- " + detail;
}

Verdict judge(const Outcome& outcome, double timeout_seconds) {
  if (stopped_by_time_limit(outcome)) {  // "timed out after 30 s -- the test case "..." ran longer ..."
    const std::size_t at = outcome.output.rfind(kTimeLimitLine) + kTimeLimitLine.size();
    const std::string line = outcome.output.substr(at, outcome.output.find('\n', at) - at);
    return {false, one_line("timed out after " + format_number(timeout_seconds) + " s -- " + line)};
  }
  if (outcome.ending == Ending::exited && outcome.status == 0) {
    switch (outcome.token) {
      case TokenSeen::matching:
        return {true, ""};
      case TokenSeen::wrong:
        return {false, "exited with status 0 but printed a wrong completion token"};
      case TokenSeen::none:
        return {
            false,
            "exited with status 0 but without the completion token (exit() before the checks?)"};
    }
  }
  if (outcome.ending == Ending::exited && outcome.status == 1) {
    // Status 1 is how a Catch run reports failed checks: the detail says it all.
    const std::string detail = failure_detail(outcome.output);
    if (!detail.empty()) return {false, one_line(detail)};
  }
  return {false, one_line(explain_failure(outcome, timeout_seconds))};
}

}  // namespace fmbd::grade
