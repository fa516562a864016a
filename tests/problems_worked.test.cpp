// Project tests of the tutorial problems, continued from problems.test.cpp: no worked solution,
// as each module's program prints it, holds a code identifier.
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
