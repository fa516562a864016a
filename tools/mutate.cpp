// fmbd-mutate: applies one mistake-catalogue mutant to a solution file.
//
//   fmbd-mutate MUTANT_FILE SOLUTION_FILE OUT
//       Applies every find/replace pair and writes OUT (only if its content changes).
//   fmbd-mutate --field file MUTANT_FILE
//   fmbd-mutate --field expect MUTANT_FILE
//       Prints that header field.
//
// Mutant file format (autograder/mistakes/moduleNN_x/<name>.mutant):
//   # one or more comment lines: the typical student mistake
//   file: joints.cpp                 (relative to the module's solutions folder)
//   expect: phrase the graded tests print when they catch the mutant
//   @@ find
//   <one or more whole lines, exactly as in the solution, indentation included>
//   @@ replace
//   <zero or more lines>
//   @@ find                          (further pairs, optional)
//   ...
//   @@ end
//
// A find block matches whole consecutive lines. Every find block must occur exactly
// once in the unmodified solution, find blocks must not overlap, and a replacement
// must differ from its find block, so a mutant that no longer applies after the
// solution changed fails the build. Errors are reported as MUTANT:line: error: ...
// with exit status 1; usage and I/O errors exit with status 2.

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "cli.hpp"
#include "file_io.hpp"
#include "strings.hpp"

