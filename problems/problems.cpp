// The variant, quantities and grading (problems.hpp); the answers file is read in
// answers_file.cpp, units in units.cpp, and the program is program.cpp.
#include "problems.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "problem_text.hpp"

namespace fmbd::problems {

namespace {

constexpr double kPi = 3.14159265358979323846;

using text::excerpt;
using text::is_blank;
using text::trim;

// "a vector of 2 entries, [a, b]"; brief: without the example.
std::string shape_text(Kind kind, int rows, int cols, bool brief = false) {
  switch (kind) {
    case Kind::number: return "one number";
    case Kind::vector:
      return "a vector of " + std::to_string(rows) + " entries" + (brief ? "" : rows > 2 ? ", [a, b, ...]" : ", [a, b]");
    case Kind::matrix:
      return "a " + std::to_string(rows) + " x " + std::to_string(cols) + " matrix" +
             (brief ? "" : ", [[a, b, ...], [c, d, ...], ...]");
  }
  return "";
}

std::string format_number(double x, int digits) {
  std::ostringstream out;
  out.precision(digits);
  out << (x == 0 ? 0.0 : x);  // no "-0"
  return out.str();
}

Quantity scaled(const Quantity& q, double factor) {
  Quantity out = q;
  for (double& x : out.values) x *= factor;
  return out;
}

Quantity transposed(const Quantity& q) {
  std::vector<double> values;
  for (int c = 0; c < q.cols; ++c)
    for (int r = 0; r < q.rows; ++r) values.push_back(q(r, c));
  return Quantity(q.kind, q.cols, q.rows, std::move(values));
}

bool same_shape(const Quantity& a, const Quantity& b) { return a.rows == b.rows && a.cols == b.cols; }

bool is_angle(const std::string& si) { return si.rfind("rad", 0) == 0; }

// The answer of `problem` as a quantity in SI, or the failing grade.
struct Read {
  std::optional<Grade> failure;
  const Answer* answer = nullptr;
  Quantity si;
  bool bare = false;  // no unit written where the problem has one (units optional)
};

Read read_answer(const Problem& problem, const AnswerFile& file) {
  Read out;
  auto fail = [&](int line, const std::string& message) {
    Grade g;
    g.line = line;
    g.message = message;
    out.failure = g;
    return out;
  };
  if (!file.found) return fail(0, "no answers file: write one line \"" + problem.id + " = VALUE" +
                                       (problem.unit.empty() ? "" : " " + problem.unit) + "\" in it");
  if (!file.not_text.empty()) return fail(file.not_text_line, file.not_text);
  const auto found = file.answers.find(problem.id);
  if (found == file.answers.end() || found->second.empty())
    return fail(0, "no answer for " + problem.id + ": add a line \"" + problem.id + " = VALUE" +
                       (problem.unit.empty() ? "" : " " + problem.unit) + "\"");
  const std::vector<Answer>& lines = found->second;
  if (lines.size() > 1) {
    std::string numbers;
    for (const Answer& a : lines) numbers += (numbers.empty() ? "" : ", ") + std::to_string(a.line);
    return fail(lines.back().line, problem.id + " is answered on more than one line (lines " + numbers +
                                       "): keep one");
  }
  const Answer& a = lines.front();
  out.answer = &a;
  if (!a.ok) return fail(a.line, a.error);
  const std::string where = "line " + std::to_string(a.line) + ": ";
  if (!(a.value.kind == problem.kind && a.value.rows == problem.rows && a.value.cols == problem.cols)) {
    const bool transpose = problem.kind == Kind::matrix && a.value.kind == Kind::matrix &&
                           a.value.rows == problem.cols && a.value.cols == problem.rows;
    if (!transpose) return fail(a.line, where + problem.id + " is " + shape_text(problem.kind, problem.rows, problem.cols) +
                                           ", not " + shape_text(a.value.kind, a.value.rows, a.value.cols, true));
  }
  double scale = 1.0;
  if (problem.unit.empty()) {
    if (!a.unit.empty())
      return fail(a.line, where + problem.id + " has no unit (entries in SI); remove \"" + excerpt(a.unit) + "\"");
  } else if (a.unit.empty()) {
    if (!problem.unit_optional)
      return fail(a.line, where + "the unit is missing: write the value with its unit, e.g. \"" + problem.id +
                              " = " + format_quantity(a.value) + " " + problem.unit + "\"");
    out.bare = true;
  } else {
    const std::optional<Unit> unit = parse_unit(a.unit);
    if (!unit) return fail(a.line, where + "unknown unit \"" + excerpt(a.unit) + "\" (SI: " + problem.unit + ")");
    if (unit->si != problem.unit)
      return fail(a.line, where + "\"" + a.unit + "\" is a unit of " + unit->si + ", and " + problem.id +
                              " is in " + problem.unit);
    scale = unit->scale;
  }
  out.si = scaled(a.value, scale);
  return out;
}

}  // namespace

// ---- identity, seed and parameters ----

std::string normalise_identity(const std::string& identity) {
  std::string out;
  bool blank = false;
  for (char c : trim(identity)) {
    if (is_blank(c)) {
      blank = true;
      continue;
    }
    if (blank) out += ' ';
    blank = false;
    out += (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
  }
  return out;
}

unsigned long long fnv1a64(const std::string& text) {
  unsigned long long h = 0xcbf29ce484222325ULL;
  for (char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  return h;
}

unsigned long long variant_seed(const std::string& identity, const std::string& problem_id) {
  return fnv1a64(normalise_identity(identity) + "/" + problem_id);
}

unsigned long long Parameters::next() {
  state_ += 0x9e3779b97f4a7c15ULL;
  unsigned long long z = state_;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double Parameters::grid(double lo, double step, int n) {
  const unsigned long long k = next() % static_cast<unsigned long long>(n);
  // Rounded to 9 decimals with IEEE operations only (no libm function whose last bit may differ).
  const double value = std::round((lo + static_cast<double>(k) * step) * 1e9) / 1e9;
  drawn_.push_back(value);
  return value;
}

int Parameters::integer(int lo, int hi) {
  const int value = lo + static_cast<int>(next() % static_cast<unsigned long long>(hi - lo + 1));
  drawn_.push_back(value);
  return value;
}

Variant make_variant(const Problem& problem, const std::string& identity) {
  Parameters parameters(variant_seed(identity, problem.id));
  Variant v = problem.make(parameters);
  v.parameters = parameters.drawn();
  return v;
}

// ---- quantities and units ----

Quantity::Quantity(Kind kind, int rows, int cols, std::vector<double> values)
    : kind(kind), rows(rows), cols(cols), values(std::move(values)) {}

Quantity Quantity::number(double value) { return Quantity(Kind::number, 1, 1, {value}); }

Quantity Quantity::vector(std::vector<double> values) {
  const int n = static_cast<int>(values.size());
  return Quantity(Kind::vector, n, 1, std::move(values));
}

Quantity Quantity::matrix(int rows, int cols, std::vector<double> values) {
  return Quantity(Kind::matrix, rows, cols, std::move(values));
}

std::string format_value(double x, int digits) { return format_number(x, digits); }

std::string format_quantity(const Quantity& q, int digits) {
  if (q.kind == Kind::number) return format_number(q.values.at(0), digits);
  std::string out = "[";
  for (int r = 0; r < q.rows; ++r) {
    if (q.kind == Kind::vector) {
      out += (r ? ", " : "") + format_number(q(r, 0), digits);
      continue;
    }
    out += r ? ", [" : "[";
    for (int c = 0; c < q.cols; ++c) out += (c ? ", " : "") + format_number(q(r, c), digits);
    out += "]";
  }
  return out + "]";
}

bool within(const Quantity& value, const Quantity& expected, const Tolerance& tolerance) {
  if (!same_shape(value, expected)) return false;
  double largest = 0;
  for (double e : expected.values) largest = std::max(largest, std::abs(e));
  const double allowed = tolerance.absolute + tolerance.relative * largest;
  for (std::size_t k = 0; k < value.values.size(); ++k) {
    if (!(std::abs(value.values[k] - expected.values[k]) <= allowed)) return false;
  }
  return true;
}

// ---- grading ----

std::optional<Grade> check_format(const Problem& problem, const AnswerFile& file) {
  const Read read = read_answer(problem, file);
  if (read.failure) return read.failure;
  if (read.answer->value.rows != problem.rows) {  // a transposed matrix: its own message
    Grade g;
    g.line = read.answer->line;
    g.message = "line " + std::to_string(g.line) + ": " + problem.id + " is " +
                shape_text(problem.kind, problem.rows, problem.cols) + ", not " +
                shape_text(read.answer->value.kind, read.answer->value.rows, read.answer->value.cols, true);
    return g;
  }
  return std::nullopt;
}

Grade grade(const Problem& problem, const Solution& solution, const AnswerFile& file) {
  const Read read = read_answer(problem, file);
  if (read.failure) return *read.failure;
  Grade g;
  g.line = read.answer->line;
  const Quantity& a = read.si;
  const Quantity& e = solution.answer;
  const Tolerance& tol = problem.tolerance;
  if (within(a, e, tol)) {
    g.passed = true;
    g.message = "correct";
    return g;
  }
  const std::string where = "line " + std::to_string(g.line) + ": " + problem.id + " = " +
                            excerpt(trim(read.answer->text.substr(read.answer->text.find('=') + 1)));
  // A mistake counts only where its value differs from the answer.
  std::vector<Mistake> mistakes = solution.mistakes;
  if (problem.kind == Kind::matrix) {
    const Quantity t = transposed(e);
    mistakes.emplace_back("the transpose: rows and columns are swapped", t);
  }
  mistakes.emplace_back("the sign is wrong", scaled(e, -1));
  mistakes.emplace_back("off by a factor of 2 (twice the answer)", scaled(e, 2));
  mistakes.emplace_back("off by a factor of 2 (half the answer)", scaled(e, 0.5));
  if (is_angle(problem.unit)) {
    const std::string bare = read.bare ? " (a number without a unit is in rad)" : "";
    mistakes.emplace_back("degrees against radians: the value is in degrees" + bare, scaled(e, 180 / kPi));
    mistakes.emplace_back("degrees against radians: an angle in degrees was taken as radians", scaled(e, kPi / 180));
  }
  if (!problem.unit.empty() && !is_angle(problem.unit)) {
    for (const double f : {1e3, 1e-3, 1e2, 1e-2}) {
      mistakes.emplace_back("a unit's scale: off by a factor of " + format_number(f, 3) +
                                " (mm or cm against m? the unit you wrote is read as written)",
                            scaled(e, f));
    }
  }
  for (const Mistake& m : mistakes) {
    if (!same_shape(m.value, e) && !same_shape(transposed(m.value), e)) continue;
    if (same_shape(m.value, e) && within(m.value, e, tol)) continue;
    if (within(a, m.value, tol)) {
      g.message = where + ": likely mistake: " + m.name;
      return g;
    }
  }
  if (!same_shape(a, e)) {
    g.message = "line " + std::to_string(g.line) + ": " + problem.id + " is " + shape_text(problem.kind, problem.rows, problem.cols);
    return g;
  }
  std::string tolerance = format_number(tol.relative * 100, 3) + " %";
  if (tol.absolute > 0) tolerance += " (+ " + format_number(tol.absolute, 3) + (problem.unit.empty() ? "" : " " + problem.unit) + ")";
  g.message = where + ": not within " + tolerance + " of the answer, and no likely mistake fits";
  return g;
}

}  // namespace fmbd::problems
