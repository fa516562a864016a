#include "verdict.hpp"

#include <algorithm>
#include <optional>

#include <signal.h>

#include <vector>

#include "grading_protocol.hpp"
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

// The driver runs each test with Catch's compact reporter, which puts a failed assertion on one
// line, never wrapped (the console reporter wraps long messages, and no heuristic can tell
// afterwards where it broke a line: "6.232e+" / "09"). Its forms, the same in Catch2 v2 and v3:
//   FILE:LINE: failed: EXPR for: EXPANSION with 2 messages: 'hint: ...' and 'x: got ...'
//   FILE:LINE: failed: unexpected exception with message: 'M1'; expression was: EXPR with 1 message: 'M2'
//   FILE:LINE: failed: fatal error condition with message: 'M1' with 1 message: 'SIGSEGV - ...'
//   FILE:LINE: failed: explicitly with 1 message: 'M1'
// The messages are the test's INFO and CAPTURE context in order, then the text of the exception
// or signal, if any. A message that itself contains "' and '" would be split there.
struct FailedLine {
  enum class Kind { expression, exception, fatal, other } kind = Kind::other;
  std::string where;       // FILE:LINE
  std::string expression;  // "EXPR with expansion: EXPANSION", for a failed expression
  bool has_expression = false;
  std::vector<std::string> messages;
};

constexpr std::string_view kFailed = ": failed: ";

// The quoted messages from `at` (a quote) on, as listed above.
std::vector<std::string> quoted_messages(std::string_view text, std::size_t at) {
  std::vector<std::string> messages;
  while (at < text.size() && text[at] == '\'') {
    const std::size_t begin = at + 1;
    const std::size_t and_next = text.find("' and '", begin);
    const std::size_t expression_was = text.find("'; expression was: ", begin);
    std::size_t with_more = text.find("' with ", begin);
    while (with_more != std::string_view::npos &&
           !(with_more + 7 < text.size() && text[with_more + 7] >= '1' && text[with_more + 7] <= '9'))
      with_more = text.find("' with ", with_more + 1);
    const std::size_t last = text.size() - 1;
    const std::size_t end = std::min({and_next, expression_was, with_more, last});
    if (end < begin || text[end] != '\'') {  // a message with a line break: its first line
      messages.emplace_back(text.substr(begin));
      break;
    }
    messages.emplace_back(text.substr(begin, end - begin));
    if (end == and_next) {
      at = end + 6;  // the next quote
    } else if (end == last) {
      break;
    } else {  // "; expression was: EXPR with N messages: '" or " with N messages: '"
      const std::size_t marker = text.find(" message", end);
      const std::size_t quote = marker == std::string_view::npos ? marker : text.find(": '", marker);
      if (quote == std::string_view::npos) break;
      at = quote + 2;
    }
  }
  return messages;
}

std::optional<FailedLine> parse_failed_line(std::string_view line) {
  const std::size_t failed = line.find(kFailed);
  if (failed == std::string_view::npos) return std::nullopt;
  FailedLine out;
  out.where = std::string(line.substr(0, failed));
  const std::string_view rest = line.substr(failed + kFailed.size());
  std::size_t first_quote = std::string_view::npos;
  if (starts_with(rest, "unexpected exception with message: '")) {
    out.kind = FailedLine::Kind::exception;
    first_quote = rest.find('\'');
  } else if (starts_with(rest, "fatal error condition with message: '")) {
    out.kind = FailedLine::Kind::fatal;
    first_quote = rest.find('\'');
  } else if (starts_with(rest, "explicitly")) {
    const std::size_t quote = rest.find(": '");
    if (quote != std::string_view::npos) first_quote = quote + 2;
  } else {
    out.kind = FailedLine::Kind::expression;
    out.has_expression = true;
    std::size_t messages = std::string_view::npos;
    for (std::size_t with = rest.find(" with "); with != std::string_view::npos; with = rest.find(" with ", with + 1)) {
      const std::size_t quote = rest.find(": '", with);
      if (with + 6 < rest.size() && rest[with + 6] >= '1' && rest[with + 6] <= '9' && quote != std::string_view::npos &&
          rest.substr(with, quote - with).find(" message") != std::string_view::npos) {
        messages = with;
        first_quote = quote + 2;
        break;
      }
    }
    std::string_view expression = rest.substr(0, messages);
    const std::size_t expansion = expression.find(" for: ");
    out.expression = expansion == std::string_view::npos
                         ? std::string(expression)
                         : std::string(expression.substr(0, expansion)) + " with expansion: " +
                               std::string(expression.substr(expansion + 6));
  }
  if (out.kind == FailedLine::Kind::exception || out.kind == FailedLine::Kind::fatal)
    out.has_expression = rest.find("'; expression was: ") != std::string_view::npos;
  if (first_quote != std::string_view::npos) out.messages = quoted_messages(rest, first_quote);
  return out;
}

std::vector<FailedLine> failed_lines(const std::vector<std::string_view>& lines) {
  std::vector<FailedLine> out;
  for (const std::string_view line : lines) {
    if (std::optional<FailedLine> failed = parse_failed_line(line)) out.push_back(std::move(*failed));
  }
  return out;
}

std::string join(const std::vector<std::string>& parts, std::string_view separator) {
  std::string out;
  for (const std::string& part : parts) {
    if (!out.empty()) out += separator;
    out += part;
  }
  return out;
}