namespace {

namespace fs = std::filesystem;

using fmbd::tools::read_file;
using fmbd::tools::write_if_changed;

struct Lines {
  std::vector<std::string> lines;
  bool final_newline = true;
};

// Splits at '\n' and remembers whether the text ended with one, so that joining
// reproduces the text byte for byte.
Lines split_lines(const std::string& content) {
  return Lines{fmbd::tools::split_lines(content), content.empty() || content.back() == '\n'};
}

std::string join_lines(const Lines& text) {
  std::string out;
  for (std::size_t i = 0; i < text.lines.size(); ++i) {
    out += text.lines[i];
    if (i + 1 < text.lines.size() || text.final_newline) out += '\n';
  }
  return out;
}

std::string strip(const std::string& s) { return fmbd::tools::trim(s, " \t\r"); }

using fmbd::tools::starts_with;

struct Diagnostic {
  std::size_t line;
  std::string message;
};

struct Pair {
  std::size_t find_line = 0;  // line of "@@ find" in the mutant file
  std::vector<std::string> find;
  std::vector<std::string> replace;
};

struct Mutant {
  std::string file;
  std::string expect;
  std::size_t file_line = 0;
  std::size_t expect_line = 0;
  std::vector<Pair> pairs;
};

void print_block(std::ostream& os, const std::vector<std::string>& block) {
  for (const std::string& line : block) os << "  | " << line << '\n';
}

// A header line "file: NAME" or "expect: PHRASE" of a mutant into its field.
void read_header_field(const std::string& trimmed, std::size_t number, Mutant& mutant,
                       std::vector<Diagnostic>& diagnostics) {
  const std::size_t colon = trimmed.find(':');
  const std::string key = colon == std::string::npos ? "" : strip(trimmed.substr(0, colon));
  const std::string value = colon == std::string::npos ? "" : strip(trimmed.substr(colon + 1));
  std::string* field = key == "file" ? &mutant.file : key == "expect" ? &mutant.expect : nullptr;
  std::size_t* field_line = key == "file" ? &mutant.file_line : &mutant.expect_line;
  if (field == nullptr) {
    diagnostics.push_back({number, "unexpected line in the header; expected '# comment', 'file: NAME', "
                                   "'expect: PHRASE' or '@@ find'"});
  } else if (*field_line != 0) {
    diagnostics.push_back(
        {number, "duplicate '" + key + ":' field (first given at line " + std::to_string(*field_line) + ")"});
  } else if (value.empty()) {
    diagnostics.push_back({number, "empty '" + key + ":' field"});
    *field_line = number;
  } else if (value.find(';') != std::string::npos) {
    diagnostics.push_back({number, "'" + key + ":' must not contain ';' (it is read as a CMake list)"});
    *field_line = number;
  } else {
    *field = value;
    *field_line = number;
  }
}

enum class MutantState { Header, Find, Replace, Done };

// One line of a mutant file in its state: the state after it.
MutantState read_mutant_line(MutantState state, const std::string& line, std::size_t number, Mutant& mutant,
                             std::size_t& comments, std::vector<Diagnostic>& diagnostics) {
  const std::string trimmed = strip(line);
  const bool directive = starts_with(trimmed, "@@");
  switch (state) {
    case MutantState::Header:
      if (trimmed.empty()) return state;
      if (trimmed[0] == '#') {
        ++comments;
      } else if (trimmed == "@@ find") {
        mutant.pairs.push_back({number, {}, {}});
        return MutantState::Find;
      } else if (directive) {
        diagnostics.push_back({number, "'" + trimmed + "' before the first '@@ find'"});
      } else {
        read_header_field(trimmed, number, mutant, diagnostics);
      }
      return state;
    case MutantState::Find:
      if (trimmed == "@@ replace") return MutantState::Replace;
      if (directive) {
        diagnostics.push_back({number, "'" + trimmed + "' where '@@ replace' was expected (the find block at line " +
                                           std::to_string(mutant.pairs.back().find_line) + " has no replacement)"});
      } else {
        mutant.pairs.back().find.push_back(line);
      }
      return state;
    case MutantState::Replace:
      if (trimmed == "@@ find") {
        mutant.pairs.push_back({number, {}, {}});
        return MutantState::Find;
      }
      if (trimmed == "@@ end") return MutantState::Done;
      if (directive) {
        diagnostics.push_back({number, "'" + trimmed + "' inside a replace block; expected '@@ find' or '@@ end'"});
      } else {
        mutant.pairs.back().replace.push_back(line);
      }
      return state;
    case MutantState::Done:
      if (!trimmed.empty()) diagnostics.push_back({number, "text after '@@ end'"});
      return state;
  }
  return state;
}

// The checks of a whole mutant once read: its end, its comment, its fields and its pairs.
void check_mutant(MutantState state, std::size_t lines, std::size_t comments, const Mutant& mutant,
                  std::vector<Diagnostic>& diagnostics) {
  const std::size_t last = std::max<std::size_t>(lines, 1);
  if (state == MutantState::Header) {
    diagnostics.push_back({last, "no '@@ find' block"});
  } else if (state != MutantState::Done) {
    diagnostics.push_back({last, "missing '@@ end' at the end of the mutant"});
  }
  if (comments == 0) diagnostics.push_back({1, "missing '# ...' comment lines describing the student mistake"});
  if (mutant.file_line == 0) diagnostics.push_back({1, "missing 'file:' field"});
  if (mutant.expect_line == 0) diagnostics.push_back({1, "missing 'expect:' field"});
  if (!mutant.file.empty()) {
    const fs::path file(mutant.file);
    bool escapes = file.is_absolute();
    for (const fs::path& part : file)
      if (part == "..") escapes = true;
    if (escapes) diagnostics.push_back({mutant.file_line, "'file:' must be relative to the module's solutions folder"});
  }
  for (const Pair& pair : mutant.pairs) {
    if (pair.find.empty()) {
      diagnostics.push_back({pair.find_line, "empty find block"});
    } else if (pair.find == pair.replace) {
      diagnostics.push_back(
          {pair.find_line, "the replacement is identical to the find block; the mutant would change nothing"});
    }
  }
}

std::vector<Diagnostic> parse_mutant(const std::string& content, Mutant& mutant) {
  std::vector<Diagnostic> diagnostics;
  MutantState state = MutantState::Header;
  std::size_t comments = 0;
  const Lines text = split_lines(content);
  for (std::size_t i = 0; i < text.lines.size(); ++i) {
    const std::string trimmed = strip(text.lines[i]);
    if (starts_with(trimmed, "@@") && trimmed != "@@ find" && trimmed != "@@ replace" && trimmed != "@@ end") {
      diagnostics.push_back({i + 1, "unknown directive '" + trimmed + "'; expected '@@ find', '@@ replace' or '@@ end'"});
      continue;
    }
    state = read_mutant_line(state, text.lines[i], i + 1, mutant, comments, diagnostics);
  }
  check_mutant(state, text.lines.size(), comments, mutant, diagnostics);
  std::stable_sort(diagnostics.begin(), diagnostics.end(),
                   [](const Diagnostic& a, const Diagnostic& b) { return a.line < b.line; });
  return diagnostics;
}

// Start indices of every whole-line occurrence of `block` in `lines`.
template <typename Equal>
std::vector<std::size_t> occurrences(const std::vector<std::string>& lines,
                                     const std::vector<std::string>& block, Equal equal) {
  std::vector<std::size_t> found;
  if (block.empty() || block.size() > lines.size()) return found;
  for (std::size_t start = 0; start + block.size() <= lines.size(); ++start) {
    bool match = true;
    for (std::size_t k = 0; k < block.size() && match; ++k) match = equal(lines[start + k], block[k]);
    if (match) found.push_back(start);
  }
  return found;
}

std::string line_list(const std::vector<std::size_t>& starts) {
  std::string list;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    if (i > 0) list += ", ";
    list += std::to_string(starts[i] + 1);
  }
  return list;
}

// True if `path` names the solution file `file` (relative to the solutions folder).
bool path_matches(const std::string& path, const std::string& file) {
  const std::string p = fs::path(path).lexically_normal().generic_string();
  const std::string f = fs::path(file).lexically_normal().generic_string();
  return p == f || (p.size() > f.size() && p.compare(p.size() - f.size(), f.size(), f) == 0 &&
                    p[p.size() - f.size() - 1] == '/');
}

struct Match {
  std::size_t start;
  const Pair* pair;
};

