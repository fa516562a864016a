// Project tests of the tutorial problems (problems/, moduleNN_*/problems/): the seed is the
// documented hash on every platform; two students get different numbers and one student the same
// numbers however the name is spaced; a correct answers file scores full, through the grade
// function and through the programs' token protocol; each named mistake gets its feedback; a
// malformed line costs only its own problem; a forged identity in the file gains nothing; each
// engine answer agrees with an independent closed form, on ordinary and extreme variants; and no
// worked solution, as each module's program prints it, holds a code identifier.
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

// ---- the oracles: closed forms of each answer from the drawn parameters -------------------

namespace {

using Oracle = std::function<Quantity(const std::vector<double>&)>;

// Modules 1 and 2: kinematics, constraints and Newton-Raphson.
void add_kinematics_oracles(std::map<std::string, Oracle>& o) {
  o["M01P1"] = [](const std::vector<double>& p) {  // links, slider, drivers: Gruebler
    const int links = static_cast<int>(p[0]), slider = static_cast<int>(p[1]), drivers = static_cast<int>(p[2]);
    return Quantity::number(3 * (links + slider) - 2 * links - 4 * slider - drivers);
  };
  o["M01P2"] = [](const std::vector<double>& p) {  // x, y, phi, quadrant, s_x, s_y [mm]
    const double phi = (p[2] + 90 * p[3]) * kDeg, sx = p[4] / 1000, sy = p[5] / 1000;
    return Quantity::vector({p[0] + std::cos(phi) * sx - std::sin(phi) * sy, p[1] + std::sin(phi) * sx + std::cos(phi) * sy});
  };
  o["M01P3"] = [](const std::vector<double>& p) {  // -s_x, s_y, phi, quadrant
    const double sx = -p[0], sy = p[1], phi = (p[2] + 90 * p[3]) * kDeg;
    const double a = -std::cos(phi) * sy - std::sin(phi) * sx, b = -std::sin(phi) * sy + std::cos(phi) * sx;
    return Quantity::matrix(2, 3, {-1, 0, -a, 0, -1, -b});
  };
  o["M02P1"] = [](const std::vector<double>& p) {  // L, phi0, direction, distance: scalar Newton on L cos phi = x_B
    const double L = p[0], phi0 = p[1] * kDeg, target = (p[1] + (p[2] ? 1 : -1) * p[3]) * kDeg;
    const double x_B = std::round(L * std::cos(target) * 1000) / 1000;
    return Quantity::number(phi0 + (L * std::cos(phi0) - x_B) / (L * std::sin(phi0)));
  };
  o["M02P2"] = [](const std::vector<double>& p) {  // r, l, A, half turn, rpm
    const double r = p[0], l = p[1], A = (p[2] + 180 * p[3]) * kDeg, omega = p[4] * 2 * kPi / 60;
    const double s = std::sin(A), c = std::cos(A);
    return Quantity::number(omega * (-r * s - r * r * s * c / std::sqrt(l * l - r * r * s * s)));
  };
  o["M02P3"] = [](const std::vector<double>& p) {
    const double pi = (p[0] + 90 * p[1]) * kDeg, pj = (p[2] + 90 * p[3]) * kDeg;
    const double wi = (p[4] ? 1 : -1) * p[5], wj = (p[6] ? 1 : -1) * p[7];
    const double six = p[8], siy = p[9], sjx = -p[10], sjy = p[11];
    auto As = [](double phi, double x, double y) {
      return std::vector<double>{std::cos(phi) * x - std::sin(phi) * y, std::sin(phi) * x + std::cos(phi) * y};
    };
    const auto a = As(pi, six, siy), b = As(pj, sjx, sjy);
    return Quantity::vector({a[0] * wi * wi - b[0] * wj * wj, a[1] * wi * wi - b[1] * wj * wj});
  };
}

// Modules 3 and 4: Lagrange's equations and integration.
void add_dynamics_oracles(std::map<std::string, Oracle>& o) {
  o["M03P1"] = [](const std::vector<double>& p) {  // m, L, phi, quadrant, sign, omega: F = m a_G - m g
    const double m = p[0], L = p[1], phi = (p[2] + 90 * p[3]) * kDeg, w = (p[4] ? 1 : -1) * p[5], g = 9.81;
    return Quantity::vector({-m * L / 2 * w * w * std::cos(phi), -m * L / 2 * w * w * std::sin(phi) + m * g});
  };
  o["M03P2"] = [](const std::vector<double>& p) {  // r, l, A, half turn, m1, m2, m3
    const double r = p[0], l = p[1], A = (p[2] + 180 * p[3]) * kDeg, m1 = p[4], m2 = p[5], m3 = p[6];
    const double beta = std::asin(-r * std::sin(A) / l);
    const double beta_dot = -r * std::cos(A) / (l * std::cos(beta));
    const double vx = -r * std::sin(A) - l / 2 * std::sin(beta) * beta_dot;
    const double vy = r * std::cos(A) + l / 2 * std::cos(beta) * beta_dot;
    const double x_dot = -r * std::sin(A) - l * std::sin(beta) * beta_dot;
    return Quantity::number(m1 * r * r / 3 + m2 * (vx * vx + vy * vy) + m2 * l * l / 12 * beta_dot * beta_dot +
                            m3 * x_dot * x_dot);
  };
  o["M03P3"] = [](const std::vector<double>& p) {  // m, L, phi, quadrant, sign, omega, sign, alpha
    const double m = p[0], L = p[1], phi = (p[2] + 90 * p[3]) * kDeg, alpha = (p[6] ? 1 : -1) * p[7], g = 9.81;
    return Quantity::number(m * L * L / 3 * alpha + m * g * L / 2 * std::cos(phi));
  };
  // m, w, H, y_1, H - y_2, m_b, w - d. Statics of the door: the moment of the loads about the hinge
  // axis, g (m w/2 + m_b d), is taken by the couple of the horizontal forces, -F_2x = F_1x = that / h;
  // the vertical forces have only their sum W fixed, and the least F_1y^2 + F_2y^2 is W/2 each.
  o["M03P4"] = [](const std::vector<double>& p) {
    const double m = p[0], w = p[1], h = p[2] - p[4] - p[3], mb = p[5], d = w - p[6], g = 9.81;
    const double F = g * (m * w / 2 + mb * d) / h, W = (m + mb) * g;
    return Quantity::vector({F, W / 2, -F, W / 2});
  };
  o["M04P1"] = [](const std::vector<double>& p) {  // m, L, phi, quadrant, sign, omega: J_O phi_ddot = moment of m g
    const double L = p[1], phi = (p[2] + 90 * p[3]) * kDeg, w = (p[4] ? 1 : -1) * p[5], g = 9.81;
    const double alpha = -3 * g * std::cos(phi) / (2 * L), c = std::cos(phi), s = std::sin(phi);
    return Quantity::vector({L / 2 * (-alpha * s - w * w * c), L / 2 * (alpha * c - w * w * s), alpha});
  };
  o["M04P2"] = [](const std::vector<double>& p) {  // m, k, c, x0 [mm], v0, h [ms]: y1 = (sum_{j<=4} (hA)^j / j!) y0
    const double m = p[0], k = p[1], c = p[2], h = p[5] / 1000;
    // z <- y0, then z <- hA z / j, accumulated: the RK4 polynomial of the linear y' = A y.
    double x = p[3] / 1000, v = p[4], sx = x, sv = v;
    for (int j = 1; j <= 4; ++j) {
      const double nx = h * v / j, nv = h * (-k * x - c * v) / (m * j);
      x = nx, v = nv, sx += x, sv += v;
    }
    return Quantity::number(sv);
  };
  o["M04P3"] = [](const std::vector<double>& p) {  // m, L, phi, quadrant, sign, omega, h [ms]
    const double L = p[1], phi = (p[2] + 90 * p[3]) * kDeg, w = (p[4] ? 1 : -1) * p[5], hw = p[6] / 1000 * w;
    return Quantity::vector({L / 2 * (std::cos(phi + hw) - std::cos(phi) + hw * std::sin(phi)),
                             L / 2 * (std::sin(phi + hw) - std::sin(phi) - hw * std::cos(phi))});
  };
}

// Modules 5 and 6: finite elements, modes and reduction.
void add_fe_oracles(std::map<std::string, Oracle>& o) {
  o["M05P1"] = [](const std::vector<double>& p) {  // material, a [mm], L, alpha, quadrant: 6 E I / L^2 (-s, c)
    const double E = p[0] ? 70e9 : 210e9, a = p[1] / 1000, L = p[2], alpha = (p[3] + 90 * p[4]) * kDeg;
    const double k = 6 * E * (a * a * a * a / 12) / (L * L);
    return Quantity::vector({-k * std::sin(alpha), k * std::cos(alpha)});
  };
  o["M05P2"] = [](const std::vector<double>& p) {  // material, a [mm], L: 24 E I / L_e^3 against 312 m_e / 420
    const double E = p[0] ? 70e9 : 210e9, rho = p[0] ? 2700 : 7850, a = p[1] / 1000, Le = p[2] / 2;
    const double K = 24 * E * (a * a * a * a / 12) / (Le * Le * Le), M = 312 * rho * a * a * Le / 420;
    return Quantity::number(std::sqrt(K / M) / (2 * kPi));
  };
  o["M05P3"] = [](const std::vector<double>& p) {  // material, a [mm], L, alpha, quadrant
    const double rho = p[0] ? 2700 : 7850, a = p[1] / 1000, m = rho * a * a * p[2], alpha = (p[3] + 90 * p[4]) * kDeg;
    const double c = std::cos(alpha), s = std::sin(alpha);
    return Quantity::vector({m / 3 * c * c + 156 * m / 420 * s * s, (m / 3 - 156 * m / 420) * c * s});
  };
  // The L-shaped frame (material, a [mm], L1, L2): leg masses in proportion to L1 and L2, the
  // centroid of the legs' centres; the rotation about it, and J by the parallel-axis theorem.
  o["M06P1"] = [](const std::vector<double>& p) {
    const double L1 = p[2], L2 = p[3];
    const double cx = (L1 * L1 / 2 + L2 * L1) / (L1 + L2), cy = (L2 * L2 / 2) / (L1 + L2);
    return Quantity::vector({-(L2 - cy), L1 - cx});
  };
  o["M06P2"] = [](const std::vector<double>& p) {  // short, long, long first: the cubic 3 xi^2 - 2 xi^3
    const double L = p[0] + p[1], xi = (p[2] ? p[1] : p[0]) / L;
    return Quantity::vector({3 * xi * xi - 2 * xi * xi * xi, 6 * (xi - xi * xi) / L});
  };
  o["M06P3"] = [](const std::vector<double>& p) {
    const double rho = p[0] ? 2700 : 7850, A = (p[1] / 1000) * (p[1] / 1000), L1 = p[2], L2 = p[3];
    const double m1 = rho * A * L1, m2 = rho * A * L2;
    const double cx = (m1 * L1 / 2 + m2 * L1) / (m1 + m2), cy = m2 * L2 / 2 / (m1 + m2);
    const double d1 = (L1 / 2 - cx) * (L1 / 2 - cx) + cy * cy, d2 = (L1 - cx) * (L1 - cx) + (L2 / 2 - cy) * (L2 / 2 - cy);
    return Quantity::number(m1 * (L1 * L1 / 12 + d1) + m2 * (L2 * L2 / 12 + d2));
  };
}

// Modules 7 and 8: the intuitive and the full floating frame of reference.
void add_flexible_oracles(std::map<std::string, Oracle>& o) {
  // The spinning dumbbell (m, d, k, Omega): one mass on its circle, m Omega^2 (d + u) = 2k u.
  o["M07P1"] = [](const std::vector<double>& p) {
    const double m = p[0], d = p[1], k = p[2], w2 = p[3] * p[3];
    return Quantity::vector({0.0, m * w2 * d / (2 * k - m * w2)});
  };
  o["M07P2"] = [](const std::vector<double>& p) {  // ..., q_f, sign, |q_f_dot|: each mass at radius d + q_f
    const double m = p[0], d = p[1], w2 = p[3] * p[3], q = p[4], qd = (p[5] ? 1 : -1) * p[6];
    return Quantity::vector({m * (w2 * d * d + qd * qd), m * (w2 * (d + q) * (d + q) + qd * qd)});
  };
  // theta, quadrant, x_bar, y_bar, phi_x, phi_y, q_f (sign, size), F_x (sign, size), F_y (sign, size), k, m:
  // the virtual work of F on the node's velocity per theta_dot and per q_f_dot.
  o["M07P3"] = [](const std::vector<double>& p) {
    const double th = (p[0] + 90 * p[1]) * kDeg, c = std::cos(th), s = std::sin(th);
    const double q = (p[6] ? 1 : -1) * p[7], Fx = (p[8] ? 1 : -1) * p[9], Fy = (p[10] ? 1 : -1) * p[11], k = p[12];
    const double X = p[2] + p[4] * q, Y = p[3] + p[5] * q;
    const double Q_theta = Fx * (-s * X - c * Y) + Fy * (c * X - s * Y);
    const double Q_f = Fx * (c * p[4] - s * p[5]) + Fy * (s * p[4] + c * p[5]) - k * q;
    return Quantity::vector({Q_theta, Q_f});
  };
  // Two point masses m at (-d, 0), (d, 0) with the shape (-a, b1), (a, b2): (m, d, a, b1, b2, ...).
  o["M08P1"] = [](const std::vector<double>& p) {  // ..., theta, quadrant, omega, q_f
    const double m = p[0], d = p[1], a = p[2], b1 = p[3], b2 = p[4];
    const double th = (p[5] + 90 * p[6]) * kDeg, w2 = p[7] * p[7], q = p[8];
    const double F = w2 * m * q * (b1 + b2);  // the centrifugal force of the moved mass centre, frame y
    return Quantity::vector({-std::sin(th) * F, std::cos(th) * F, 0.0,
                             w2 * m * (2 * a * d + q * (2 * a * a + b1 * b1 + b2 * b2))});
  };
  o["M08P2"] = [](const std::vector<double>& p) {  // ..., q_f
    const double m = p[0], d = p[1], a = p[2], b1 = p[3], b2 = p[4], q = p[5];
    const double x = d + a * q;
    return Quantity::vector({m * (2 * x * x + b1 * b1 * q * q + b2 * b2 * q * q), m * d * (b2 - b1)});
  };
  o["M08P3"] = [](const std::vector<double>& p) {  // ..., omega (sign, size), q_f, q_f_dot (sign, size)
    const double m = p[0], d = p[1], a = p[2], b1 = p[3], b2 = p[4];
    const double w = (p[5] ? 1 : -1) * p[6], q = p[7], qd = (p[8] ? 1 : -1) * p[9];
    return Quantity::number(-2 * w * qd * m * (2 * a * d + q * (2 * a * a + b1 * b1 + b2 * b2)));
  };
  o["M08P4"] = [](const std::vector<double>& p) {  // m, d, k, Omega: as M07P1's true stretch
    const double m = p[0], d = p[1], k = p[2], w2 = p[3] * p[3];
    return Quantity::number(m * w2 * d / (2 * k - m * w2));
  };
  // m, L, r_h, Omega, Omega/omega_1: EI to three digits; the cubic tip-load shape gives
  // int v'^2 = 6/5 v^2/L, so omega^2 = omega_1^2 + (6 (r_h + L)/(5 L) - 1) Omega^2.
  o["M08P5"] = [](const std::vector<double>& p) {
    const double m = p[0], L = p[1], r = p[2], W = p[3];
    const double exact = m * std::pow(W / p[4], 2) * L * L * L / 3;
    const double digits = std::pow(10.0, std::floor(std::log10(exact)) - 2);
    const double EI = std::round(exact / digits) * digits;
    const double w1_2 = 3 * EI / (m * L * L * L);
    return Quantity::vector({std::sqrt(w1_2), std::sqrt(w1_2 + (6 * (r + L) / (5 * L) - 1) * W * W)});
  };
}

// The drawn parameters of each problem, in the order its make() draws them.
std::map<std::string, Oracle> oracles() {
  std::map<std::string, Oracle> o;
  add_kinematics_oracles(o);
  add_dynamics_oracles(o);
  add_fe_oracles(o);
  add_flexible_oracles(o);
  return o;
}

// The ratio that makes a variant extreme, per problem (the grid's far corner is looked for).
std::map<std::string, std::function<double(const std::vector<double>&)>> extremes() {
  std::map<std::string, std::function<double(const std::vector<double>&)>> e;
  e["M01P1"] = [](const std::vector<double>& p) { return p[0] + p[1]; };                    // longest chain
  e["M01P2"] = [](const std::vector<double>& p) { return -std::hypot(p[0], p[1]); };        // centroid near O
  e["M01P3"] = [](const std::vector<double>& p) { return -p[0]; };                          // shortest arm
  e["M02P1"] = [](const std::vector<double>& p) { return p[3] / p[0]; };                    // far guess, short link
  e["M02P2"] = [](const std::vector<double>& p) { return p[0] / p[1]; };                    // r / l near lock
  e["M02P3"] = [](const std::vector<double>& p) { return p[5] / p[7]; };                    // unequal rates
  e["M03P1"] = [](const std::vector<double>& p) { return p[5] * p[5] * p[1] / p[0]; };     // fast, long, light
  e["M03P2"] = [](const std::vector<double>& p) { return p[6] / (p[4] + p[5]) + p[0] / p[1]; };  // heavy slider
  e["M03P3"] = [](const std::vector<double>& p) { return p[7] * p[1]; };                   // fast spin-up
  e["M03P4"] = [](const std::vector<double>& p) { return p[1] / (p[2] - p[3] - p[4]); };  // wide door, close hinges
  e["M04P1"] = [](const std::vector<double>& p) { return p[5] * p[5] * p[1]; };            // fast, long
  e["M04P2"] = [](const std::vector<double>& p) { return std::sqrt(p[1] / p[0]) * p[5]; };  // omega h
  e["M04P3"] = [](const std::vector<double>& p) { return p[5] * p[6]; };                   // h phi_dot
  e["M05P1"] = [](const std::vector<double>& p) { return p[2] / p[1]; };                   // slender
  e["M05P2"] = [](const std::vector<double>& p) { return p[2] / p[1]; };                   // slender, low f_1
  e["M05P3"] = [](const std::vector<double>& p) { return p[1] * p[1] * p[2]; };            // heavy
  e["M06P1"] = [](const std::vector<double>& p) { return p[3] / p[2]; };                   // tall frame
  e["M06P2"] = [](const std::vector<double>& p) { return (p[2] ? p[1] : p[0]) / (p[0] + p[1]); };  // xi_1
  e["M06P3"] = [](const std::vector<double>& p) { return p[1] * p[1] * (p[2] + p[3]); };   // heavy, large
  e["M07P1"] = [](const std::vector<double>& p) { return p[0] * p[3] * p[3] / p[2]; };    // spin against spring
  e["M07P2"] = [](const std::vector<double>& p) { return p[4] / p[1]; };                   // stretch against d
  e["M07P3"] = [](const std::vector<double>& p) { return p[5] * p[7] / p[2]; };            // deformation against x_bar
  e["M08P1"] = [](const std::vector<double>& p) { return p[7] * p[7] * p[8]; };            // fast spin, large q_f
  e["M08P2"] = [](const std::vector<double>& p) { return p[5] * (p[3] + p[4]) / p[1]; };   // large deformation
  e["M08P3"] = [](const std::vector<double>& p) { return p[6] * p[9]; };                   // fast spin and rate
  e["M08P4"] = [](const std::vector<double>& p) { return p[0] * p[3] * p[3] / p[2]; };    // spin against spring
  e["M08P5"] = [](const std::vector<double>& p) { return p[4] * (p[2] + p[1]) / p[1]; };  // fast spin, large hub
  return e;
}

}  // namespace

