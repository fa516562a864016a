// Project tests of the tutorial problems (problems/, moduleNN_*/problems/): the seed is the
// documented hash on every platform; two students get different numbers and one student the same
// numbers however the name is spaced; a correct answers file scores full, through the grade
// function and through the programs' token protocol; each named mistake gets its feedback; a
// malformed line costs only its own problem; a forged identity in the file gains nothing
// (problems_oracles.test.cpp: each engine answer agrees with an independent closed form;
// problems_worked.test.cpp: no worked solution holds a code identifier).
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "fmbd/forward_dynamics.hpp"
#include "fmbd/model.hpp"
#include "fmbd/reactions.hpp"
#include "grading.hpp"
#include "modules.hpp"
#include "problems.hpp"
#include "problems_support.hpp"

using namespace fmbd::problems;
using namespace fmbd::problems::testing;

TEST_CASE("the seed is FNV-1a 64 of the normalised identity, the parameters a splitmix64 stream", "[problems]") {
  CHECK(normalise_identity("  Ada \t  LOVELACE \n") == "ada lovelace");
  // FNV-1a 64's published test vectors.
  CHECK(fnv1a64("") == 0xcbf29ce484222325ULL);
  CHECK(fnv1a64("a") == 0xaf63dc4c8601ec8cULL);
  // Worked by hand from the documentation (problems/problems.hpp): these pin the algorithm.
  const unsigned long long seed = variant_seed("  Ada   LOVELACE ", "M01P2");
  CHECK(seed == 0x93aff7aa585f8c0fULL);
  Parameters stream(seed);
  CHECK(stream.next() == 0xf79142744c97204aULL);
  CHECK(stream.next() == 0x29e767011df8d528ULL);
  // M01P2 draws x, y, phi (5 + 5 k), its quadrant and s_x (40 + 10 k) first.
  const Variant v = make_variant(module01_problems().at(1), "Ada Lovelace");
  REQUIRE(v.parameters.size() >= 5);
  CHECK(v.parameters[0] == -0.33);
  CHECK(v.parameters[1] == -0.12);
  CHECK(v.parameters[2] == 30);
  CHECK(v.parameters[3] == 3);
  CHECK(v.parameters[4] == 200);
}

TEST_CASE("two students get different numbers; one student the same however written", "[problems]") {
  for (const Problem& p : all_problems()) {
    INFO(p.id);
    const Variant ada = make_variant(p, "Ada Lovelace");
    CHECK(make_variant(p, "  ada   LOVELACE").parameters == ada.parameters);
    CHECK(make_variant(p, "ADA LOVELACE").statement == ada.statement);
    for (std::size_t k = 1; k < kStudents.size(); ++k) {
      INFO(kStudents[k]);
      CHECK(make_variant(p, kStudents[k]).parameters != ada.parameters);
    }
    CHECK(make_variant(p, "Alan Turing").statement != ada.statement);
  }
}

