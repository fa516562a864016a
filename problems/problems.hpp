#pragma once
// Tutorial problems with a variant per student: the engine that defines, prints and
// grades them. Each module's problems are defined in moduleNN_*/problems/problems.cpp; this
// library holds what they share:
//
//   * the variant: a seed from the student's identity and the problem id (variant_seed) and a
//     stream of parameters on grids of "nice" numbers (Parameters), the same on every platform;
//   * the answers file moduleNN_*/answers.txt (read_answers, answers_file.cpp): one line
//     "MnnPk = VALUE UNIT", the unit converted to SI (units.hpp);
//   * the grade of one answer (grade), with feedback that names the likely mistake;
//   * the program of a module (run_program), which speaks the grade driver's list/token protocol
//     (autograder/driver/grade.cpp) and prints the statements and worked numbers.
//
// The identity. normalise_identity() trims the string, lower-cases ASCII letters and collapses
// every inner run of blanks (space, tab, CR, LF, VT, FF) into one space:
// "  Ada   LOVELACE " -> "ada lovelace".
//
// The seed. variant_seed(identity, id) = FNV-1a 64 (offset basis 0xcbf29ce484222325, prime
// 0x100000001b3) over the bytes of normalise_identity(identity), one byte '/', then the problem
// id as written ("M01P2").
//
// The parameters. Parameters(seed) is a splitmix64 stream: state += 0x9e3779b97f4a7c15, then
// z = state; z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9; z = (z ^ (z >> 27)) * 0x94d049bb133111eb;
// z ^ (z >> 31) is the next 64-bit draw. grid(lo, step, n) takes the draw k = z mod n and returns
// lo + k step, rounded to 9 decimals (so 0.1 + 3 * 0.05 is the double nearest 0.25). No standard
// distribution is used: their output differs between standard libraries.
//
// Tolerances. An answer (a number, or each entry of a vector or matrix) passes when
// |a_k - e_k| <= absolute + relative * max_k |e_k|, e the model answer, both in SI.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "units.hpp"

namespace fmbd::problems {

/// Lower-case, trimmed, inner blanks collapsed to one space (see above).
std::string normalise_identity(const std::string& identity);
/// FNV-1a 64 of the bytes of `text`.
unsigned long long fnv1a64(const std::string& text);
/// FNV-1a 64 of normalise_identity(identity) + "/" + problem_id.
unsigned long long variant_seed(const std::string& identity, const std::string& problem_id);

/// The splitmix64 stream of a variant's parameters (see above).
class Parameters {
 public:
  explicit Parameters(unsigned long long seed) : state_(seed) {}
  /// The next 64-bit draw.
  unsigned long long next();
  /// lo + k step with k = next() mod n (n >= 1), rounded to 9 decimals: round(x 1e9) / 1e9.
  double grid(double lo, double step, int n);
  /// An integer in lo..hi (inclusive): lo + next() mod (hi - lo + 1).
  int integer(int lo, int hi);
  /// The values drawn so far by grid() and integer(), in order (what differs between variants).
  const std::vector<double>& drawn() const { return drawn_; }

 private:
  unsigned long long state_;
  std::vector<double> drawn_;
};

enum class Kind { number, vector, matrix };

/// A number (1 x 1), a vector (n x 1) or a matrix (rows x cols), entries row by row.
struct Quantity {
  Kind kind = Kind::number;
  int rows = 1;
  int cols = 1;
  std::vector<double> values;

