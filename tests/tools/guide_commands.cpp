// fmbd-guide-commands: the ./workbook command lines of guides, or those that scripts run, one a
// line from ./workbook on.
//
//   fmbd-guide-commands guide FILE.md...   each line of a code block (fenced, or indented by four
//                                          spaces) that runs ./workbook; not an inline mention
//                                          in prose; a trailing "# comment" is dropped
//   fmbd-guide-commands run SCRIPT...      each ./workbook (or "$dir/workbook") at a command's
//                                          place in code: not inside a string, a grep pattern or
//                                          a comment; printed to the end of its line, with
//                                          "$dir/workbook" shown as ./workbook
//
// A command's place is the start of a line, or after &&, ||, ; ( { | !, if, then, do or else,
// with only env (-u NAME), nice -n N and assignments between. Continued lines are one.
// Exits 2 for a wrong command line or a file it cannot read.
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

bool is_word(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

bool read_text(const std::string& file, std::string& text) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    std::cerr << file << ": " << std::strerror(errno) << "\n";
    return false;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  text = buffer.str();
  return true;
}

// "./workbook" at `at`, as a whole word.
bool workbook_at(const std::string& line, std::size_t at) {
  static const std::string word = "./workbook";
  return line.compare(at, word.size(), word) == 0 &&
         (at + word.size() == line.size() || !is_word(line[at + word.size()]));
}

// The command of a code-block line ("  $ ./workbook ..." or "./workbook ..."), or "".
std::string block_command(const std::string& line) {
  std::size_t at = 0;
  while (at < line.size() && is_space(line[at])) ++at;
  if (at < line.size() && line[at] == '$' && at + 1 < line.size() && is_space(line[at + 1])) {
    ++at;
    while (at < line.size() && is_space(line[at])) ++at;
  }
  if (!workbook_at(line, at)) return "";
  std::string command = line.substr(at);
  // A trailing comment: the first run of white space that a # follows.
  for (std::size_t k = 0; k < command.size(); ++k) {
    if (!is_space(command[k])) continue;
    std::size_t end = k;
    while (end < command.size() && is_space(command[end])) ++end;
    if (end < command.size() && command[end] == '#') return command.substr(0, k);
    k = end - 1;
  }
  return command;
}

// Four or more spaces, then ./workbook: an indented code block's command.
bool indented_command(const std::string& line) {
  std::size_t spaces = 0;
  while (spaces < line.size() && line[spaces] == ' ') ++spaces;
  return spaces >= 4 && workbook_at(line, spaces);
}

void guide_commands(const std::string& text) {
  bool fence = false;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::size_t at = 0;
    while (at < line.size() && is_space(line[at])) ++at;
    if (line.compare(at, 3, "```") == 0) {
      fence = !fence;
      continue;
    }
    if (!fence && !indented_command(line)) continue;
    const std::string command = block_command(line);
    if (!command.empty()) std::cout << command << "\n";
  }
}

// The length of a workbook word at `at` (./workbook, "$dir/workbook" or "${dir}/workbook") that
// white space, ')', ';' or the end follows; 0 if there is none.
std::size_t workbook_word(const std::string& text, std::size_t at) {
  std::size_t end = 0;
  if (text.compare(at, 10, "./workbook") == 0) {
    end = at + 10;
  } else if (text.compare(at, 2, "\"$") == 0) {
    std::size_t k = at + 2;
    if (k < text.size() && text[k] == '{') ++k;
    const std::size_t name = k;
    while (k < text.size() && is_word(text[k])) ++k;
    if (k == name) return 0;
    if (k < text.size() && text[k] == '}') ++k;
    if (text.compare(k, 10, "/workbook\"") != 0) return 0;
    end = k + 10;
  } else {
    return 0;
  }
  if (end < text.size() && !is_space(text[end]) && text[end] != ')' && text[end] != ';') return 0;
  return end - at;
}

// Whether the text of a line before a workbook word puts it at a command's place.
bool at_command_place(const std::string& before) {
  static const std::regex prefix(
      R"((?:\s*(?:env(?:\s+-u\s+\w+)*|nice\s+-n\s+\d+|\w+=(?:"[^"]*"|\S*)))*\s*$)");
  static const std::regex place(R"((?:^|&&|\|\||[;({|!]|\bif|\bthen|\bdo|\belse)\s*$)");
  const std::string rest = std::regex_replace(before, prefix, "", std::regex_constants::format_first_only);
  return std::regex_search(rest, place);
}

// The line from a workbook word on, with "$dir/workbook" shown as ./workbook.
std::string run_line(const std::string& text, std::size_t at) {
  const std::size_t end = text.find('\n', at);
  std::string line = text.substr(at, end == std::string::npos ? std::string::npos : end - at);
  if (!line.empty() && line[0] == '"') {
    const std::size_t close = line.find('"', 1);
    if (close != std::string::npos) line = "./workbook" + line.substr(close + 1);
  }
  return line;
}

// The text with each backslash-newline one space: continued lines are one.
std::string joined(const std::string& raw) {
  std::string text;
  for (std::size_t k = 0; k < raw.size(); ++k) {
    if (raw[k] == '\\' && k + 1 < raw.size() && raw[k + 1] == '\n') {
      text += ' ';
      ++k;
    } else {
      text += raw[k];
    }
  }
  return text;
}

void run_commands(const std::string& raw) {
  const std::string text = joined(raw);
  std::vector<char> stack{'c'};  // c code, p code in ( ) or $( ), d a "string", s a 'string'
  std::size_t start = 0;         // where the current line began
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const char top = stack.back();
    if (c == '\n') {
      start = i + 1;
      continue;
    }
    if (top == 's') {
      if (c == '\'') stack.pop_back();
      continue;
    }
    if (top == 'd') {
      if (c == '\\') {
        ++i;
      } else if (c == '"') {
        stack.pop_back();
      } else if (text.compare(i, 2, "$(") == 0) {
        stack.push_back('p');
        ++i;
      }
      continue;
    }
    if (c == '#' && (i == start || is_space(text[i - 1]))) {  // a comment
      const std::size_t end = text.find('\n', i);
      i = (end == std::string::npos ? text.size() : end) - 1;
      continue;
    }
    if (workbook_word(text, i) > 0 && at_command_place(text.substr(start, i - start)))
      std::cout << run_line(text, i) << "\n";
    if (c == '\\') ++i;
    else if (c == '\'') stack.push_back('s');
    else if (c == '"') stack.push_back('d');
    else if (c == '(') stack.push_back('p');
    else if (c == ')' && top == 'p') stack.pop_back();
  }
}

}  // namespace

int main(int argc, char** argv) {
  const fmbd::cli::Command command = fmbd::cli::program("fmbd-guide-commands", {}, "FILE", -1, "guide|run FILE...");
  fmbd::cli::Parsed parsed;
  if (const auto status = fmbd::cli::parse_program(command, argc, argv, parsed)) return *status;
  const std::vector<std::string>& args = parsed.positionals;
  const std::string mode = args.empty() ? "" : args.front();
  if (mode != "guide" && mode != "run") {
    std::cerr << fmbd::cli::program_usage(command);
    return 2;
  }
  for (std::size_t k = 1; k < args.size(); ++k) {
    std::string text;
    if (!read_text(args[k], text)) return 2;
    if (mode == "guide") guide_commands(text);
    else run_commands(text);
  }
  return 0;
}
