#include "problems.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <utility>

namespace fmbd::problems {

namespace {

constexpr double kPi = 3.14159265358979323846;

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

std::string trim(const std::string& text) {
  std::size_t begin = 0;
  std::size_t end = text.size();
  while (begin < end && is_blank(text[begin])) ++begin;
  while (end > begin && is_blank(text[end - 1])) --end;
  return text.substr(begin, end - begin);
}

std::string upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

// A number's text: [+-]digits[.digits][(e|E)[+-]digits] or [+-].digits...; no hex, inf or nan.
bool is_decimal(const std::string& text) {
  std::size_t i = 0;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  std::size_t digits = 0;
  while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i, ++digits;
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i, ++digits;
  }
  if (digits == 0) return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    std::size_t exponent = 0;
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i, ++exponent;
    if (exponent == 0) return false;
  }
  return i == text.size();
}

// Reads a VALUE from text[pos...]: a number, [n, ...] or [[n, ...], ...]. Advances pos past it.
class ValueReader {
 public:
  ValueReader(const std::string& text, std::size_t pos) : text_(text), pos_(pos) {}

  bool read(Quantity& out, std::string& error) {
    skip();
    if (peek() != '[') {
      double x = 0;
      if (!number(x, error)) return false;
      out = Quantity::number(x);
      return true;
    }
    ++pos_;
    skip();
    if (peek() != '[') {
      std::vector<double> row;
      if (!list(row, error)) return false;
      out = Quantity::vector(std::move(row));
      return true;
    }
    std::vector<std::vector<double>> rows;
    for (;;) {
      skip();
      if (peek() != '[') return fail(error, "a matrix is written [[a, b], [c, d]]: \"[\" expected");
      ++pos_;
      std::vector<double> row;
      if (!list(row, error)) return false;
      if (!rows.empty() && row.size() != rows.front().size())
        return fail(error, "the rows of a matrix have the same number of entries (row " + std::to_string(rows.size() + 1) +
                               " has " + std::to_string(row.size()) + ", row 1 has " +
                               std::to_string(rows.front().size()) + ")");
      rows.push_back(std::move(row));
      skip();
      if (peek() == ',') {
        ++pos_;
        continue;
      }
      if (peek() == ']') {
        ++pos_;
        break;
      }
      return fail(error, "\",\" or \"]\" expected after a row of the matrix");
    }
    std::vector<double> values;
    for (const auto& row : rows) values.insert(values.end(), row.begin(), row.end());
    out = Quantity::matrix(static_cast<int>(rows.size()), static_cast<int>(rows.front().size()), std::move(values));
    return true;
  }

  std::size_t position() const { return pos_; }

