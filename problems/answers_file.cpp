// The answers file (problems.hpp: read_answers): the text check, the grammar of a line, the file.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <utility>

#include "problems.hpp"
#include "problem_text.hpp"

namespace fmbd::problems {

namespace {

using text::excerpt;
using text::is_blank;
using text::trim;
using text::upper;

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
    if (!is_decimal(word)) return fail(error, "\"" + excerpt(word) + "\" is not a number (write 1.5, -2 or 3.1e-4)");
    x = std::strtod(word.c_str(), nullptr);
    if (!std::isfinite(x)) return fail(error, "\"" + excerpt(word) + "\" is out of range");
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

// The length of the UTF-8 character at text[i], or 0 when the bytes there are no character
// (a stray continuation byte, an overlong form, a surrogate, above U+10FFFF, cut off).
std::size_t character_length(const std::string& text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return k < text.size() ? static_cast<unsigned char>(text[k]) : 0u; };
  const unsigned lead = byte(i);
  std::size_t length = 0;
  unsigned low = 0x80;  // the range of the second byte
  unsigned high = 0xBF;
  if (lead < 0x80) return 1;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) low = 0xA0;   // overlong below U+0800
    if (lead == 0xED) high = 0x9F;  // the surrogates U+D800..U+DFFF
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) low = 0x90;   // overlong below U+10000
    if (lead == 0xF4) high = 0x8F;  // above U+10FFFF
  } else {
    return 0;
  }
  if (byte(i + 1) < low || byte(i + 1) > high) return 0;
  for (std::size_t k = 2; k < length; ++k) {
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  }
  return length;
}

// Why `text` is not UTF-8 text without NUL bytes, with the line and column (in characters, from 1)
// of the first bad byte; std::nullopt when it is.
std::optional<std::pair<int, std::string>> not_text(const std::string& text, const std::string& name) {
  int line = 1;
  int column = 1;
  for (std::size_t i = 0; i < text.size(); ++column) {
    const std::size_t length = text[i] == '\0' ? 0 : character_length(text, i);
    if (length == 0) {
      char byte[8];
      std::snprintf(byte, sizeof byte, "0x%02X", static_cast<unsigned>(static_cast<unsigned char>(text[i])));
      const std::string what = text[i] == '\0' ? std::string("a NUL byte (binary data?)")
                                               : "the byte " + std::string(byte) +
                                                     " is not UTF-8 (saved as Latin-1 or Windows-1252?)";
      return std::make_pair(line, name + " is not plain UTF-8 text: line " + std::to_string(line) + ", column " +
                                      std::to_string(column) + ": " + what +
                                      "; save it as plain UTF-8 text (in your editor: save with the encoding UTF-8)");
    }
    if (text[i] == '\n') {
      ++line;
      column = 0;
    }
    i += length;
  }
  return std::nullopt;
}

// The answer on `line` (its number `number`) of problem `id`, the id's `end` in the line.
Answer read_line(const std::string& line, int number, const std::string& id, std::size_t end) {
  const std::string where = "line " + std::to_string(number) + ": ";
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
  return a;
}

}  // namespace

AnswerFile read_answers(const std::string& text, const std::vector<std::string>& ids, const std::string& name) {
  AnswerFile file;
  const std::size_t bom = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;  // a byte-order mark: no text
  const std::string body = text.substr(bom);
  if (const auto fault = not_text(body, name)) {
    file.not_text_line = fault->first;
    file.not_text = fault->second;
    return file;
  }
  std::string known;
  for (const std::string& k : ids) known += (known.empty() ? "" : ", ") + k;
  std::istringstream in(body);
  int number = 0;
  for (std::string raw; std::getline(in, raw);) {
    ++number;
    const std::string line = trim(raw.substr(0, raw.find('#')));
    if (line.empty()) continue;
    std::size_t end = 0;
    while (end < line.size() && std::isalnum(static_cast<unsigned char>(line[end]))) ++end;
    const std::string id = upper(line.substr(0, end));
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) {
      file.notes.push_back("line " + std::to_string(number) + ": \"" + excerpt(trim(raw)) +
                           "\" names no problem of this module (" + known + "); the line is ignored");
      continue;
    }
    file.answers[id].push_back(read_line(line, number, id, end));
  }
  return file;
}

AnswerFile read_answers_file(const std::string& path, const std::vector<std::string>& ids) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    AnswerFile file;
    file.found = false;
    return file;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return read_answers(text.str(), ids, path);
}

}  // namespace fmbd::problems
