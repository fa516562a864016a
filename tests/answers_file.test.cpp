// Project tests of the answers file as a file (problems/answers_file.cpp, problems/units.cpp): a
// byte-order mark and CRLF line ends are read as plain text; every SI prefix of every unit a
// problem uses converts to SI; a file that is not UTF-8 text (binary data, a NUL byte, Latin-1)
// gets one message naming the file, the line and the column of the first bad byte, which the
// grade driver shows rather than an exit status; an empty file and a file of comments leave every
// problem unanswered; a file of 100 000 lines is graded; and a failure of the program itself is
// reported through the driver's protocol.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "grading.hpp"
#include "problems.hpp"
#include "problems_support.hpp"
#include "verdict.hpp"

using namespace fmbd::problems;
using namespace fmbd::problems::testing;
using namespace std::string_literals;

namespace {

// `text` with CRLF line ends, the last line without one.
std::string with_crlf(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '\n' ? std::string("\r\n") : std::string(1, c);
  if (out.size() >= 2 && out.compare(out.size() - 2, 2, "\r\n") == 0) out.resize(out.size() - 2);
  return out;
}

// What the grade driver makes of a failed run's output: it keeps the first 64 KiB (sandbox.hpp).
std::string driver_verdict(const std::string& output, int status) {
  fmbd::grade::Outcome outcome;
  outcome.ending = fmbd::grade::Ending::exited;
  outcome.status = status;
  outcome.output = output.substr(0, std::size_t{64} * 1024);
  return fmbd::grade::judge(outcome, 30).reason;
}

// `bytes` pseudo-random bytes (every value, NUL and newline among them), the same on every run.
std::string random_bytes(std::size_t bytes) {
  std::string out(bytes, '\0');
  std::uint64_t state = 0x2545F4914F6CDD1DULL;
  for (char& c : out) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    c = static_cast<char>(state >> 56);
  }
  return out;
}

const std::string kFix = "save it as plain UTF-8 text";

}  // namespace

TEST_CASE("a byte-order mark and CRLF line ends are read as plain text", "[problems]") {
  for (const auto& module : all_modules()) {
    const std::string student = "Emmy Noether";
    std::string text = "\xEF\xBB\xBF";
    for (const Problem& p : module) text += answer_line(p, make_variant(p, student).solve().answer);
    const AnswerFile file = read_answers(with_crlf(text), ids_of(module));
    CHECK(file.notes.empty());
    for (const Problem& p : module) {
      INFO(p.id);
      CHECK(grade(p, make_variant(p, student).solve(), file).passed);
    }
  }
  // A mark and no answers: nothing to note.
  CHECK(read_answers("\xEF\xBB\xBF# my answers\r\n", {"M01P1"}).notes.empty());
}

TEST_CASE("every SI prefix of every unit a problem uses converts to SI", "[problems]") {
  std::set<std::string> units;  // one problem per unit is enough, each unit's every prefix
  for (const Problem& p : all_problems()) {
    if (p.unit.empty() || !units.insert(p.unit).second) continue;
    const Solution s = make_variant(p, "Ada Lovelace").solve();
    int prefixed = 0;
    for (const BaseUnit& base : base_units()) {
      if (base.unit.si != p.unit) continue;
      const auto in = [&](double scale) {
        Quantity q = s.answer;
        for (double& x : q.values) x /= scale;
        return q;
      };
      INFO(p.id << " in " << base.symbol);
      CHECK(grade_value(p, s, in(base.unit.scale), base.symbol).passed);  // the unprefixed unit
      if (base.prefixes == Prefixes::none) continue;
      for (const Prefix& prefix : si_prefixes()) {
        if (prefix.symbol == "c" && base.prefixes != Prefixes::all_and_centi) continue;
        const std::string symbol = prefix.symbol + base.symbol;
        INFO(symbol);
        const std::optional<Unit> unit = parse_unit(symbol);
        REQUIRE(unit.has_value());
        CHECK(unit->si == p.unit);
        CHECK(unit->scale == Approx(prefix.factor * base.unit.scale).epsilon(1e-14));
        CHECK(grade_value(p, s, in(prefix.factor * base.unit.scale), symbol).passed);
        ++prefixed;
      }
    }
    INFO(p.unit << " has no unit that takes a prefix");
    CHECK(prefixed >= 9);  // p n µ μ u m k M G
  }
  CHECK(units.size() >= 10);
}

