#pragma once
// JSON for the grader and the front end: nlohmann/json (the package nlohmann-json3-dev, 3.10 or
// later), for the course manifest (course.json), the Gradescope metadata, compile_commands.json,
// and every results.json the grader writes. What the project adds to the library is here:
//
// - parse is strict: RFC 8259 and nothing more (no comments, no trailing commas, no NaN), and a
//   duplicate key in one object is an error too (the manifest's readers would see only one of
//   the two). Its errors say the line and column.
// - write is the one writer of results.json: two spaces a level, the strings' UTF-8 repaired.
//
// Objects keep the order of their keys (nlohmann::ordered_json).

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace fmbd::json {

using Value = nlohmann::ordered_json;

// A malformed JSON text: what() is "line L, column C: what was wrong" (the library's words,
// line and column from 1, the column in bytes), or, where the library does not say where, the
// words alone with line and column 0: "duplicate key \"K\"", "number overflow parsing '1e999'".
class ParseError : public std::runtime_error {
 public:
  ParseError(std::size_t line, std::size_t column, const std::string& message);
  std::size_t line() const { return line_; }
  std::size_t column() const { return column_; }

 private:
  std::size_t line_;
  std::size_t column_;
};

// The value of a complete JSON text (white space around it allowed, nothing else), in UTF-8 (a
// string that is not is an error).
// Throws ParseError.
Value parse(std::string_view text);

// The JSON text of `value`, an item per line indented by two spaces a level, without a newline
// at the end. Bytes that are not UTF-8 in its strings become U+FFFD. Whole numbers are written
// without a fraction only when they are integers in the Value (see whole_or_fraction).
std::string write(const Value& value);

// `number` as an integer where it is whole (points and seconds in results.json: "3", not "3.0").
Value whole_or_fraction(double number);

// The name of a kind, for messages: "null", "a boolean", "a number" (integers and others alike),
// "a string", "an array", "an object".
std::string kind_name(Value::value_t kind);

}  // namespace fmbd::json