TEST_CASE("each engine answer agrees with an independent closed form", "[problems]") {
  const auto oracle = oracles();
  const auto extreme = extremes();
  for (const Problem& p : all_problems()) {
    REQUIRE(oracle.count(p.id) == 1);
    // Ada, and the most and least extreme of 300 students.
    std::string lowest = "student 0", highest = "student 0";
    double low = 1e300, high = -1e300;
    for (int k = 0; k < 300; ++k) {
      const std::string name = "student " + std::to_string(k);
      const double x = extreme.at(p.id)(make_variant(p, name).parameters);
      if (x < low) low = x, lowest = name;
      if (x > high) high = x, highest = name;
    }
    for (const std::string& student : {std::string("Ada Lovelace"), lowest, highest}) {
      const Variant v = make_variant(p, student);
      const Quantity engine = v.solve().answer;
      const Quantity closed = oracle.at(p.id)(v.parameters);
      INFO(p.id << " of " << student << ": engine " << format_quantity(engine, 15) << ", closed form "
                << format_quantity(closed, 15));
      CHECK(within(engine, closed, Tolerance(1e-9, 1e-12)));
    }
  }
}

TEST_CASE("M03P4's hinge forces are those of the multipliers module 4's forward dynamics reports", "[problems]") {
  // The door of the statement, built here from the drawn parameters (m, w, H, y_1, H - y_2, m_b,
  // w - d) and released at rest: forward_dynamics (solve_augmented's rank-revealing path) finds
  // q_ddot = 0, one dependent row, and the multipliers of least norm, whose hinge forces are the
  // problem's answer.
  const Problem door = module03_problems().at(3);
  REQUIRE(door.id == "M03P4");
  for (const std::string& student : kStudents) {
    const Variant v = make_variant(door, student);
    const std::vector<double>& p = v.parameters;
    const double m = p[0], w = p[1], H = p[2], y1 = p[3], y2 = p[2] - p[4], mb = p[5], d = w - p[6], g = 9.81;
    fmbd::Model model;
    model.set_gravity(fmbd::Vec2(0, -g));
    const fmbd::BodyId leaf = model.add_body("door", m, m * (w * w + H * H) / 12, fmbd::Vec3(w / 2, H / 2, 0));
    const int lower = model.add_revolute("lower", model.add_point(fmbd::ground, fmbd::Vec2(0, y1), "lower frame"),
                                         model.add_point_at(leaf, fmbd::Vec2(0, y1), "lower leaf"));
    const int upper = model.add_revolute("upper", model.add_point(fmbd::ground, fmbd::Vec2(0, y2), "upper frame"),
                                         model.add_point_at(leaf, fmbd::Vec2(0, y2), "upper leaf"));
    model.add_point_force("bag", model.add_point_at(leaf, fmbd::Vec2(d, 1.0), "handle"), fmbd::Vec2(0, -mb * g));
    const fmbd::VecX q = model.initial_guess();
    const fmbd::Accelerations a = fmbd::forward_dynamics(model, q, fmbd::VecX::Zero(3), 0.0);
    INFO(student);
    CHECK(a.qdd.norm() < 1e-9);
    CHECK(a.rank_deficit == 1);
    const fmbd::Vec2 F1 = fmbd::joint_reaction(model, lower, q, a.lambda).on_j.force;
    const fmbd::Vec2 F2 = fmbd::joint_reaction(model, upper, q, a.lambda).on_j.force;
    const Quantity engine = Quantity::vector({F1.x(), F1.y(), F2.x(), F2.y()});
    const Quantity answer = v.solve().answer;
    INFO("forward dynamics " << format_quantity(engine, 15) << ", M03P4 " << format_quantity(answer, 15));
    CHECK(within(engine, answer, Tolerance(1e-9, 1e-9)));
  }
}