 private:
  char peek() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }
  void skip() {
    while (pos_ < text_.size() && is_blank(text_[pos_])) ++pos_;
  }
  static bool fail(std::string& error, const std::string& why) {
    error = why;
    return false;
  }
  bool number(double& x, std::string& error) {
    skip();
    const std::size_t begin = pos_;
    while (pos_ < text_.size() && !is_blank(text_[pos_]) && text_[pos_] != ',' && text_[pos_] != ']' &&
           text_[pos_] != '[')
      ++pos_;
    const std::string word = text_.substr(begin, pos_ - begin);
    if (word.empty()) return fail(error, "a number is missing");
    if (!is_decimal(word)) return fail(error, "\"" + word + "\" is not a number (write 1.5, -2 or 3.1e-4)");
    x = std::strtod(word.c_str(), nullptr);
    if (!std::isfinite(x)) return fail(error, "\"" + word + "\" is out of range");
    return true;
  }
  // n, n, ... ] (the opening bracket read)
  bool list(std::vector<double>& row, std::string& error) {
    for (;;) {
      double x = 0;
      if (!number(x, error)) return false;
      row.push_back(x);
      skip();
      if (peek() == ',') {
        ++pos_;
        continue;
      }
      if (peek() == ']') {
        ++pos_;
        return true;
      }
      return fail(error, "\",\" or \"]\" expected after " + format_quantity(Quantity::number(x)) +
                             " (entries are separated by commas)");
    }
  }

  const std::string& text_;
  std::size_t pos_;
};

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
      return fail(a.line, where + problem.id + " has no unit (entries in SI); remove \"" + a.unit + "\"");
  } else if (a.unit.empty()) {
    if (!problem.unit_optional)
      return fail(a.line, where + "the unit is missing: write the value with its unit, e.g. \"" + problem.id +
                              " = " + format_quantity(a.value) + " " + problem.unit + "\"");
    out.bare = true;
  } else {
    const std::optional<Unit> unit = parse_unit(a.unit);
    if (!unit) return fail(a.line, where + "unknown unit \"" + a.unit + "\" (SI: " + problem.unit + ")");
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

std::optional<Unit> parse_unit(const std::string& text) {
  // Factors separated by blanks or '*', rejoined with one space.
  std::string key;
  std::string word;
  std::string spaced = text;
  std::replace(spaced.begin(), spaced.end(), '*', ' ');
  std::istringstream parts(spaced);
  while (parts >> word) key += (key.empty() ? "" : " ") + word;
  static const std::map<std::string, Unit> units = {
      {"m", {"m", 1}},          {"cm", {"m", 1e-2}},
      {"mm", {"m", 1e-3}},      {"s", {"s", 1}},
      {"kg", {"kg", 1}},        {"N", {"N", 1}},
      {"kN", {"N", 1e3}},       {"N m", {"N m", 1}},
      {"Nm", {"N m", 1}},       {"rad", {"rad", 1}},
      {"deg", {"rad", kPi / 180}}, {"rad/s", {"rad/s", 1}},
      {"deg/s", {"rad/s", kPi / 180}}, {"rad/s^2", {"rad/s^2", 1}},
      {"m/s", {"m/s", 1}},      {"m/s^2", {"m/s^2", 1}},
      {"Hz", {"1/s", 1}},       {"1/s", {"1/s", 1}},
      {"J", {"J", 1}},          {"Pa", {"Pa", 1}},
      {"MPa", {"Pa", 1e6}},     {"GPa", {"Pa", 1e9}},
      {"kg m^2", {"kg m^2", 1}},
  };
  const auto found = units.find(key);
  if (found == units.end()) return std::nullopt;
  return found->second;
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

// ---- the answers file ----

AnswerFile read_answers(const std::string& text, const std::vector<std::string>& ids) {
  AnswerFile file;
  std::istringstream in(text);
  int number = 0;
  for (std::string raw; std::getline(in, raw);) {
    ++number;
    const std::string line = trim(raw.substr(0, raw.find('#')));
    if (line.empty()) continue;
    const std::string where = "line " + std::to_string(number) + ": ";
    std::size_t end = 0;
    while (end < line.size() && std::isalnum(static_cast<unsigned char>(line[end]))) ++end;
    const std::string id = upper(line.substr(0, end));
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) {
      std::string known;
      for (const std::string& k : ids) known += (known.empty() ? "" : ", ") + k;
      file.notes.push_back(where + "\"" + trim(raw) + "\" names no problem of this module (" + known +
                           "); the line is ignored");
      continue;
    }
    Answer a;
    a.line = number;
    a.text = line;
    std::size_t pos = end;
    while (pos < line.size() && is_blank(line[pos])) ++pos;
    std::string error;
    if (pos >= line.size() || line[pos] != '=') {
      a.error = where + "write \"" + id + " = VALUE UNIT\" (an \"=\" after the id)";
    } else {
      ValueReader reader(line, pos + 1);
      if (!reader.read(a.value, error)) {
        a.error = where + error;
      } else {
        a.unit = trim(line.substr(reader.position()));
        a.ok = true;
      }
    }
    file.answers[id].push_back(a);
  }
  return file;
}

AnswerFile read_answers_file(const std::string& path, const std::vector<std::string>& ids) {
  std::ifstream in(path);
  if (!in) {
    AnswerFile file;
    file.found = false;
    return file;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return read_answers(text.str(), ids);
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
                            trim(read.answer->text.substr(read.answer->text.find('=') + 1));
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

// ---- the program ----

namespace {

// The test name inside a Catch test spec: quoted, with \ before \ , [ ] * ~ ".
std::string unescape(const std::string& spec) {
  std::string text = spec;
  if (text.size() >= 2 && text.front() == '"' && text.back() == '"') text = text.substr(1, text.size() - 2);
  std::string name;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\' && i + 1 < text.size()) ++i;
    name += text[i];
  }
  return name;
}

// "module01_kinematics" of ".../module01_kinematics/answers.txt".
std::string parent_folder_name(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  if (slash == std::string::npos || slash == 0) return "";
  const std::size_t before = path.rfind('/', slash - 1);
  return path.substr(before == std::string::npos ? 0 : before + 1, slash - (before == std::string::npos ? 0 : before + 1));
}

std::string read_token(int fd) {
  std::string token;
  char c = 0;
  while (::read(fd, &c, 1) == 1 && c != '\n') token += c;
  ::close(fd);
  return token;
}

std::string points_text(double points) { return format_number(points, 6); }

// The section "## ID ..." of problems.md up to the next "## ", or "" when absent.
std::string worked_section(const std::string& path, const std::string& id) {
  std::ifstream in(path);
  std::string out;
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("## ", 0) == 0) {
      inside = line.rfind("## " + id, 0) == 0;
      if (!inside && !out.empty()) break;
    }
    if (inside) out += line + "\n";
  }
  return out;
}

// "VALUE m", "[x1, x2] m", "[[a11, a12], [a21, a22]]": the form of an answer line's value.
std::string answer_template(const Problem& p) {
  std::string out;
  if (p.kind == Kind::number) {
    out = "VALUE";
  } else if (p.kind == Kind::vector) {
    for (int r = 0; r < p.rows; ++r) out += (r ? ", x" : "[x") + std::to_string(r + 1);
    out += "]";
  } else {
    for (int r = 0; r < p.rows; ++r) {
      out += r ? ", [" : "[[";
      for (int c = 0; c < p.cols; ++c) out += (c ? ", a" : "a") + std::to_string(r + 1) + std::to_string(c + 1);
      out += "]";
    }
    out += "]";
  }
  if (!p.unit.empty()) out += " " + p.unit + (p.unit_optional ? " (or no unit: SI)" : "");
  return out;
}

const char* kNoIdentity =
    "no student identity: grade with --student NAME (./workbook), or set FMBD_STUDENT; your numbers "
    "depend on it";

// The program's command line: its mode, the problem asked for, and where things are.
struct Invocation {
  std::string mode = "grade";  // grade, list, check, template, model-answers, print, worked, help
  std::string only;            // --print ID, --worked ID
  std::string spec;            // the test to grade: "MnnPk: title" or MnnPk
  std::string answers_path;
  std::string student;  // --student NAME (for --print, --worked, --model-answers)
  bool have_student = false;
  int token_fd = -1;
};

// Reads the command line; returns 2 for an unknown option (after saying so), else -1.
int read_invocation(int argc, char** argv, const ProgramConfig& config, Invocation& call) {
  call.answers_path = config.answers_path;
  // The front end hands the answers over in a folder of its own (readable by the unprivileged
  // user the tests may run as): ROOT/<module folder>/answers.txt.
  if (const char* root = std::getenv("FMBD_ANSWERS_ROOT"); root != nullptr && *root != '\0') {
    call.answers_path = std::string(root) + "/" + parent_folder_name(config.answers_path) + "/answers.txt";
  }
  static const std::map<std::string, std::string> flags = {
      {"--fmbd-list", "list"}, {"--check", "check"}, {"--model-answers", "model-answers"}, {"--template", "template"},
      {"-h", "help"},          {"--help", "help"}};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (flags.count(arg)) {
      call.mode = flags.at(arg);
    } else if (arg == "--print" || arg == "--worked") {
      call.mode = arg.substr(2);
      if (has_value && argv[i + 1][0] != '-') call.only = upper(argv[++i]);
    } else if (arg == "--fmbd-token-fd" && has_value) {
      call.token_fd = std::atoi(argv[++i]);
    } else if (arg == "--answers" && has_value) {
      call.answers_path = argv[++i];
    } else if (arg == "--student" && has_value) {
      call.student = argv[++i];
      call.have_student = true;
    } else if ((arg == "--fmbd-time-limit" || arg == "--use-colour" || arg == "--warn" || arg == "--reporter") &&
               has_value) {
      ++i;
    } else if (!arg.empty() && arg[0] == '-' && arg != "-") {
      std::cout << "unknown option " << arg << " (--help lists them)\n";
      return 2;
    } else {
      call.spec = arg;
    }
    if (call.mode == "help") return -1;
  }
  return -1;
}