TEST_CASE("a correct answers file scores full", "[problems]") {
  for (const auto& module : all_modules()) {
    for (const std::string& student : kStudents) {
      const AnswerFile file = read_answers(correct_file(module, student), ids_of(module));
      CHECK(file.notes.empty());
      for (const Problem& p : module) {
        INFO(p.id << " of " << student);
        const Grade g = grade(p, make_variant(p, student).solve(), file);
        CHECK(g.passed);
        CHECK(g.message == "correct");
      }
    }
  }
  // Other units of the same dimension, and a bare angle in rad where units are optional.
  const Problem position = module01_problems().at(1);
  const Solution s = make_variant(position, "Alan Turing").solve();
  CHECK(grade_value(position, s, Quantity::vector({s.answer.values[0] * 1000, s.answer.values[1] * 1000}), "mm").passed);
  CHECK(grade_value(position, s, Quantity::vector({s.answer.values[0] * 100, s.answer.values[1] * 100}), "cm").passed);
  const Problem newton = module02_problems().at(0);
  const Solution n = make_variant(newton, "Alan Turing").solve();
  CHECK(grade(newton, n, read_answers("M02P1 = " + format_quantity(n.answer, 12) + "\n", {"M02P1"})).passed);
  CHECK(grade_value(newton, n, Quantity::number(n.answer.values[0] / kDeg), "deg").passed);
  const Problem torque = module03_problems().at(2);
  const Solution t = make_variant(torque, "Alan Turing").solve();
  CHECK(grade_value(torque, t, t.answer, "N*m").passed);
  CHECK(grade_value(torque, t, t.answer, "Nm").passed);
  CHECK(grade_value(torque, t, Quantity::number(t.answer.values[0] / 1000), "kN m").passed);  // a prefix: units.hpp
  const Problem drift = module04_problems().at(2);
  const Solution d = make_variant(drift, "Alan Turing").solve();
  CHECK(grade_value(drift, d, Quantity::vector({d.answer.values[0] * 1000, d.answer.values[1] * 1000}), "mm").passed);
  const Problem frequency = module05_problems().at(1);
  const Solution f = make_variant(frequency, "Alan Turing").solve();
  CHECK(grade_value(frequency, f, f.answer, "Hz").passed);
  CHECK(grade_value(frequency, f, Quantity::number(f.answer.values[0] * 2 * kPi), "rad/s").passed == false);
  const Problem mode = module06_problems().at(0);
  const Solution r = make_variant(mode, "Alan Turing").solve();
  CHECK(grade_value(mode, r, Quantity::vector({r.answer.values[0] * 1000, r.answer.values[1] * 1000}), "mm").passed);
  const Problem constraint = module06_problems().at(1);
  const Solution c = make_variant(constraint, "Alan Turing").solve();
  CHECK(grade_value(constraint, c, c.answer, "m").passed == false);  // entries of mixed units: no unit
  const Problem inertia = module06_problems().at(2);
  const Solution j = make_variant(inertia, "Alan Turing").solve();
  CHECK(grade_value(inertia, j, j.answer, "kg*m^2").passed);
  const Problem forces = module07_problems().at(2);
  const Solution q = make_variant(forces, "Alan Turing").solve();
  CHECK(grade_value(forces, q, q.answer, "Nm").passed);
  CHECK(grade_value(forces, q, q.answer, "N").passed == false);
}

TEST_CASE("the programs grade through the token protocol", "[problems]") {
  const std::vector<Problem> m01 = module01_problems();
  const std::string path = write_file("m01-correct.txt", correct_file(m01, "Emmy Noether"));
  for (const Problem& p : m01) {
    INFO(p.id);
    const Run r = run(m01, {"--answers", path, "\"" + p.name() + "\""}, "Emmy Noether", path, "tok-" + p.id);
    CHECK(r.status == 0);
    CHECK(r.out.find("fmbd-completion-token: tok-" + p.id + "\n") != std::string::npos);
  }
  const Run list = run(m01, {"--fmbd-list"}, "", path);
  CHECK(list.status == 0);
  CHECK(list.out.find("M01P1: degrees of freedom of a driven chain\t[M01][P1][points=2]\n") != std::string::npos);
  // A wrong answer: the feedback in Catch's compact form, no token.
  const Run wrong = run(m01, {"M01P2"}, "Alan Turing", path, "tok");
  CHECK(wrong.status == 1);
  CHECK(wrong.out.find(": failed: M01P2 with 1 message: 'hint: ") != std::string::npos);
  CHECK(wrong.out.find("fmbd-completion-token") == std::string::npos);
  // No identity: every problem fails and says how to grade.
  const Run anonymous = run(m01, {"M01P1"}, "", path, "tok");
  CHECK(anonymous.status == 1);
  CHECK(anonymous.out.find("grade with --student NAME") != std::string::npos);

  // The built programs themselves, as the grade driver runs them: fd 3 holds the token.
  const std::map<std::string, std::vector<Problem>> programs = {
      {FMBD_M01_PROBLEMS, m01},
      {FMBD_M02_PROBLEMS, module02_problems()},
      {FMBD_M03_PROBLEMS, module03_problems()},
      {FMBD_M04_PROBLEMS, module04_problems()},
      {FMBD_M05_PROBLEMS, module05_problems()},
      {FMBD_M06_PROBLEMS, module06_problems()},
      {FMBD_M07_PROBLEMS, module07_problems()},
      {FMBD_M08_PROBLEMS, module08_problems()}};
  const std::string token = write_file("token.txt", "child-token\n");
  for (const auto& [program, problems] : programs) {
    const std::string answers = write_file(problems.front().module_tag() + ".txt", correct_file(problems, "Leonhard Euler"));
    const Problem& p = problems.back();
    const std::string command = "FMBD_STUDENT='leonhard  euler' '" + program + "' --answers " + answers +
                                " --fmbd-token-fd 3 --fmbd-time-limit 10 --use-colour no --warn NoTests \"" + p.name() +
                                "\" 3<" + token;
    INFO(command);
    FILE* pipe = ::popen(command.c_str(), "r");
    REQUIRE(pipe != nullptr);
    std::string out;
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
    const int status = ::pclose(pipe);
    CHECK(status == 0);
    CHECK(out.find("fmbd-completion-token: child-token\n") != std::string::npos);
  }
}

