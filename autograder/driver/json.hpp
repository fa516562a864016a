#pragma once
// A small JSON value, a strict parser and a writer, for the course manifest (course.json) that
// the front end reads, and every JSON file the grader writes (the driver's results.json, the
// front end's). Numbers are written in the fewest digits that read back as the same double.
//
// Strict means RFC 8259 and nothing more: no comments, no trailing commas, no single quotes, no
// NaN; a duplicate key in one object is an error too (the manifest's readers would see only one
// of the two). Numbers are doubles. Objects keep the order of their keys.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace fmbd::json {

class Value;
using Array = std::vector<Value>;
using Object = std::vector<std::pair<std::string, Value>>;  // in the order written

// What a JSON text can be: null, true/false, a number, a string, an array or an object.
class Value {
 public:
  enum class Kind { null, boolean, number, string, array, object };

  Value() = default;  // null
  Value(std::nullptr_t) {}
  Value(bool value) : data_(value) {}
  Value(double value) : data_(value) {}
  Value(int value) : data_(static_cast<double>(value)) {}
  Value(std::string value) : data_(std::move(value)) {}
  Value(const char* value) : data_(std::string(value)) {}
  Value(Array value) : data_(std::move(value)) {}
  Value(Object value) : data_(std::move(value)) {}

  Kind kind() const { return static_cast<Kind>(data_.index()); }
  bool is_null() const { return kind() == Kind::null; }

  // The value as its kind; std::logic_error when it is of another kind (check kind() first).
  bool as_bool() const;
  double as_number() const;
  const std::string& as_string() const;
  const Array& as_array() const;
  const Object& as_object() const;
  Array& as_array();
  Object& as_object();

  // The member `key` of an object, or nullptr (also when this is not an object).
  const Value* find(std::string_view key) const;

  friend bool operator==(const Value& a, const Value& b) { return a.data_ == b.data_; }
  friend bool operator!=(const Value& a, const Value& b) { return !(a == b); }

 private:
  std::variant<std::monostate, bool, double, std::string, Array, Object> data_;
};

// The name of a kind, for messages: "null", "a boolean", "a number", "a string", "an array",
// "an object".
std::string kind_name(Value::Kind kind);

// A malformed JSON text: what() is "line L, column C: what was wrong"; line and column count
// from 1, the column in bytes.
class ParseError : public std::runtime_error {
 public:
  ParseError(std::size_t line, std::size_t column, const std::string& message);
  std::size_t line() const { return line_; }
  std::size_t column() const { return column_; }

 private:
  std::size_t line_;
  std::size_t column_;
};

// The value of a complete JSON text (white space around it allowed, nothing else). Strings are
// taken as UTF-8; \uXXXX escapes, surrogate pairs included, become UTF-8. Throws ParseError.
Value parse(std::string_view text);

// The JSON text of `value`: with indent 0 on one line (", " and ": " between items), otherwise
// an item per line indented by `indent` spaces a level. Strings go through the grade driver's
// json_string (UTF-8 repaired, control characters escaped); whole numbers up to 2^53 are written
// without a fraction, others with 17 significant digits. No newline at the end.
std::string write(const Value& value, int indent = 2);

}  // namespace fmbd::json
