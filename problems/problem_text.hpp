#pragma once
// Small text helpers shared by the files of the problems' engine (problems.cpp, program.cpp,
// answers_file.cpp); not part of its interface (problems.hpp).
//
//   is_blank(c)       space, tab, CR, LF, VT or FF
//   trim(text)        without the blanks at either end
//   upper(text)       ASCII letters in upper case, other bytes unchanged
//   excerpt(text, n)  at most n characters of UTF-8 text, "..." appended where it was cut; a cut
//                     never splits a multi-byte character (a student's line quoted in a message)
#include <cctype>
#include <cstddef>
#include <string>

namespace fmbd::problems::text {

inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

inline std::string trim(const std::string& text) {
  std::size_t begin = 0;
  std::size_t end = text.size();
  while (begin < end && is_blank(text[begin])) ++begin;
  while (end > begin && is_blank(text[end - 1])) --end;
  return text.substr(begin, end - begin);
}

inline std::string upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

inline std::string excerpt(const std::string& text, std::size_t characters = 60) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const bool starts_character = (static_cast<unsigned char>(text[i]) & 0xC0) != 0x80;
    if (starts_character && count++ == characters) return text.substr(0, i) + "...";
  }
  return text;
}

}  // namespace fmbd::problems::text