  Quantity() = default;
  Quantity(Kind kind, int rows, int cols, std::vector<double> values);
  static Quantity number(double value);
  static Quantity vector(std::vector<double> values);
  /// `values` row by row.
  static Quantity matrix(int rows, int cols, std::vector<double> values);
  double operator()(int row, int col) const { return values[static_cast<std::size_t>(row * cols + col)]; }
};

/// "0.25", "[1.5, -2]", "[[1, 2], [3, 4]]", with `digits` significant digits.
std::string format_quantity(const Quantity& q, int digits = 6);
/// One number with `digits` significant digits ("0.25", "-1.2e-05"; never "-0").
std::string format_value(double x, int digits = 6);

struct Tolerance {
  double relative = 5e-3;
  double absolute = 0.0;
  Tolerance() = default;
  Tolerance(double relative, double absolute) : relative(relative), absolute(absolute) {}
};

/// Whether `value` is within `tolerance` of `expected` (same shape; see above).
bool within(const Quantity& value, const Quantity& expected, const Tolerance& tolerance);

/// A likely mistake: its name as the feedback says it, and the value it leads to.
struct Mistake {
  std::string name;
  Quantity value;
  Mistake(std::string name, Quantity value) : name(std::move(name)), value(std::move(value)) {}
};

/// The model answer of a variant, computed by the reference engine, with the values of the
/// named mistakes and the intermediate values of the worked solution ("A(phi) s = [...] m").
struct Solution {
  Quantity answer;
  std::vector<Mistake> mistakes;
  std::vector<std::string> steps;
};

/// One student's variant of a problem: the statement with its numbers, and how to solve it.
struct Variant {
  std::string statement;
  std::vector<double> parameters;    ///< the drawn numbers (Parameters::drawn())
  std::function<Solution()> solve;   ///< calls the reference engine
};

/// A problem: what the grade driver lists and how a variant is made from the parameter stream.
struct Problem {
  std::string id;     ///< "M01P2"
  std::string title;  ///< one line, no tab
  double points = 1;
  Tolerance tolerance;
  Kind kind = Kind::number;
  int rows = 1;       ///< shape of the answer (1 x 1 for a number, n x 1 for a vector)
  int cols = 1;
  std::string unit;   ///< SI unit of the answer ("m/s", "N m", "rad"); "" when it has none
  /// A bare number is accepted in SI. Set where the unit is rad: a bare angle is in radians.
  bool unit_optional = false;
  std::function<Variant(Parameters&)> make;

