#include "catalog.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <locale>
#include <sstream>

#include "text.hpp"
#include "verdict.hpp"

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

std::string file_name(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

std::vector<std::string> listing_command(const TestProgram& program) {
  return {program.lister, "--fmbd-list"};
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
    } else if (const auto task = numbered_tag(tag, 't')) {
      test.task = Task{'T', *task};
    } else if (const auto problem = numbered_tag(tag, 'p')) {
      test.task = Task{'P', *problem};
    } else if (starts_with(tag, kPoints)) {
      const auto points = parse_points(std::string_view(tag).substr(kPoints.size()));
      if (!points) return "bad points tag [" + tag + "]";
      test.points = *points;
    }
  }
  return std::nullopt;
}

Listing parse_listing(const TestProgram& program, const Outcome& outcome, double timeout_seconds) {
  Listing listing;
  const auto fail = [&listing](const std::string& reason) {
    listing.tests.clear();
    listing.error = reason;
    return listing;
  };
  if (outcome.ending != Ending::exited || outcome.status != 0) {
    return fail("test program failed before any test ran: " +
                explain_failure(outcome, timeout_seconds));
  }
  if (outcome.truncated) return fail("test program printed a test list that is too long");

  std::string_view rest = outcome.output;
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
    test.executable = program.executable;
    test.name = std::string(line.substr(0, tab));
    if (const auto error = apply_tags(line.substr(tab + 1), test)) return malformed(*error);
    listing.tests.push_back(std::move(test));
  }
  if (listing.tests.empty()) {
    listing.ran_and_listed_none = true;
    listing.error = "test program " + file_name(program.lister) + " lists no tests";
  }
  return listing;
}

std::vector<std::string> test_command(const TestCase& test, double time_limit_seconds) {
  // Without "--warn NoTests", Catch v2 exits 0 when the spec matches no test at all. The compact
  // reporter writes each failed check on one line, unwrapped (verdict.cpp reads it).
  return {test.executable, "--fmbd-token-fd", "3", "--fmbd-time-limit", format_number(time_limit_seconds),
          "--reporter", "compact", "--use-colour", "no", "--warn", "NoTests", catch_test_spec(test.name)};
}

std::string catch_test_spec(std::string_view name) {
  constexpr std::string_view kSpecial = "\\,[]*~\"";
  std::string spec = "\"";
  for (const char c : name) {
    if (kSpecial.find(c) != std::string_view::npos) spec += '\\';
    spec += c;
  }
  spec += '"';
  return spec;
}

std::string module_label(const std::optional<int>& module) {
  if (!module) return "other";
  char label[16];
  std::snprintf(label, sizeof label, "M%02d", *module);
  return label;
}

std::string task_label(const std::optional<Task>& task) {
  return task ? task->kind + std::to_string(task->number) : "-";
}

}  // namespace fmbd::grade
