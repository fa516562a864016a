#include "json.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "text.hpp"

namespace fmbd::json {

bool Value::as_bool() const {
  if (kind() != Kind::boolean) throw std::logic_error("json: not a boolean");
  return std::get<bool>(data_);
}

double Value::as_number() const {
  if (kind() != Kind::number) throw std::logic_error("json: not a number");
  return std::get<double>(data_);
}

const std::string& Value::as_string() const {
  if (kind() != Kind::string) throw std::logic_error("json: not a string");
  return std::get<std::string>(data_);
}

const Array& Value::as_array() const {
  if (kind() != Kind::array) throw std::logic_error("json: not an array");
  return std::get<Array>(data_);
}

const Object& Value::as_object() const {
  if (kind() != Kind::object) throw std::logic_error("json: not an object");
  return std::get<Object>(data_);
}

Array& Value::as_array() {
  if (kind() != Kind::array) throw std::logic_error("json: not an array");
  return std::get<Array>(data_);
}

Object& Value::as_object() {
  if (kind() != Kind::object) throw std::logic_error("json: not an object");
  return std::get<Object>(data_);
}

const Value* Value::find(std::string_view key) const {
  if (kind() != Kind::object) return nullptr;
  for (const auto& [name, value] : std::get<Object>(data_)) {
    if (name == key) return &value;
  }
  return nullptr;
}

std::string kind_name(Value::Kind kind) {
  switch (kind) {
    case Value::Kind::null: return "null";
    case Value::Kind::boolean: return "a boolean";
    case Value::Kind::number: return "a number";
    case Value::Kind::string: return "a string";
    case Value::Kind::array: return "an array";
    case Value::Kind::object: return "an object";
  }
  return "?";
}

ParseError::ParseError(std::size_t line, std::size_t column, const std::string& message)
    : std::runtime_error("line " + std::to_string(line) + ", column " + std::to_string(column) + ": " + message),
      line_(line),
      column_(column) {}

namespace {

constexpr int kMaxDepth = 256;  // deeper nesting is refused rather than overflowing the stack

// A recursive-descent parser over the text, which knows its position for errors.
class Parser {
 public:
  explicit Parser(std::string_view text) : text_(text) {}

  Value document() {
    skip_space();
    Value value = parse_value(0);
    skip_space();
    if (pos_ < text_.size()) fail("unexpected " + describe_here() + " after the value");
    return value;
  }

 private:
  [[noreturn]] void fail(const std::string& message) const { fail_at(pos_, message); }