int print_help(const ProgramConfig& config, const char* program) {
  std::cout << "usage: " << program
            << " [--answers FILE] (--fmbd-list | --check | --print [ID] | --worked [ID] | --model-answers |\n"
               "  \"MnnPk: title\")\n"
               "Tutorial problems of module "
            << config.module_tag
            << ": lists them, checks the answers file's format, prints your variant's statements\n"
               "(--student NAME or FMBD_STUDENT), its worked solution, or grades one problem\n"
               "(identity from FMBD_STUDENT only). Answers: "
            << config.answers_path << "\n";
  return 0;
}

std::vector<std::string> problem_ids(const std::vector<Problem>& problems) {
  std::vector<std::string> ids;
  for (const Problem& p : problems) ids.push_back(p.id);
  return ids;
}

// The answers file, with its notes printed.
AnswerFile read_answers_noted(const std::string& path, const std::vector<std::string>& ids) {
  AnswerFile file = read_answers_file(path, ids);
  if (!file.found) std::cout << path << ": note: no such file\n";
  for (const std::string& note : file.notes) std::cout << path << ": note: " << note << "\n";
  return file;
}

int list_problems(const std::vector<Problem>& problems) {
  for (const Problem& p : problems)
    std::cout << p.name() << "\t[" << p.module_tag() << "][" << p.problem_tag() << "][points=" << points_text(p.points)
              << "]\n";
  return 0;
}

