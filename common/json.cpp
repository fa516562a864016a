#include "json.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

namespace fmbd::json {

ParseError::ParseError(std::size_t line, std::size_t column, const std::string& message)
    : std::runtime_error(line == 0 ? message
                                   : "line " + std::to_string(line) + ", column " + std::to_string(column) + ": " +
                                         message),
      line_(line),
      column_(column) {}

namespace {

// The library's words for `error`, without its "[json.exception.NAME] " and "parse error at
// line L, column C: " in front.
std::string words_of(const nlohmann::json::exception& error) {
  std::string words = error.what();
  if (!words.empty() && words.front() == '[' && words.find("] ") != std::string::npos) {
    words.erase(0, words.find("] ") + 2);
  }
  if (words.rfind("parse error", 0) == 0 && words.find(": ") != std::string::npos) {
    words.erase(0, words.find(": ") + 2);
  }
  return words;
}

// The library's parse error as ParseError, with the line and column of the byte where it stopped
// (the last one it read, counted from 1; one past the end at the end of the text).
ParseError parse_error(std::string_view text, const nlohmann::json::parse_error& error) {
  const std::size_t at = std::min<std::size_t>(error.byte == 0 ? 0 : error.byte - 1, text.size());
  const std::size_t line_start = at == 0 ? 0 : text.rfind('\n', at - 1) + 1;  // npos + 1 == 0
  const std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + line_start, '\n'));
  return ParseError(line, at - line_start + 1, words_of(error));
}

}  // namespace

Value parse(std::string_view text) {
  std::vector<std::set<std::string>> keys;  // those of every object that is open
  const Value::parser_callback_t unique_keys = [&keys](int, Value::parse_event_t event, Value& parsed) {
    if (event == Value::parse_event_t::object_start) keys.emplace_back();
    if (event == Value::parse_event_t::object_end) keys.pop_back();
    if (event == Value::parse_event_t::key && !keys.back().insert(parsed.get<std::string>()).second) {
      throw ParseError(0, 0, "duplicate key \"" + parsed.get<std::string>() + "\"");
    }
    return true;
  };
  try {
    return Value::parse(text.data(), text.data() + text.size(), unique_keys);
  } catch (const Value::parse_error& error) {
    throw parse_error(text, error);
  } catch (const Value::exception& error) {  // a number out of range: the library does not say where
    throw ParseError(0, 0, words_of(error));
  }
}

std::string write(const Value& value) { return value.dump(2, ' ', false, Value::error_handler_t::replace); }

Value whole_or_fraction(double number) {
  if (std::floor(number) == number && std::fabs(number) <= 9007199254740992.0) {
    return static_cast<std::int64_t>(number);
  }
  return number;
}

std::string kind_name(Value::value_t kind) {
  switch (kind) {
    case Value::value_t::null: return "null";
    case Value::value_t::boolean: return "a boolean";
    case Value::value_t::number_integer:
    case Value::value_t::number_unsigned:
    case Value::value_t::number_float: return "a number";
    case Value::value_t::string: return "a string";
    case Value::value_t::array: return "an array";
    case Value::value_t::object: return "an object";
    default: return "binary data";
  }
}

}  // namespace fmbd::json