TEST_CASE("the flexible bodies of modules 7 and 8 deform by at most 5 % of their size", "[problems]") {
  // The largest displacement of a mass or node against its distance from the frame's origin, from
  // the drawn parameters (M08P5 asks for small vibrations: no finite deformation).
  std::map<std::string, std::function<double(const std::vector<double>&)>> deformation;
  auto stretch = [](const std::vector<double>& p) {  // m, d, k, Omega: the true stretch over d
    const double w2 = p[0] * p[3] * p[3];
    return w2 / (2 * p[2] - w2);
  };
  deformation["M07P1"] = stretch;
  deformation["M08P4"] = stretch;
  deformation["M07P2"] = [](const std::vector<double>& p) { return p[4] / p[1]; };
  deformation["M07P3"] = [](const std::vector<double>& p) {
    return std::hypot(p[4], p[5]) * p[7] / std::hypot(p[2], p[3]);
  };
  auto dumbbell = [](int q_index) {  // (m, d, a, b1, b2, ...): the mass with the larger shape, b2 > b1
    return [q_index](const std::vector<double>& p) { return std::hypot(p[2], p[4]) * p[q_index] / p[1]; };
  };
  deformation["M08P1"] = dumbbell(8);
  deformation["M08P2"] = dumbbell(5);
  deformation["M08P3"] = dumbbell(7);
  for (const Problem& p : all_problems()) {
    if (deformation.count(p.id) == 0) continue;
    double worst = 0;
    std::string who;
    for (int k = 0; k < 300; ++k) {
      const std::string name = "student " + std::to_string(k);
      const double x = deformation.at(p.id)(make_variant(p, name).parameters);
      if (x > worst) worst = x, who = name;
    }
    INFO(p.id << ": " << who << " deforms the body by " << 100 * worst << " % of its size");
    CHECK(worst <= 0.05);
    CHECK(worst > 0.0);
  }
}