TEST_CASE("units: no prefixed form is itself a unit; a wrong dimension is named", "[problems]") {
  for (const BaseUnit& base : base_units()) {
    for (const Prefix& prefix : si_prefixes()) {
      INFO(prefix.symbol << " + " << base.symbol);
      for (const BaseUnit& other : base_units()) CHECK(prefix.symbol + base.symbol != other.symbol);
      if (base.prefixes == Prefixes::none || (prefix.symbol == "c" && base.prefixes != Prefixes::all_and_centi))
        CHECK_FALSE(parse_unit(prefix.symbol + base.symbol).has_value());
    }
  }
  // The units read before prefixes were: the same factors.
  const std::vector<std::pair<std::string, double>> known = {
      {"mm", 1e-3}, {"cm", 1e-2}, {"kN", 1e3}, {"MPa", 1e6}, {"GPa", 1e9}, {"kg", 1}, {"kg*m^2", 1},
      {"kg m^2", 1}, {"Nm", 1}, {"N*m", 1}, {"N m", 1}, {"deg", kDeg}, {"deg/s", kDeg}, {"Hz", 1}, {"1/s", 1}};
  for (const auto& [text, scale] : known) {
    INFO(text);
    REQUIRE(parse_unit(text).has_value());
    CHECK(parse_unit(text)->scale == Approx(scale).epsilon(1e-15));
  }
  CHECK(parse_unit("rpm")->scale == Approx(2 * kPi / 60));
  CHECK(parse_unit("kN\xC2\xB7m")->scale == 1e3);  // N·m
  CHECK(parse_unit("m")->scale == 1);               // the metre, never a bare milli
  CHECK(parse_unit("ms")->si == "s");               // the millisecond
  CHECK_FALSE(parse_unit("min").has_value());       // no minute, and no milli-inch either
  CHECK_FALSE(parse_unit("KN").has_value());        // kilo is k
  CHECK_FALSE(parse_unit("N km").has_value());      // the prefix goes on the first factor
  // A prefixed unit of another dimension: the problem's own is named.
  const Problem torque = module03_problems().at(2);
  const Solution t = make_variant(torque, "Alan Turing").solve();
  const Grade energy = grade_value(torque, t, t.answer, "kJ");
  CHECK_FALSE(energy.passed);
  CHECK(energy.message.find("\"kJ\" is a unit of J, and " + torque.id + " is in N m") != std::string::npos);
  CHECK(grade_value(torque, t, Quantity::number(t.answer.values[0] * 1e3), "mN m").passed);
  CHECK(grade_value(torque, t, Quantity::number(t.answer.values[0] / 1e3), "kNm").passed);
}

TEST_CASE("a file that is not UTF-8 text gets one message with its line and column", "[problems]") {
  const std::vector<Problem> m01 = module01_problems();
  // text, line, column, words of the message
  const std::vector<std::tuple<std::string, int, int, std::string>> cases = {
      {"M01P1 = 2\nM01P2 = [1, 2] m\0\n"s, 2, 17, "a NUL byte"},
      {"# r\xE9ponse (Latin-1)\nM01P1 = 2\n"s, 1, 4, "the byte 0xE9"},
      {"M01P1 = 2\r\n\xEF\xBB\xBF# \xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80 \xFF\n"s, 2, 8, "the byte 0xFF"},
      {"M01P1 = 2 # \xC0\xAF\n"s, 1, 13, "the byte 0xC0"},  // an overlong '/'
      {"# \xED\xA0\x80\n"s, 1, 3, "the byte 0xED"},          // a surrogate
      {"# \xF4\x90\x80\x80\n"s, 1, 3, "the byte 0xF4"},      // above U+10FFFF
      {"# \x80\n"s, 1, 3, "the byte 0x80"},                  // a lone continuation byte
      {"M01P1 = 2\n# \xE2\x82"s, 2, 3, "the byte 0xE2"},     // cut off at the end
  };
  for (const auto& [text, line, column, words] : cases) {
    INFO(line << ":" << column << " " << words);
    const std::string path = write_file("not-text.txt", text);
    const AnswerFile file = read_answers_file(path, ids_of(m01));
    CHECK(file.notes.empty());
    for (const Problem& p : m01) {
      const Grade g = grade(p, make_variant(p, "Ada Lovelace").solve(), file);
      CHECK_FALSE(g.passed);
      CHECK(g.line == line);
      CHECK(g.message.find(path + " is not plain UTF-8 text: line " + std::to_string(line) + ", column " +
                           std::to_string(column) + ": " + words) == 0);
      CHECK(g.message.find(kFix) != std::string::npos);
    }
  }
  CHECK(read_answers("M01P1 = 2\n\0"s, {"M01P1"}).not_text_line == 2);
  // Valid UTF-8 of every length is text.
  CHECK(read_answers("# \xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80 \xC2\xB5m\n", {"M01P1"}).not_text.empty());
}