int apply(const std::string& mutant_path, const Mutant& mutant, const std::string& solution_path,
          const std::string& out_path) {
  if (!path_matches(solution_path, mutant.file)) {
    std::cerr << mutant_path << ':' << mutant.file_line << ": error: the mutant is for '" << mutant.file
              << "' but was applied to '" << solution_path << "'\n";
    return 1;
  }
  std::string content;
  if (!read_file(solution_path, content)) {
    std::cerr << solution_path << ": error: cannot read the solution file\n";
    return 2;
  }
  Lines solution = split_lines(content);
  const auto exact = [](const std::string& a, const std::string& b) { return a == b; };
  const auto loose = [](const std::string& a, const std::string& b) { return strip(a) == strip(b); };

  bool ok = true;
  std::vector<Match> matches;
  for (const Pair& pair : mutant.pairs) {
    const std::vector<std::size_t> found = occurrences(solution.lines, pair.find, exact);
    if (found.size() == 1) {
      matches.push_back({found.front(), &pair});
      continue;
    }
    ok = false;
    std::cerr << mutant_path << ':' << pair.find_line << ": error: ";
    if (found.empty()) {
      std::cerr << "find block not found in " << solution_path;
      const std::vector<std::size_t> near = occurrences(solution.lines, pair.find, loose);
      if (!near.empty())
        std::cerr << " (it matches at line " << line_list(near)
                  << " if whitespace is ignored; the find text must match exactly, indentation included)";
      std::cerr << "; the mutant no longer applies to the solution:\n";
    } else {
      std::cerr << "find block occurs " << found.size() << " times in " << solution_path << " (at lines "
                << line_list(found) << "); it must occur exactly once, so add surrounding lines:\n";
    }
    print_block(std::cerr, pair.find);
  }
  if (!ok) return 1;

  std::sort(matches.begin(), matches.end(),
            [](const Match& a, const Match& b) { return a.start < b.start; });
  for (std::size_t i = 1; i < matches.size(); ++i) {
    const Match& previous = matches[i - 1];
    if (previous.start + previous.pair->find.size() > matches[i].start) {
      std::cerr << mutant_path << ':' << matches[i].pair->find_line
                << ": error: this find block overlaps the one at line " << previous.pair->find_line
                << " (both match around line " << (matches[i].start + 1) << " of " << solution_path << ")\n";
      ok = false;
    }
  }
  if (!ok) return 1;

  Lines mutated;
  mutated.final_newline = solution.final_newline;
  std::size_t next = 0;
  for (const Match& match : matches) {
    mutated.lines.insert(mutated.lines.end(), solution.lines.begin() + static_cast<std::ptrdiff_t>(next),
                         solution.lines.begin() + static_cast<std::ptrdiff_t>(match.start));
    mutated.lines.insert(mutated.lines.end(), match.pair->replace.begin(), match.pair->replace.end());
    next = match.start + match.pair->find.size();
  }
  mutated.lines.insert(mutated.lines.end(), solution.lines.begin() + static_cast<std::ptrdiff_t>(next),
                       solution.lines.end());
  if (mutated.lines.empty()) mutated.final_newline = true;

  if (!write_if_changed(out_path, join_lines(mutated))) {
    std::cerr << out_path << ": error: cannot write the mutated file\n";
    return 2;
  }
  return 0;
}

// The command line (its usage comes from this table).
fmbd::cli::Command command_line() {
  const fmbd::cli::Option field{"--field", fmbd::cli::Kind::value, "file|expect", "'file' or 'expect'", ""};
  return fmbd::cli::program("fmbd-mutate", {field}, "FILE", -1, "MUTANT_FILE SOLUTION_FILE OUT",
                            {"       fmbd-mutate --field file|expect MUTANT_FILE"});
}

}  // namespace

int main(int argc, char** argv) {
  const fmbd::cli::Command command = command_line();
  fmbd::cli::Parsed parsed;
  if (const auto status = fmbd::cli::parse_program(command, argc, argv, parsed)) return *status;
  const std::string field = parsed.value("--field");
  const std::vector<std::string>& args = parsed.positionals;
  if (parsed.has("--field") && (args.size() != 1 || (field != "file" && field != "expect"))) {
    std::cerr << "fmbd-mutate: --field takes 'file' or 'expect' and a mutant file\n"
              << fmbd::cli::program_usage(command);
    return 2;
  }
  if (!parsed.has("--field") && args.size() != 3) {
    std::cerr << fmbd::cli::program_usage(command);
    return 2;
  }

  const std::string& mutant_path = args[0];
  std::string content;
  if (!read_file(mutant_path, content)) {
    std::cerr << mutant_path << ": error: cannot read the mutant file\n";
    return 2;
  }
  Mutant mutant;
  const std::vector<Diagnostic> diagnostics = parse_mutant(content, mutant);
  if (!diagnostics.empty()) {
    for (const Diagnostic& d : diagnostics)
      std::cerr << mutant_path << ':' << d.line << ": error: " << d.message << '\n';
    return 1;
  }
  if (field == "file") {
    std::cout << mutant.file << '\n';
    return 0;
  }
  if (field == "expect") {
    std::cout << mutant.expect << '\n';
    return 0;
  }
  return apply(mutant_path, mutant, args[1], args[2]);
}