// One failed assertion in a line: the test's hint first, then an exception's message, then the
// context logged before it; the expression and its expansion where no message was logged.
std::string summarise(FailedLine failed) {
  std::vector<std::string>& messages = failed.messages;
  if (failed.kind == FailedLine::Kind::exception && !messages.empty()) {
    messages.back() = "unexpected exception: " + messages.back();
    std::rotate(messages.begin(), messages.end() - 1, messages.end());
  }
  const auto hint = std::find_if(messages.begin(), messages.end(),
                                 [](const std::string& m) { return starts_with(m, "hint:"); });
  std::rotate(messages.begin(), hint, messages.end());
  if (!messages.empty()) return join(messages, "; ");
  return failed.expression;
}

// A part of a reason split where it may be cut: the head names what is wrong and is kept whole
// (a hint: all of it; a compared quantity: its label up to ": "; a captured one: its name up to
// " := "; a failed expression: the expression), the tail is the values that follow it.
struct ReasonPart {
  std::string_view head;
  std::string_view tail;
};

constexpr std::size_t kLongestLabel = 100;  // a label that names a quantity, before its ": "
constexpr std::size_t kFirstValues = 80;    // the values of the first quantity keep at least this much

ReasonPart split_part(std::string_view part) {
  if (part.find("hint:") != std::string_view::npos) return {part, {}};
  for (const std::string_view marker :
       {std::string_view(" with expansion: "), std::string_view(" := "), std::string_view(": ")}) {
    const std::size_t at = part.find(marker);
    if (at != std::string_view::npos && at <= kLongestLabel)
      return {part.substr(0, at + marker.size()), part.substr(at + marker.size())};
  }
  if (part.size() <= kLongestLabel) return {part, {}};
  std::size_t cut = kLongestLabel;
  while (cut > 0 && (static_cast<unsigned char>(part[cut]) & 0xC0) == 0x80) --cut;
  return {part.substr(0, cut), part.substr(cut)};
}

// `text` as one line of at most kMaxReasonLength bytes where it fits; where it does not, the
// heads of its "; "-separated parts stay whole (up to kMaxNamedLength in all) and the tails share
// what is left in their order, each cut with "...", and the line ends with kWholeMessagePointer.
Verdict fitted_reason(std::string_view text) {
  const std::string line = single_line(text);
  if (line.size() <= kMaxReasonLength) return {false, line, false};
  std::vector<ReasonPart> parts;
  for (std::size_t start = 0; start <= line.size();) {
    std::size_t end = line.find("; ", start);
    if (end == std::string::npos) end = line.size();
    parts.push_back(split_part(std::string_view(line).substr(start, end - start)));
    start = end + 2;
  }
  constexpr std::string_view kEllipsis = "...";
  std::size_t fixed = kWholeMessagePointer.size() + 2 * (parts.size() - 1);
  for (const ReasonPart& part : parts) fixed += part.head.size() + (part.tail.empty() ? 0 : kEllipsis.size());
  // The tails share the rest in their order: the values of the first quantity (after the hint)
  // before the context logged after it; the first keeps kFirstValues bytes at least.
  std::size_t left = kMaxReasonLength > fixed ? kMaxReasonLength - fixed : 0;
  std::vector<std::size_t> budget(parts.size(), 0);
  bool first = true;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (parts[i].tail.empty()) continue;
    budget[i] = std::min(parts[i].tail.size(), first ? std::max(left, kFirstValues) : left);
    left -= std::min(left, budget[i]);
    first = false;
  }
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (i > 0) out += "; ";
    out += parts[i].head;
    if (parts[i].tail.size() <= budget[i] + kEllipsis.size()) {
      out += parts[i].tail;
    } else if (!parts[i].tail.empty()) {
      out += shorten(parts[i].tail, budget[i] + kEllipsis.size());
    }
  }
  return {false, shorten(out, kMaxNamedLength) + std::string(kWholeMessagePointer), true};
}

Verdict failed(std::string_view text) { return fitted_reason(text); }

constexpr std::string_view kTimeLimitLine = protocol::kTimeLimitPrefix;

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

std::string fitted_line(std::string_view text) { return fitted_reason(text).reason; }

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

  const std::vector<FailedLine> failed = failed_lines(lines);
  std::string detail;
  for (const FailedLine& f : failed) {  // a message of an assertion, or a line of another program
    for (const std::string& m : f.messages)
      if (detail.empty() && contains_ignoring_case(m, "not implemented yet")) detail = m;
  }
  if (detail.empty()) {
    detail = first_line([](std::string_view line) {
      return contains_ignoring_case(line, "not implemented yet") && line.find(kFailed) == std::string_view::npos;
    });
  }
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
  for (const FailedLine& f : failed) {  // the exception that ended the test case
    if (detail.empty() && f.kind == FailedLine::Kind::exception && !f.has_expression) detail = summarise(f);
  }
  if (detail.empty()) {
    detail = first_line(
        [](std::string_view line) { return starts_with(line, "No test cases matched"); });
  }
  if (detail.empty() && !failed.empty()) detail = summarise(failed.front());
  return detail;
}

namespace {

// Where Catch last was when a fatal signal came: "FILE:LINE" of its "fatal error condition" line
// (the last check reached, or the test case), from its "autograder/" on (else without the build's
// "../"); "" when there is none.
std::string fatal_location(std::string_view output) {
  for (const FailedLine& f : failed_lines(split_lines(output))) {
    if (f.kind != FailedLine::Kind::fatal) continue;
    std::string_view where = f.where;
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
    return failed("timed out after " + format_number(timeout_seconds) + " s -- " + line);
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
    if (!detail.empty()) return failed(detail);
  }
  return failed(explain_failure(outcome, timeout_seconds));
}

}  // namespace fmbd::grade