TEST_CASE("each named mistake gets its feedback", "[problems]") {
  std::map<std::string, std::set<std::string>> named;  // problem -> mistakes named at least once
  std::map<std::string, std::set<std::string>> expected;
  for (const Problem& p : all_problems()) {
    for (const std::string& student : kStudents) {
      const Solution s = make_variant(p, student).solve();
      const auto& e = s.answer.values;
      auto scaled = [&](double f) {
        Quantity q = s.answer;
        for (double& x : q.values) x *= f;
        return q;
      };
      // value, unit as written, the words the feedback must contain
      std::vector<std::tuple<Quantity, std::string, std::string>> cases;
      for (const Mistake& m : s.mistakes) cases.emplace_back(m.value, "", m.name);
      cases.emplace_back(scaled(-1), "", "the sign");
      cases.emplace_back(scaled(2), "", "factor of 2");
      cases.emplace_back(scaled(0.5), "", "factor of 2");
      const bool angle = p.unit.rfind("rad", 0) == 0;  // rad, rad/s, rad/s^2: degrees are the likely slip
      if (angle) cases.emplace_back(scaled(1 / kDeg), "", "degrees against radians");
      if (!p.unit.empty() && !angle) cases.emplace_back(scaled(1000), "", "a unit's scale");
      if (p.kind == Kind::matrix) {
        std::vector<double> t;
        for (int c = 0; c < p.cols; ++c)
          for (int r = 0; r < p.rows; ++r) t.push_back(s.answer(r, c));
        cases.emplace_back(Quantity::matrix(p.cols, p.rows, t), "", "the transpose");
      }
      for (const auto& [value, unit, words] : cases) {
        expected[p.id].insert(words);
        if (within(value, s.answer, p.tolerance)) continue;  // this variant has no such mistake
        const Grade g = grade_value(p, s, value, unit);
        INFO(p.id << " of " << student << ": " << words << "; answer " << format_quantity(s.answer) << ", given "
                  << format_quantity(value) << ": " << g.message);
        CHECK_FALSE(g.passed);
        CHECK(g.message.find("likely mistake: ") != std::string::npos);
        if (g.message.find(words) != std::string::npos) named[p.id].insert(words);
      }
      (void)e;
    }
  }
  for (const auto& [id, words] : expected) {
    for (const std::string& w : words) {
      INFO(id << ": \"" << w << "\" was never named for " << kStudents.size() << " students");
      CHECK(named[id].count(w) == 1);
    }
  }
}