// ---- the worked texts hold mathematics, not code ---------------------------------------------

namespace {

bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// A math symbol: a letter with optional digits (A, f, L1), a Greek letter's name (phi, Omega) or a
// differential of either (dx, dphi).
bool is_math_symbol(const std::string& head) {
  static const std::set<std::string> greek = {
      "alpha", "beta",    "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa", "lambda", "mu",
      "nu",    "xi",      "omicron", "pi",  "rho",     "sigma", "tau", "upsilon", "phi", "chi", "psi", "omega"};
  auto symbol = [&](const std::string& s) {
    std::size_t end = s.size();
    while (end > 0 && std::isdigit(static_cast<unsigned char>(s[end - 1]))) --end;
    std::string name = s.substr(0, end);
    if (name.size() == 1) return static_cast<bool>(std::isalpha(static_cast<unsigned char>(name[0])));
    if (!name.empty()) name[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(name[0])));
    return greek.count(name) == 1;
  };
  return symbol(head) || (head.size() > 1 && head[0] == 'd' && symbol(head.substr(1)));
}

// The code identifiers in a worked text, each with its line: what a reader sees as C++ where the
// text means mathematics (format_value(y_0) for f(y_0)). Flagged: "::"; "->" between names; a
// member access (data.K_ff, q.segment); a name with an underscore whose head is a word, not a
// math symbol (format_value, rk4_step: K_ff, x_dot_0, phi_ddot, omega_1 and dx_C are math); a
// call of a name that is neither a math symbol with subscripts nor a math function (f(y_0),
// A(theta), C(q_1) and sin(phi) are math). In problems.md a code span that is one bare name
// (`rk4_step`) names the engine's function that computes the numbers, as the worked solutions
// do on purpose; a code span with more than a name (`node_dofs({0, 2})`) is checked as text.
std::vector<std::string> code_identifiers(const std::string& text) {
  static const std::set<std::string> functions = {"sin",  "cos", "tan", "cot", "asin", "acos", "atan", "atan2",
                                                  "sinh", "cosh", "tanh", "exp", "log", "ln", "sqrt", "diag",
                                                  "blockdiag", "det", "max", "min", "abs", "sign", "sgn", "tr",
                                                  "rank"};
  std::vector<std::string> hits;
  auto line_of = [&](std::size_t at) {
    const std::size_t newline = text.rfind('\n', at);
    const std::size_t from = newline == std::string::npos ? 0 : newline + 1;
    const std::size_t end = text.find('\n', at);
    return text.substr(from, (end == std::string::npos ? text.size() : end) - from);
  };
  auto hit = [&](std::size_t at, const std::string& what) { hits.push_back(what + "  in: " + line_of(at)); };
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] == '`') {  // a code span: one bare name passes, anything else is scanned
      const std::size_t end = text.find('`', i + 1);
      if (end != std::string::npos) {
        const std::string span = text.substr(i + 1, end - i - 1);
        const bool bare = !span.empty() && !std::isdigit(static_cast<unsigned char>(span[0])) &&
                          std::all_of(span.begin(), span.end(), is_word_char);
        if (bare) {
          i = end + 1;
          continue;
        }
      }
      ++i;
      continue;
    }
    if (text.compare(i, 2, "::") == 0) {
      hit(i, "\"::\"");
      i += 2;
      continue;
    }
    if (text.compare(i, 2, "->") == 0 && i > 0 && is_word_char(text[i - 1]) && i + 2 < text.size() &&
        is_word_char(text[i + 2])) {
      hit(i, "\"->\"");
      i += 2;
      continue;
    }
    if (!is_word_char(text[i])) {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && is_word_char(text[end])) ++end;
    const std::string word = text.substr(i, end - i);
    const std::size_t start = i;
    i = end;
    // A number (2.5e-3, 3D), or a subscript of a symbol outside ASCII (the _i of omega_i in UTF-8).
    if (std::isdigit(static_cast<unsigned char>(word[0])) || word[0] == '_') continue;
    const std::string head = word.substr(0, word.find('_'));
    const bool math = is_math_symbol(head);
    if (word.find('_') != std::string::npos && !math) hit(start, "\"" + word + "\"");
    if (end < text.size() && text[end] == '(' && !math && functions.count(word) == 0 &&
        text.compare(end, 3, "(s)") != 0)  // a plural, mode(s)
      hit(start, "\"" + word + "(\"");
    if (end + 1 < text.size() && text[end] == '.' && (std::isalpha(static_cast<unsigned char>(text[end + 1])) ||
                                                       text[end + 1] == '_')) {
      const bool abbreviation = word.size() == 1 && end + 2 < text.size() && text[end + 2] == '.';  // e.g., i.e.
      if (!abbreviation) {
        std::size_t tail = end + 1;
        while (tail < text.size() && is_word_char(text[tail])) ++tail;
        hit(start, "\"" + text.substr(start, tail - start) + "\"");
      }
    }
  }
  return hits;
}