TEST_CASE("3 MB of random bytes: the driver shows the message and not an exit status", "[problems]") {
  const std::vector<Problem> m07 = module07_problems();
  const std::string path = write_file("binary.txt", "M07P1 = [0.1, 0.2] m\n# notes\nxy\xFF" + random_bytes(3 << 20));
  const std::string message = path + " is not plain UTF-8 text: line 3, column 3: the byte 0xFF";
  for (const Problem& p : m07) {
    INFO(p.id);
    const Run r = run(m07, {"--answers", path, p.id}, "Ada Lovelace", path, "tok");
    CHECK(r.status == 1);
    CHECK(r.out.size() < 2048);
    const std::string verdict = driver_verdict(r.out, r.status);
    CHECK(verdict.find("hint: " + message) == 0);
    CHECK(verdict.find(kFix) != std::string::npos);
  }
  const Run check = run(m07, {"--answers", path, "--check"}, "", path);
  CHECK(check.status == 1);
  CHECK(check.out.find(message) != std::string::npos);
  CHECK(check.out.find(message, check.out.find(message) + 1) == std::string::npos);  // once
}

TEST_CASE("an empty file or one of comments answers no problem", "[problems]") {
  for (const auto& module : all_modules()) {
    for (const std::string text : {"", "\n\n", "# nothing yet\n#\n   # indented\n", "\xEF\xBB\xBF# marked\r\n"}) {
      const AnswerFile file = read_answers(text, ids_of(module));
      CHECK(file.notes.empty());
      CHECK(file.not_text.empty());
      for (const Problem& p : module) {
        INFO(p.id << " in \"" << text << "\"");
        const Grade g = grade(p, make_variant(p, "Alan Turing").solve(), file);
        CHECK_FALSE(g.passed);
        CHECK(g.line == 0);
        CHECK(g.message.find("no answer for " + p.id + ": add a line \"" + p.id + " = ") == 0);
      }
    }
  }
}

TEST_CASE("a file of 100 000 lines is graded and its notes kept short", "[problems]") {
  const std::vector<Problem> m03 = module03_problems();
  const std::string student = "Sophie Germain";
  std::string text;
  int lines = 0;
  while (lines < 100000 - static_cast<int>(m03.size())) {
    text += lines % 10 == 0 ? "scratch = " + std::to_string(lines) + " N m, a line of working\n"
                            : lines % 2 ? "# a comment\n" : "\n";
    ++lines;
  }
  text += correct_file(m03, student).substr(std::string("# answers of " + student + "\n\n").size());
  const std::string path = write_file("long.txt", text);
  const AnswerFile file = read_answers_file(path, ids_of(m03));
  CHECK(file.notes.size() == 10000);
  CHECK(grade(m03.back(), make_variant(m03.back(), student).solve(), file).line == 100000);
  for (const Problem& p : m03) {
    INFO(p.id);
    const Run r = run(m03, {"--answers", path, p.id}, student, path, "tok");
    CHECK(r.status == 0);
    CHECK(r.out.find("fmbd-completion-token: tok\n") != std::string::npos);
    CHECK(r.out.size() < 4096);  // far below the 64 KiB the driver keeps
    CHECK(r.out.find("9990 more lines name no problem") != std::string::npos);
  }
}

TEST_CASE("a failure of the program itself is reported through the protocol", "[problems]") {
  Problem broken;
  broken.id = "M09P1";
  broken.title = "a problem whose engine fails";
  broken.unit = "m";
  broken.make = [](Parameters&) -> Variant { throw std::runtime_error("the engine ran out of iterations"); };
  const std::string path = write_file("broken.txt", "M09P1 = 1 m\n");
  const Run r = run({broken}, {"--answers", path, broken.name()}, "Ada Lovelace", path, "tok");
  CHECK(r.status == 1);
  const std::string verdict = driver_verdict(r.out, r.status);
  CHECK(verdict.find("hint: the program of the problems failed: the engine ran out of iterations") == 0);
  CHECK(verdict.find("exited with status") == std::string::npos);
}