TEST_CASE("a malformed line names its number and costs no other answer", "[problems]") {
  const std::vector<Problem> m03 = module03_problems();
  const std::string student = "Sophie Germain";
  std::vector<Solution> s;
  for (const Problem& p : m03) s.push_back(make_variant(p, student).solve());
  const std::string good1 = answer_line(m03[1], s[1].answer);
  const std::string good2 = answer_line(m03[2], s[2].answer);
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"M03P1 [1, 2] N", "an \"=\" after the id"},
      {"M03P1 = [1, 2 N", "expected"},
      {"M03P1 = [1; 2] N", "\"1;\" is not a number"},
      {"M03P1 = [1, 2.3.4] N", "is not a number"},
      {"M03P1 = [1, 2]", "the unit is missing"},
      {"M03P1 = [1, 2] furlongs", "unknown unit"},
      {"M03P1 = [1, 2] m/s", "is a unit of m/s"},
      {"M03P1 = 1.5 N", "is a vector of 2 entries"},
      {"M03P1 = [[1, 2], [3]] N", "the rows of a matrix"},
      {"M03P1 = [nan, 1] N", "is not a number"},
  };
  for (const auto& [line, words] : bad) {
    INFO(line);
    const AnswerFile file = read_answers("# answers\n" + good1 + line + "  # my try\n" + good2, ids_of(m03));
    const Grade g = grade(m03[0], s[0], file);
    CHECK_FALSE(g.passed);
    CHECK(g.line == 3);
    CHECK(g.message.find("line 3: ") == 0);
    CHECK(g.message.find(words) != std::string::npos);
    CHECK(grade(m03[1], s[1], file).passed);
    CHECK(grade(m03[2], s[2], file).passed);
  }
  // Twice the same problem: that problem fails, naming both lines.
  const AnswerFile twice = read_answers(good1 + good1 + good2, ids_of(m03));
  CHECK(grade(m03[1], s[1], twice).message.find("lines 1, 2") != std::string::npos);
  CHECK(grade(m03[2], s[2], twice).passed);
  // The format check of a copy without the reference.
  CHECK(check_format(m03[1], read_answers(good1, ids_of(m03))) == std::nullopt);
}

TEST_CASE("a forged identity or seed in the answers file gains nothing", "[problems]") {
  const std::vector<Problem> m02 = module02_problems();
  const std::string forged = "student = Alan Turing\nseed = 12345\nFMBD_STUDENT=Alan Turing\n" + correct_file(m02, "Alan Turing");
  const std::string path = write_file("forged.txt", forged);
  for (const Problem& p : m02) {
    INFO(p.id);
    const Run as_ada = run(m02, {"--answers", path, p.id}, "Ada Lovelace", path, "tok");
    CHECK(as_ada.status == 1);
    CHECK(as_ada.out.find("fmbd-completion-token") == std::string::npos);
    CHECK(as_ada.out.find("line 1: \"student = Alan Turing\" names no problem") != std::string::npos);
    const Run as_alan = run(m02, {"--answers", path, p.id}, "Alan Turing", path, "tok");
    CHECK(as_alan.status == 0);
  }
  // --student sets the identity of --print, never of a grade.
  const Run print = run(m02, {"--print", "M02P2", "--student", "Alan Turing"}, "", path);
  CHECK(print.out.find(make_variant(m02[1], "Alan Turing").statement) != std::string::npos);
  const Run grade_with_option = run(m02, {"--answers", path, "--student", "Alan Turing", "M02P2"}, "", path, "tok");
  CHECK(grade_with_option.status == 1);
}

TEST_CASE("a copy without the reference checks only the format", "[problems]") {
  const std::vector<Problem> m01 = module01_problems();
  const std::string path = write_file("format-only.txt", "M01P1 = 3\nM01P2 = [1, 2]\n");
  ProgramConfig config;
  config.module_tag = "M01";
  config.answers_path = path;
  config.has_reference = false;
  ::setenv("FMBD_STUDENT", "Ada Lovelace", 1);
  std::ostringstream out;
  std::streambuf* old = std::cout.rdbuf(out.rdbuf());
  std::string a0 = "m01_problems", a1 = "M01P1", a2 = "M01P2", a3 = "--worked";
  char* argv1[] = {a0.data(), a1.data(), nullptr};
  char* argv2[] = {a0.data(), a2.data(), nullptr};
  char* argv3[] = {a0.data(), a3.data(), nullptr};
  const int first = run_program(m01, config, 2, argv1);
  const std::string first_out = out.str();
  out.str("");
  const int second = run_program(m01, config, 2, argv2);
  const std::string second_out = out.str();
  const int worked = run_program(m01, config, 2, argv3);
  std::cout.rdbuf(old);
  ::unsetenv("FMBD_STUDENT");
  CHECK(first == 1);
  CHECK(first_out.find(kFormatOnly) != std::string::npos);
  CHECK(second == 1);
  CHECK(second_out.find("line 2: the unit is missing") != std::string::npos);
  CHECK(worked == 2);
}
