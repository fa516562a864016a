#pragma once
// Small text helpers shared by the grade driver: UTF-8 repair, XML escaping,
// number formatting. Test output is arbitrary bytes; everything that leaves the driver
// in a results file goes through these functions first (results.json through json.hpp's
// write, which repairs UTF-8 the same way).

#include <string>
#include <string_view>

namespace fmbd::grade {

// `text` with every byte sequence that is not well-formed UTF-8 (stray continuation
// bytes, overlong forms, surrogates, code points above U+10FFFF, truncated sequences)
// replaced by U+FFFD.
std::string repair_utf8(std::string_view text);

// `text` for use in XML 1.0 character data or a double-quoted attribute value: UTF-8
// repaired, characters that XML 1.0 forbids (most C0 controls, U+FFFE, U+FFFF) removed,
// & < > " ' escaped. In attributes, tab, newline and carriage return become character
// references so that parsers do not normalise them to spaces.
std::string xml_text(std::string_view text);
std::string xml_attribute(std::string_view text);

// One line for a terminal: UTF-8 repaired, control characters replaced by spaces,
// leading and trailing white space removed.
std::string single_line(std::string_view text);

std::string_view trim(std::string_view text);
bool starts_with(std::string_view text, std::string_view prefix);
bool contains_ignoring_case(std::string_view text, std::string_view fragment);

// `text` cut to at most `max_bytes` bytes (never inside a UTF-8 sequence), with "..."
// at the end when something was cut.
std::string shorten(std::string_view text, std::size_t max_bytes);

// Numbers for humans and for JSON: "3", "0.5", "12.25" (at most 3 decimals); seconds
// always with 3 decimals: "1.234".
std::string format_number(double value);
std::string format_seconds(double seconds);

// Whether `value` is one of Gradescope's visibilities of a test: hidden, after_due_date,
// after_published, visible (the driver's --hidden-visibility, and the front end's).
inline bool is_visibility(std::string_view value) {
  return value == "hidden" || value == "after_due_date" || value == "after_published" || value == "visible";
}

}  // namespace fmbd::grade