// What `mNN_problems --worked --student NAME` prints: each problem's section of
// solutions/moduleNN_*/problems.md, the variant's statement and its numbers.
std::string worked_output(const std::string& program, const std::string& student) {
  const std::string command = "'" + program + "' --worked --student '" + student + "'";
  FILE* pipe = ::popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  std::string out;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
  CHECK(::pclose(pipe) == 0);
  return out;
}

}  // namespace

TEST_CASE("no worked-solution text contains a code identifier", "[problems]") {
  // The check itself: code fails, mathematics passes.
  for (const std::string code : {"k_1 = format_value(y_0)", "snake_case_name(x)", "std::cos(phi)", "fmbd::problems",
                                 "data.K_ff q_f", "q.segment(3, n)", "body->pose", "the engine: rk4_step on it",
                                 "`node_dofs({0, 2})`", "solve(q)"}) {
    INFO(code);
    CHECK_FALSE(code_identifiers(code).empty());
  }
  for (const std::string math :
       {"k_1 = f(y_0) = (x_dot_0, -(k x_0 + c x_dot_0) / m)", "A(theta) s", "K_ff q_f", "sin(phi), cos phi",
        "C(q_1) = -(R_1 + A(phi_1) s_P)", "omega_1 = sqrt(K[v_1, v_1] / M[v_1, v_1])", "dx_C/dt = (dx_C/dA) omega",
        "M = diag(m_1, J_1), T = blockdiag(R, R), the mode(s), e.g. a beam, i.e. one",
        "ω_i² = K_ii / M_ii, Φ_f(ξ) q_f",
        "The engine takes `rk4_step` on the model.", "E I = 567 N m^2, 2.8e7 N, x_dot_1 = 0.25 m/s."}) {
    INFO(math);
    CHECK(code_identifiers(math).empty());
  }

  // Every module's worked text, as printed, for three students.
  const std::map<std::string, std::vector<Problem>> programs = {
      {FMBD_M01_PROBLEMS, module01_problems()}, {FMBD_M02_PROBLEMS, module02_problems()},
      {FMBD_M03_PROBLEMS, module03_problems()}, {FMBD_M04_PROBLEMS, module04_problems()},
      {FMBD_M05_PROBLEMS, module05_problems()}, {FMBD_M06_PROBLEMS, module06_problems()},
      {FMBD_M07_PROBLEMS, module07_problems()}, {FMBD_M08_PROBLEMS, module08_problems()}};
  for (const auto& [program, problems] : programs) {
    for (const std::string student : {"Ada Lovelace", "Alan Turing", "s1234567"}) {
      const std::string out = worked_output(program, student);
      for (const Problem& p : problems) {
        // The section of problems.md was found and printed before the variant.
        const std::size_t heading = out.find("## " + p.name());
        INFO(program << " --worked --student '" << student << "', " << p.id);
        REQUIRE(heading != std::string::npos);
        const std::size_t body = out.find_first_not_of('\n', out.find('\n', heading));
        CHECK(out.compare(body, 13, "Your variant:") != 0);
      }
      for (const std::string& h : code_identifiers(out))
        FAIL_CHECK(problems.front().module_tag() << " worked text (" << student << ") holds code " << h);
    }
  }
}