int check_answers(const std::vector<Problem>& problems, const Invocation& call) {
  const AnswerFile file = read_answers_noted(call.answers_path, problem_ids(problems));
  int bad = 0;
  for (const Problem& p : problems) {
    const std::optional<Grade> failure = check_format(p, file);
    if (failure) ++bad;
    std::cout << p.id << ": " << (failure ? failure->message : std::string("format OK")) << "\n";
  }
  return bad ? 1 : 0;
}

// An answers file to fill in (./workbook problems writes it).
int print_template(const std::vector<Problem>& problems, const ProgramConfig& config) {
  std::cout << "# Your answers to the tutorial problems of module " << std::stoi(config.module_tag.substr(1))
            << " (./workbook problems " << config.module_tag << " prints them).\n"
               "# One line per problem, ID = VALUE UNIT, e.g. M01P2 = [0.1, -0.25] m; '#' starts a comment.\n";
  for (const Problem& p : problems) std::cout << "# " << p.id << " = " << answer_template(p) << "\n";
  return 0;
}

// --student NAME, else FMBD_STUDENT.
std::string identity_of(const Invocation& call) {
  const char* env = std::getenv("FMBD_STUDENT");
  return !call.have_student && env ? std::string(env) : call.student;
}

// A correct answers file of the variant (./workbook grade --solutions).
int print_model_answers(const std::vector<Problem>& problems, const ProgramConfig& config, const Invocation& call) {
  const std::string student = identity_of(call);
  if (normalise_identity(student).empty() || !config.has_reference) {
    std::cout << "--model-answers needs the reference and a student identity (--student NAME or FMBD_STUDENT)\n";
    return 2;
  }
  for (const Problem& p : problems) {
    const Solution s = make_variant(p, student).solve();
    std::cout << p.id << " = " << format_quantity(s.answer, 12) << (p.unit.empty() ? "" : " " + p.unit) << "\n";
  }
  return 0;
}

// One problem's worked solution: its derivation (solutions/) and the variant's numbers.
void print_worked(const Problem& p, const Variant& v, const ProgramConfig& config) {
  const std::string text = worked_section(config.worked_path, p.id);
  const std::size_t body = text.find('\n');  // without the heading, printed above
  const std::string derivation = trim(text.substr(body == std::string::npos ? text.size() : body + 1));
  if (!derivation.empty()) std::cout << derivation << "\n\n";
  std::cout << "Your variant:\n" << v.statement << "\n\nYour numbers:\n";
  const Solution s = v.solve();
  for (const std::string& step : s.steps) std::cout << "  " << step << "\n";
  std::cout << "  answer: " << p.id << " = " << format_quantity(s.answer) << (p.unit.empty() ? "" : " " + p.unit)
            << "\n\n";
}

