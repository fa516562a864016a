// fmbd-function-length: lists the functions of C++ files that are longer than a limit.
//
//   fmbd-function-length [--limit N] FOLDER|FILE...
//
// Every .cpp and .hpp file under each FOLDER (recursively) is read. A function is a body `{ ... }`
// opened outside any other function whose declaration, since the last `;`, `{` or `}` at the
// same depth, holds a parameter list: `)` before the brace, perhaps followed by qualifiers
// (const, noexcept, override, a trailing return type), and no `=` before its `(` (which would be
// a variable with a lambda) nor `if`, `for`, `while`, `switch` or `catch` in front. Its length
// runs from the first line of that declaration to the line of its closing brace. Comments,
// string and character literals are skipped (raw strings R"(...)" too).
//
// Prints "FILE:LINE: NAME is N lines (limit L)" for each function beyond the limit (default 80)
// and exits 1 if there is one, 0 if none, 2 for a wrong command line or a file it cannot read.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "file_io.hpp"

namespace fs = std::filesystem;

namespace {

// The text with comments and literals blanked (newlines kept, so lines stay where they are).
std::string code_only(const std::string& text) {
  std::string out = text;
  std::size_t i = 0;
  auto blank = [&out](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to && k < out.size(); ++k)
      if (out[k] != '\n') out[k] = ' ';
  };
  while (i < text.size()) {
    if (text.compare(i, 2, "//") == 0) {
      const std::size_t end = text.find('\n', i);
      blank(i, end == std::string::npos ? text.size() : end);
      i = end == std::string::npos ? text.size() : end;
    } else if (text.compare(i, 2, "/*") == 0) {
      const std::size_t end = text.find("*/", i + 2);
      const std::size_t stop = end == std::string::npos ? text.size() : end + 2;
      blank(i, stop);
      i = stop;
    } else if (text.compare(i, 2, "R\"") == 0 && (i == 0 || !std::isalnum(static_cast<unsigned char>(text[i - 1])))) {
      const std::size_t open = text.find('(', i + 2);
      const std::string close = ")" + text.substr(i + 2, open - i - 2) + "\"";
      const std::size_t end = open == std::string::npos ? std::string::npos : text.find(close, open);
      const std::size_t stop = end == std::string::npos ? text.size() : end + close.size();
      blank(i, stop);
      i = stop;
    } else if (text[i] == '"' || (text[i] == '\'' && !(i > 0 && std::isxdigit(static_cast<unsigned char>(text[i - 1])) &&
                                                        i + 1 < text.size() && std::isxdigit(static_cast<unsigned char>(text[i + 1]))))) {
      const char quote = text[i];  // a ' between hex digits is a digit separator (1'000), not a quote
      std::size_t k = i + 1;
      while (k < text.size() && text[k] != quote && text[k] != '\n') k += text[k] == '\\' ? 2 : 1;
      blank(i, k + 1);
      i = k + 1;
    } else {
      ++i;
    }
  }
  return out;
}

bool is_word(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Whether a declaration (the text since the last ; { or } at its depth) opens a function body.
bool opens_function(std::string declaration) {
  while (!declaration.empty() && std::isspace(static_cast<unsigned char>(declaration.back()))) declaration.pop_back();
  const std::size_t close = declaration.rfind(')');
  const std::size_t open = declaration.find('(');
  if (close == std::string::npos || open == std::string::npos) return false;
  // After the parameter list only qualifiers and a trailing return type, with no parenthesis.
  const std::string tail = declaration.substr(close + 1);
  if (tail.find_first_of("(=") != std::string::npos && tail.find("->") == std::string::npos) return false;
  if (declaration.substr(0, open).find('=') != std::string::npos) return false;
  std::size_t first = declaration.find_first_not_of(" \t\n");
  std::size_t end = first;
  while (end < declaration.size() && is_word(declaration[end])) ++end;
  const std::string keyword = declaration.substr(first, end - first);
  for (const char* control : {"if", "for", "while", "switch", "catch", "else", "do", "return"})
    if (keyword == control) return false;
  return true;
}

int line_of(const std::string& text, std::size_t at) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

// The functions of one file longer than `limit`: "FILE:LINE: NAME is N lines (limit L)".
std::vector<std::string> long_functions(const std::string& path, const std::string& text, int limit) {
  const std::string code = code_only(text);
  std::vector<std::string> found;
  std::size_t statement = 0;  // where the current declaration starts
  int depth = 0, function_depth = -1;
  std::size_t function_start = 0;
  for (std::size_t i = 0; i < code.size(); ++i) {
    const char c = code[i];
    if (c == '{') {
      if (function_depth < 0 && opens_function(code.substr(statement, i - statement))) {
        function_depth = depth;
        function_start = code.find_first_not_of(" \t\n", statement);
      }
      ++depth;
      statement = i + 1;
    } else if (c == '}') {
      --depth;
      statement = i + 1;
      if (depth == function_depth) {
        const int first = line_of(code, function_start), last = line_of(code, i);
        if (last - first + 1 > limit) {
          std::string name = code.substr(function_start, code.find('(', function_start) - function_start);
          name = name.substr(name.find_last_of(" \t\n*&") == std::string::npos ? 0 : name.find_last_of(" \t\n*&") + 1);
          found.push_back(path + ":" + std::to_string(first) + ": " + name + " is " + std::to_string(last - first + 1) +
                          " lines (limit " + std::to_string(limit) + ")");
        }
        function_depth = -1;
      }
    } else if (c == ';') {
      statement = i + 1;
    }
  }
  return found;
}

}  // namespace

int main(int argc, char** argv) {
  namespace cli = fmbd::cli;
  const cli::Option limit_option{"--limit", cli::Kind::value, "N", "a positive number", "the longest (80)"};
  const cli::Command command =
      cli::program("fmbd-function-length", {limit_option}, "PATH", -1, "[--limit N] FOLDER|FILE...");
  cli::Parsed parsed;
  if (const auto status = cli::parse_program(command, argc, argv, parsed)) return *status;
  const std::string limit_text = parsed.value("--limit", "80");
  const int limit = limit_text.find_first_not_of("0123456789") == std::string::npos ? std::atoi(limit_text.c_str()) : 0;
  if (limit <= 0) {
    std::cerr << "fmbd-function-length: --limit needs a positive number\n";
    return 2;
  }
  const std::vector<std::string>& roots = parsed.positionals;
  if (roots.empty()) {
    std::cerr << cli::program_usage(command);
    return 2;
  }
  std::vector<std::string> files;
  for (const std::string& root : roots) {
    if (fs::is_regular_file(root)) files.push_back(root);
    if (!fs::is_directory(root)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
      const std::string ext = entry.path().extension().string();
      if (entry.is_regular_file() && (ext == ".cpp" || ext == ".hpp")) files.push_back(entry.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  std::size_t count = 0;
  for (const std::string& file : files) {
    std::string text;
    if (!fmbd::tools::read_file(file, text)) {
      std::cerr << file << ": error: cannot read\n";
      return 2;
    }
    for (const std::string& line : long_functions(file, text, limit)) {
      std::cout << line << "\n";
      ++count;
    }
  }
  std::cout << "fmbd-function-length: " << files.size() << " files, " << count << " function" << (count == 1 ? "" : "s")
            << " longer than " << limit << " lines\n";
  return count ? 1 : 0;
}