  [[noreturn]] void fail_at(std::size_t at, const std::string& message) const {
    std::size_t line = 1;
    std::size_t column = 1;
    for (std::size_t i = 0; i < at && i < text_.size(); ++i) {
      if (text_[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    throw ParseError(line, column, message);
  }

  std::string describe_here() const {
    if (pos_ >= text_.size()) return "end of text";
    const auto c = static_cast<unsigned char>(text_[pos_]);
    if (c >= 0x20 && c < 0x7F) return std::string("'") + text_[pos_] + "'";
    char code[8];
    std::snprintf(code, sizeof code, "0x%02X", c);
    return std::string("byte ") + code;
  }

  void skip_space() {
    while (pos_ < text_.size() &&
           (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\n' || text_[pos_] == '\r')) {
      ++pos_;
    }
  }

  bool take(char c) {
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }

  void expect_word(std::string_view word) {
    if (text_.substr(pos_, word.size()) != word) fail("unexpected " + describe_here());
    pos_ += word.size();
  }

  Value parse_value(int depth) {
    if (depth > kMaxDepth) fail("nested deeper than " + std::to_string(kMaxDepth) + " levels");
    if (pos_ >= text_.size()) fail("unexpected end of text, where a value belongs");
    switch (text_[pos_]) {
      case '{': return parse_object(depth);
      case '[': return parse_array(depth);
      case '"': return parse_string();
      case 't': expect_word("true"); return Value(true);
      case 'f': expect_word("false"); return Value(false);
      case 'n': expect_word("null"); return Value();
      default:
        if (text_[pos_] == '-' || (text_[pos_] >= '0' && text_[pos_] <= '9')) return parse_number();
        fail("unexpected " + describe_here() + ", where a value belongs");
    }
  }

  Value parse_object(int depth) {
    ++pos_;  // '{'
    Object object;
    skip_space();
    if (take('}')) return object;
    for (;;) {
      skip_space();
      if (pos_ >= text_.size() || text_[pos_] != '"') fail("expected a key (a string), found " + describe_here());
      const std::size_t key_at = pos_;
      std::string key = parse_string();
      for (const auto& member : object) {
        if (member.first == key) fail_at(key_at, "duplicate key \"" + key + "\"");
      }
      skip_space();
      if (!take(':')) fail("expected ':' after the key, found " + describe_here());
      skip_space();
      Value value = parse_value(depth + 1);
      object.emplace_back(std::move(key), std::move(value));
      skip_space();
      if (take('}')) return object;
      if (!take(',')) fail("expected ',' or '}' in the object, found " + describe_here());
    }
  }

  Value parse_array(int depth) {
    ++pos_;  // '['
    Array array;
    skip_space();
    if (take(']')) return array;
    for (;;) {
      skip_space();
      array.push_back(parse_value(depth + 1));
      skip_space();
      if (take(']')) return array;
      if (!take(',')) fail("expected ',' or ']' in the array, found " + describe_here());
    }
  }

  Value parse_number() {
    const std::size_t start = pos_;
    const auto digits = [this] {
      const std::size_t from = pos_;
      while (pos_ < text_.size() && text_[pos_] >= '0' && text_[pos_] <= '9') ++pos_;
      return pos_ - from;
    };
    take('-');
    if (take('0')) {
      if (pos_ < text_.size() && text_[pos_] >= '0' && text_[pos_] <= '9') fail("a number may not start with 0");
    } else if (digits() == 0) {
      fail("expected a digit, found " + describe_here());
    }
    if (take('.') && digits() == 0) fail("expected a digit after '.', found " + describe_here());
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      ++pos_;
      if (!take('+')) take('-');
      if (digits() == 0) fail("expected a digit in the exponent, found " + describe_here());
    }
    const std::string literal(text_.substr(start, pos_ - start));
    const double value = std::strtod(literal.c_str(), nullptr);
    if (!std::isfinite(value)) fail_at(start, "number " + literal + " is out of range");
    return Value(value);
  }

  unsigned hex4() {
    if (pos_ + 4 > text_.size()) fail("expected four hex digits after \\u");
    unsigned code = 0;
    for (int i = 0; i < 4; ++i) {
      const char c = text_[pos_];
      code <<= 4;
      if (c >= '0' && c <= '9') code |= static_cast<unsigned>(c - '0');
      else if (c >= 'a' && c <= 'f') code |= static_cast<unsigned>(c - 'a' + 10);
      else if (c >= 'A' && c <= 'F') code |= static_cast<unsigned>(c - 'A' + 10);
      else fail("expected a hex digit in \\u escape, found " + describe_here());
      ++pos_;
    }
    return code;
  }

  static void append_utf8(std::string& out, unsigned code) {
    if (code < 0x80) {
      out += static_cast<char>(code);
    } else if (code < 0x800) {
      out += static_cast<char>(0xC0 | (code >> 6));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
      out += static_cast<char>(0xE0 | (code >> 12));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (code >> 18));
      out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    }
  }

  std::string parse_string() {
    ++pos_;  // '"'
    std::string out;
    for (;;) {
      if (pos_ >= text_.size()) fail("unterminated string");
      const char c = text_[pos_];
      if (c == '"') {
        ++pos_;
        return out;
      }
      if (static_cast<unsigned char>(c) < 0x20) fail("control character in a string (escape it)");
      if (c != '\\') {
        out += c;
        ++pos_;
        continue;
      }
      ++pos_;
      if (pos_ >= text_.size()) fail("unterminated string");
      const char e = text_[pos_++];
      switch (e) {
        case '"': out += '"'; break;
        case '\\': out += '\\'; break;
        case '/': out += '/'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': {
          unsigned code = hex4();
          if (code >= 0xD800 && code <= 0xDBFF) {  // a high surrogate: its low one must follow
            if (!take('\\') || !take('u')) fail("a high surrogate \\u escape without its low surrogate");
            const unsigned low = hex4();
            if (low < 0xDC00 || low > 0xDFFF) fail("a high surrogate \\u escape without its low surrogate");
            code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
          } else if (code >= 0xDC00 && code <= 0xDFFF) {
            fail("a low surrogate \\u escape without its high surrogate");
          }
          append_utf8(out, code);
          break;
        }
        default:
          --pos_;
          fail("unknown escape \\" + describe_here().substr(1, 1));
      }
    }
  }

  std::string_view text_;
  std::size_t pos_ = 0;
};

std::string number_text(double value) {
  if (std::floor(value) == value && std::fabs(value) <= 9007199254740992.0) {
    return std::to_string(static_cast<long long>(value));
  }
  char buffer[32];
  for (int digits = 15; digits <= 17; ++digits) {  // the shortest of these that reads back exactly
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
    if (std::strtod(buffer, nullptr) == value) break;
  }
  return buffer;
}

void write_value(std::string& out, const Value& value, int indent, int level) {
  const auto newline = [&](int at) {
    if (indent > 0) {
      out += '\n';
      out.append(static_cast<std::size_t>(indent * at), ' ');
    }
  };
  const char* separator = indent > 0 ? "," : ", ";
  switch (value.kind()) {
    case Value::Kind::null: out += "null"; return;
    case Value::Kind::boolean: out += value.as_bool() ? "true" : "false"; return;
    case Value::Kind::number: out += number_text(value.as_number()); return;
    case Value::Kind::string: out += fmbd::grade::json_string(value.as_string()); return;
    case Value::Kind::array: {
      const Array& array = value.as_array();
      out += '[';
      for (std::size_t i = 0; i < array.size(); ++i) {
        if (i > 0) out += separator;
        newline(level + 1);
        write_value(out, array[i], indent, level + 1);
      }
      if (!array.empty()) newline(level);
      out += ']';
      return;
    }
    case Value::Kind::object: {
      const Object& object = value.as_object();
      out += '{';
      for (std::size_t i = 0; i < object.size(); ++i) {
        if (i > 0) out += separator;
        newline(level + 1);
        out += fmbd::grade::json_string(object[i].first);
        out += ": ";
        write_value(out, object[i].second, indent, level + 1);
      }
      if (!object.empty()) newline(level);
      out += '}';
      return;
    }
  }
}

}  // namespace

Value parse(std::string_view text) { return Parser(text).document(); }

std::string write(const Value& value, int indent) {
  std::string out;
  write_value(out, value, indent, 0);
  return out;
}

}  // namespace fmbd::json