  /// "M01P2: title", the test name of the protocol.
  std::string name() const { return id + ": " + title; }
  /// The module and problem numbers of the id, "M01", "P2".
  std::string module_tag() const { return id.substr(0, 3); }
  std::string problem_tag() const { return id.substr(3); }
};

/// The variant of `problem` for `identity`.
Variant make_variant(const Problem& problem, const std::string& identity);

/// One answer line as read.
struct Answer {
  int line = 0;
  std::string text;      ///< the line as written
  bool ok = false;       ///< the value (and unit) could be read
  std::string error;     ///< why not: "line 4: ..." (when !ok)
  Quantity value;        ///< as written, before the unit's scale
  std::string unit;      ///< as written ("" when none)
};

/// The answers file, read line by line: each problem's answers (more than one: a repeated line)
/// and the messages of the lines that name no problem of the module.
struct AnswerFile {
  std::map<std::string, std::vector<Answer>> answers;  ///< by problem id
  std::vector<std::string> notes;                      ///< "line 7: ..." of the other lines
  bool found = true;                                   ///< the file could be opened
  /// Why the file is not UTF-8 text ("" when it is): then it has no answers and no notes, and
  /// every problem fails with this message, which names the file, the line and column of the
  /// first bad byte, and the fix.
  std::string not_text;
  int not_text_line = 0;  ///< the line of that byte (0 when the file is text)
};

/// Reads the answers in `text`; `ids` are the module's problem ids (a line "m01p2 = ..." is
/// M01P2). The grammar, after '#' and what follows it is removed:
///   ID = VALUE [UNIT]      VALUE: 1.5e-3 | [1, 2] | [[1, 2], [3, 4]]
/// A line that cannot be read gets a message with its number and affects only its problem. A
/// line whose first word names no problem of the module (a claimed identity or seed, say) is a
/// note and changes no grade; a note quotes at most 60 characters of its line.
///
/// The text. A UTF-8 byte-order mark (EF BB BF) at the start is skipped; lines end in LF or CRLF,
/// the last one with or without. The rest must be UTF-8 without a NUL byte (binary data): else
/// nothing is read and AnswerFile::not_text says, with `name` (the file's path), where the first
/// bad byte is: its line and its column, counted in characters from 1 after the mark, e.g.
/// "answers.txt is not plain UTF-8 text: line 3, column 4: the byte 0xE9 is not UTF-8 (saved as
/// Latin-1 or Windows-1252?); save it as plain UTF-8 text (...)". Bad bytes are those of no UTF-8
/// character: a stray continuation byte, an overlong form, a surrogate, a code point above
/// U+10FFFF, a character cut off at the end. One pass over the text: the time is linear in its size.
AnswerFile read_answers(const std::string& text, const std::vector<std::string>& ids,
                        const std::string& name = "the answers file");
/// read_answers() of the file at `path` (its bytes as they are), named by its path; found = false
/// when it cannot be opened.
AnswerFile read_answers_file(const std::string& path, const std::vector<std::string>& ids);

/// The grade of one problem.
struct Grade {
  bool passed = false;
  int line = 0;         ///< line of the answer (0: none)
  std::string message;  ///< "correct", or the feedback: the likely mistake, or why not read
};

/// Checks the format of `problem`'s answer in `file` (one line, readable, the right shape and a
/// unit of the right dimension): std::nullopt when fine, else the failing grade.
std::optional<Grade> check_format(const Problem& problem, const AnswerFile& file);
/// Grades `problem`'s answer in `file` against `solution`: the format first, then the value
/// within the tolerance; a wrong value is named after the first mistake it matches (the
/// problem's own, then the sign, a factor of 2, degrees against radians, a unit's scale, the
/// transpose).
Grade grade(const Problem& problem, const Solution& solution, const AnswerFile& file);

/// What a module's program knows besides its problems (compiled-in definitions).
struct ProgramConfig {
  std::string module_tag;     ///< "M01"
  std::string answers_path;   ///< default of --answers: the module folder's answers.txt
  std::string worked_path;    ///< solutions/moduleNN_*/problems.md (may not exist)
  bool has_reference = true;  ///< false: a format-only build (a copy without the reference)
};

/// The message of a format-only build for an answer whose format is fine.
inline constexpr const char* kFormatOnly =
    "format OK; the value is graded by your instructor's grader (this copy has no reference)";

/// The program of a module (problems/main.cpp):
///   --fmbd-list                    one line per problem, "MnnPk: title<TAB>[Mnn][Pk][points=p]"
///   --fmbd-token-fd 3 ... "NAME"   grades one problem (NAME in Catch's escaping, or the bare
///                                  id); on a pass prints "fmbd-completion-token: <token>" and
///                                  exits 0, else prints the feedback and exits 1
///   --check                        the format of every line of the answers file
///   --print [ID]                   the statements of the student's variant
///   --worked [ID]                  the worked solution: problems.md, then the variant's numbers
///   --model-answers                a correct answers file of the variant (with the reference)
///   --template                     an answers file to fill in: every line commented out
///   --answers FILE                 the answers file (default: config.answers_path, or
///                                  $FMBD_ANSWERS_ROOT/<its module folder>/answers.txt where the
///                                  front end sets FMBD_ANSWERS_ROOT)
///   --student NAME                 the identity for --print and --worked (else FMBD_STUDENT)
/// Grading takes the identity from FMBD_STUDENT only. FMBD_ANSWERS_ROOT and FMBD_STUDENT are the
/// grade driver's protocol (autograder/driver/grade.cpp, "The environment"). Everything goes to
/// std::cout, and stays short: it prints at most 10 notes of the answers file and then how many
/// more there are (the driver keeps the first 64 KiB of a test's output), and a file that
/// is not text gets its one message (AnswerFile::not_text), as the feedback of every problem and
/// once under --check. An exception (the engine's, or running out of memory) is reported in the
/// same way: a grade fails with "the program of the problems failed: WHAT" in Catch's compact
/// form, which the driver shows; another mode prints that message after "error: " and exits 2.
/// Exit status: 0 done (a graded problem passed), 1 a graded problem failed, 2 a usage error
/// (or an exception outside a grade).
int run_program(const std::vector<Problem>& problems, const ProgramConfig& config, int argc, char** argv);

}  // namespace fmbd::problems
