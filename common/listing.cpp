#include "listing.hpp"

#include <charconv>
#include <cmath>
#include <locale>
#include <sstream>

#include "text.hpp"

namespace fmbd::grade {
namespace {

std::string ascii_lowercase(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return out;
}

// "12" -> 12; nothing for anything that is not a plain decimal number.
std::optional<int> parse_int(std::string_view digits) {
  int value = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || error != std::errc() || end != digits.data() + digits.size() || value < 0) {
    return std::nullopt;
  }
  return value;
}

// "m01" -> 1 for prefix 'm'; nothing when the tag is not the prefix followed by digits.
std::optional<int> numbered_tag(std::string_view tag, char prefix) {
  if (tag.size() < 2 || tag[0] != prefix) return std::nullopt;
  return parse_int(tag.substr(1));
}

// "t3" -> task 3 of the code, "p2" -> task 2 of the inputs: a kind letter of a task id
// (protocol::kTaskKinds), lower-cased, and its number.
std::optional<Task> task_tag(std::string_view tag) {
  if (tag.empty() || tag[0] < 'a' || tag[0] > 'z') return std::nullopt;
  const char kind = static_cast<char>(tag[0] - 'a' + 'A');
  if (!protocol::is_task_kind(kind)) return std::nullopt;
  const std::optional<int> number = numbered_tag(tag, tag[0]);
  return number ? std::optional<Task>(Task{kind, *number}) : std::nullopt;
}

// A stream in the classic locale, not std::from_chars: libc++ (macOS, clang) has no
// floating-point from_chars before version 17.
std::optional<double> parse_points(std::string_view text) {
  if (text.empty() || text.find_first_of(" \t\n") != std::string_view::npos) return std::nullopt;
  std::istringstream in{std::string(text)};
  in.imbue(std::locale::classic());
  double value = 0;
  in >> value;
  if (in.fail() || in.peek() != std::char_traits<char>::eof() || !std::isfinite(value) || value < 0) {
    return std::nullopt;
  }
  return value;
}

}  // namespace

ParsedList parse_test_list(std::string_view text, const std::string& executable) {
  ParsedList parsed;
  const auto fail = [&parsed](const std::string& reason) {
    parsed.tests.clear();
    parsed.error = reason;
    return parsed;
  };
  std::string_view rest = text;
  for (std::size_t number = 1; !rest.empty(); ++number) {
    const std::size_t newline = rest.find('\n');
    std::string_view line = rest.substr(0, newline);
    rest.remove_prefix(newline == std::string_view::npos ? rest.size() : newline + 1);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.empty()) continue;

    const std::size_t tab = line.rfind('\t');  // tags contain no tab; names might
    const auto malformed = [&](const std::string& why) {
      return fail("test program printed a malformed test list: line " + std::to_string(number) +
                  ": " + why + ": \"" + shorten(single_line(line), 80) + "\"");
    };
    if (tab == std::string_view::npos || tab == 0) return malformed("expected name<TAB>tags");
    TestCase test;
    test.executable = executable;
    test.name = std::string(line.substr(0, tab));
    if (const auto error = apply_tags(line.substr(tab + 1), test)) return malformed(*error);
    parsed.tests.push_back(std::move(test));
  }
  return parsed;
}

std::optional<std::string> apply_tags(std::string_view tags, TestCase& test) {
  while (!tags.empty()) {
    const std::size_t close = tags.find(']');
    if (tags[0] != '[' || close == std::string_view::npos) {
      return "malformed tag list \"" + std::string(tags) + "\"";
    }
    const std::string tag = ascii_lowercase(tags.substr(1, close - 1));
    tags.remove_prefix(close + 1);

    constexpr std::string_view kPoints = "points=";
    if (tag == "hidden") {
      test.hidden = true;
    } else if (const auto module = numbered_tag(tag, 'm')) {
      test.module = module;
    } else if (const auto task = task_tag(tag)) {
      test.task = task;
    } else if (starts_with(tag, kPoints)) {
      const auto points = parse_points(std::string_view(tag).substr(kPoints.size()));
      if (!points) return "bad points tag [" + tag + "]";
      test.points = *points;
    }
  }
  return std::nullopt;
}

std::string module_label(const std::optional<int>& module) {
  return module ? protocol::format_module_id(*module) : "other";
}

std::string task_label(const std::optional<Task>& task) {
  return task ? task->kind + std::to_string(task->number) : "-";
}

}  // namespace fmbd::grade