// --print and --worked: the statements, or the worked solutions, of the variant.
int print_variant(const std::vector<Problem>& problems, const ProgramConfig& config, const Invocation& call) {
  const std::string student = identity_of(call);
  if (normalise_identity(student).empty()) {
    std::cout << "no student identity: pass --student NAME (or set FMBD_STUDENT); your numbers depend on it\n";
    return 2;
  }
  if (call.mode == "worked" && !config.has_reference) {
    std::cout << "worked solutions come with the module's released solutions; this copy has none for "
              << config.module_tag << "\n";
    return 2;
  }
  bool any = false;
  for (const Problem& p : problems) {
    if (!call.only.empty() && p.id != call.only) continue;
    any = true;
    const Variant v = make_variant(p, student);
    std::cout << "## " << p.name() << " (" << points_text(p.points) << " points)\n\n";
    if (call.mode == "print") {
      std::cout << v.statement << "\n\nAnswer as: " << p.id << " = " << answer_template(p) << "\n\n";
    } else {
      print_worked(p, v, config);
    }
  }
  if (!any) {
    std::cout << "no problem " << call.only << " in " << config.module_tag << "\n";
    return 2;
  }
  return 0;
}

// The grade of one problem: its value with the identity of FMBD_STUDENT where the copy has the
// reference, else its format only.
Grade grade_one(const Problem& p, const AnswerFile& file, const ProgramConfig& config) {
  const char* env = std::getenv("FMBD_STUDENT");
  const std::string identity = env ? env : "";
  if (!normalise_identity(identity).empty() && config.has_reference) return grade(p, make_variant(p, identity).solve(), file);
  Grade g;
  const std::optional<Grade> failure = check_format(p, file);
  if (failure) return *failure;
  g.line = file.answers.at(p.id).front().line;
  g.message = config.has_reference ? kNoIdentity : kFormatOnly;
  return g;
}

// Grades the problem named by the driver, in its protocol: the completion token after a pass, the
// feedback in Catch's compact form after a failure.
int grade_problem(const std::vector<Problem>& problems, const ProgramConfig& config, const Invocation& call) {
  std::string token;
  if (call.token_fd >= 0) token = read_token(call.token_fd);
  const std::string name = unescape(call.spec);
  for (const Problem& p : problems) {
    if (p.name() != name && p.id != upper(name)) continue;
    const AnswerFile file = read_answers_noted(call.answers_path, problem_ids(problems));
    if (call.have_student)
      std::cout << "note: --student sets the identity of --print and --worked; a grade reads FMBD_STUDENT only\n";
    const Grade g = grade_one(p, file, config);
    if (!g.passed) {
      // Catch's compact form, which the driver reads: FILE:LINE: failed: ... with 1 message: 'hint: ...'
      // A quote that the driver could read as the end of the message becomes ": an apostrophe
      // inside a word ("instructor's") stays.
      std::string message = g.message;
      for (std::size_t i = 0; i < message.size(); ++i) {
        if (message[i] == '\'' && !(i + 1 < message.size() && std::isalpha(static_cast<unsigned char>(message[i + 1]))))
          message[i] = '"';
      }
      std::cout << call.answers_path << ":" << g.line << ": failed: " << p.id << " with 1 message: 'hint: " << message
                << "'\n";
      return 1;
    }
    std::cout << p.id << ": correct\n";
    if (call.token_fd >= 0) std::cout << "fmbd-completion-token: " << token << std::endl;
    return 0;
  }
  std::cout << "No test cases matched '" << name << "'\n";
  return 1;
}

}  // namespace

int run_program(const std::vector<Problem>& problems, const ProgramConfig& config, int argc, char** argv) {
  Invocation call;
  if (const int status = read_invocation(argc, argv, config, call); status >= 0) return status;
  if (call.mode == "help") return print_help(config, argv[0]);
  if (call.mode == "list") return list_problems(problems);
  if (call.mode == "check") return check_answers(problems, call);
  if (call.mode == "template") return print_template(problems, config);
  if (call.mode == "model-answers") return print_model_answers(problems, config, call);
  if (call.mode == "print" || call.mode == "worked") return print_variant(problems, config, call);
  return grade_problem(problems, config, call);
}

}  // namespace fmbd::problems
