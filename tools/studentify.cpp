// fmbd-studentify: generates a student exercise file from its solution.
//
// The solution solutions/moduleNN_x/F.cpp is the only hand-edited version of an
// exercise file; the student copy moduleNN_x/src/F.cpp is generated from it.
//
//   fmbd-studentify --source-name NAME IN OUT
//       Writes OUT (only if its content changes, so builds stay incremental).
//   fmbd-studentify --check --source-name NAME IN COMMITTED
//       Exits 0 if COMMITTED is exactly what would be generated, else 1 and
//       reports the first differing line.
//
// NAME (e.g. solutions/module01_kinematics/joints.cpp) gives the module number of the generated
// header (which names no folder a student lacks) and the file of messages, so the output never
// depends on absolute paths.
//
// Marker language (markers stand on their own line; leading whitespace is allowed):
//   // BEGIN SOLUTION ... // END SOLUTION
//       The marker lines and every line between them are removed.
//   // STUB: <text>
//       Becomes <same indentation><text>. In the solution it is just a comment.
//   // TASK(MnnTk): ...
//       Anywhere in a line, "// TASK(" becomes "// TODO(" (only directly after "// ").
//       The id must match M[0-9][0-9]T[0-9]+.
// Errors (reported as IN:line: error: ..., exit status 1): unterminated or nested
// BEGIN SOLUTION, END SOLUTION without BEGIN, a STUB inside a solution region, a
// misspelt marker (e.g. "//BEGIN SOLUTION", "// STUB:x"), a malformed task id, and a
// file without any marker. Usage and I/O errors exit with status 2.

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
#include "task_id.hpp"

namespace {

namespace fs = std::filesystem;

constexpr const char* kRegenerateCommand = "./workbook studentify";

using fmbd::tools::read_file;
using fmbd::tools::split_lines;
using fmbd::tools::write_if_changed;

bool is_blank(char c) { return c == ' ' || c == '\t'; }

std::string rstrip(const std::string& s) {
  std::size_t end = s.size();
  while (end > 0 && (is_blank(s[end - 1]) || s[end - 1] == '\r')) --end;
  return s.substr(0, end);
}

using fmbd::tools::starts_with;

struct Diagnostic {
  std::size_t line;
  std::string message;
};

// Rewrites every "// TASK(" into "// TODO(" and checks the ids. Returns the number
// of task tokens found.
std::size_t rewrite_tasks(std::string& line, std::size_t line_number,
                          std::vector<Diagnostic>& diagnostics) {
  static const std::string token = "// TASK(";
  std::size_t count = 0;
  std::size_t pos = 0;
  while ((pos = line.find(token, pos)) != std::string::npos) {
    ++count;
    const std::size_t id_begin = pos + token.size();
    const std::size_t close = line.find(')', id_begin);
    const std::string id = close == std::string::npos ? line.substr(id_begin)
                                                      : line.substr(id_begin, close - id_begin);
    if (close == std::string::npos || !fmbd::protocol::parse_task_id(id)) {
      diagnostics.push_back({line_number, "malformed task id 'TASK(" + id +
                                              (close == std::string::npos ? "" : ")") +
                                              "'; write '// TASK(MnnTk)', e.g. '// TASK(M01T2)'"});
    }
    line.replace(pos + 3, 4, "TODO");
    pos = id_begin;
  }
  return count;
}

enum class Kind { Plain, Begin, End, Stub, Malformed };

struct Classified {
  Kind kind = Kind::Plain;
  std::string indentation;  // for Stub
  std::string text;         // for Stub: the replacement text; for Malformed: the marker
};

Classified classify(const std::string& line) {
  Classified result;
  std::size_t first = 0;
  while (first < line.size() && is_blank(line[first])) ++first;
  const std::string trimmed = rstrip(line.substr(first));
  if (trimmed == "// BEGIN SOLUTION") {
    result.kind = Kind::Begin;
  } else if (trimmed == "// END SOLUTION") {
    result.kind = Kind::End;
  } else if (trimmed == "// STUB:" || starts_with(trimmed, "// STUB: ")) {
    result.kind = Kind::Stub;
    result.indentation = line.substr(0, first);
    std::size_t text_begin = std::string("// STUB:").size();
    if (text_begin < trimmed.size()) ++text_begin;  // the single space after the colon
    result.text = trimmed.substr(text_begin);
  } else if (starts_with(trimmed, "//")) {
    // Near misses of a marker are errors rather than silently kept comments.
    std::size_t rest = 2;
    while (rest < trimmed.size() && is_blank(trimmed[rest])) ++rest;
    const std::string word = trimmed.substr(rest);
    if (starts_with(word, "BEGIN SOLUTION") || starts_with(word, "END SOLUTION") ||
        starts_with(word, "STUB:")) {
      result.kind = Kind::Malformed;
      result.text = trimmed;
    }
  }
  return result;
}

// The module number of a solution path ".../moduleNN_x/F.cpp", without a leading zero; "?" if
// the path names no module folder.
std::string module_number(const std::string& source_name) {
  const std::size_t at = source_name.rfind("module");
  if (at == std::string::npos || at + 8 > source_name.size()) return "?";
  const char tens = source_name[at + 6], ones = source_name[at + 7];
  if (tens < '0' || tens > '9' || ones < '0' || ones > '9') return "?";
  return tens == '0' ? std::string(1, ones) : std::string{tens, ones};
}

struct Result {
  std::string output;
  std::vector<Diagnostic> diagnostics;
};

// The state of one pass over a solution file: the unclosed BEGIN SOLUTION and the markers seen.
struct Regions {
  std::size_t open_region = 0;  // line of the unclosed BEGIN SOLUTION; 0: none (lines count from 1)
  std::size_t markers = 0;
};

// One line of the solution: what the student file gets of it (into `out`), and its diagnostics.
void studentify_line(std::string line, std::size_t number, Regions& regions, std::ostream& out,
                     std::vector<Diagnostic>& diagnostics) {
  regions.markers += rewrite_tasks(line, number, diagnostics);
  const Classified c = classify(line);
  if (c.kind != Kind::Plain) ++regions.markers;
  switch (c.kind) {
    case Kind::Begin:
      if (regions.open_region) {
        diagnostics.push_back({number, "nested BEGIN SOLUTION (the region opened at line " +
                                           std::to_string(regions.open_region) + " is not closed yet)"});
      } else {
        regions.open_region = number;
      }
      break;
    case Kind::End:
      if (!regions.open_region) diagnostics.push_back({number, "END SOLUTION without a matching BEGIN SOLUTION"});
      regions.open_region = 0;
      break;
    case Kind::Stub:
      if (regions.open_region) {
        diagnostics.push_back({number, "STUB line inside the solution region opened at line " +
                                           std::to_string(regions.open_region) +
                                           " (put the STUB before BEGIN SOLUTION or after END SOLUTION)"});
      } else if (c.text.empty()) {
        out << '\n';
      } else {
        out << c.indentation << c.text << '\n';
      }
      break;
    case Kind::Malformed:
      diagnostics.push_back({number, "malformed marker '" + c.text +
                                         "'; write exactly '// BEGIN SOLUTION', '// END SOLUTION' or "
                                         "'// STUB: <text>' on a line of its own"});
      break;
    case Kind::Plain:
      if (!regions.open_region) out << line << '\n';
      break;
  }
}

Result studentify(const std::string& content, const std::string& source_name) {
  Result result;
  std::ostringstream out;
  out << "// Exercise file of module " << module_number(source_name)
      << ", yours to edit: replace each NotImplemented below a TODO\n"
      << "// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.\n";
  const std::vector<std::string> lines = split_lines(content);
  Regions regions;
  for (std::size_t i = 0; i < lines.size(); ++i) studentify_line(lines[i], i + 1, regions, out, result.diagnostics);
  if (regions.open_region) {
    result.diagnostics.push_back(
        {regions.open_region, "unterminated BEGIN SOLUTION (no END SOLUTION before the end of the file)"});
  }
  if (regions.markers == 0) {
    result.diagnostics.push_back({1, "no studentify marker (BEGIN SOLUTION, STUB or TASK) in this file; "
                                     "an exercise file must contain at least one task"});
  }
  result.output = out.str();
  return result;
}

// Reports the first difference between the committed and the generated file.
void report_difference(const std::string& committed_path, const std::string& in_path,
                       const std::string& committed, const std::string& generated) {
  const std::vector<std::string> a = split_lines(committed);
  const std::vector<std::string> b = split_lines(generated);
  std::size_t i = 0;
  while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
  const std::string end_of_file = "(end of file)";
  std::cerr << committed_path << ':' << (i + 1) << ": error: the student file is out of date with "
            << in_path << '\n';
  if (i == a.size() && i == b.size()) {
    std::cerr << "  the files differ only in the newline at the end of the file\n";
  } else {
    std::cerr << "  committed: " << (i < a.size() ? a[i] : end_of_file) << '\n'
              << "  generated: " << (i < b.size() ? b[i] : end_of_file) << '\n';
  }
  std::cerr << "Edit the solution, not the student file, then regenerate with: "
            << kRegenerateCommand << '\n';
}

// The command line (its usage comes from this table).
fmbd::cli::Command command_line() {
  using fmbd::cli::Kind;
  return fmbd::cli::program("fmbd-studentify",
                            {{"--source-name", Kind::value, "NAME", "a value", ""},
                             {"--check", Kind::flag, "", "", ""}},
                            "FILE", -1, "--source-name NAME IN OUT",
                            {"       fmbd-studentify --check --source-name NAME IN COMMITTED",
                             "NAME is the solution path, whose module number the generated header quotes,",
                             "e.g. solutions/module01_kinematics/joints.cpp"});
}

}  // namespace

int main(int argc, char** argv) {
  const fmbd::cli::Command command = command_line();
  fmbd::cli::Parsed parsed;
  if (const auto status = fmbd::cli::parse_program(command, argc, argv, parsed)) return *status;
  const bool check = parsed.has("--check");
  const std::string source_name = parsed.value("--source-name");
  const std::vector<std::string>& positional = parsed.positionals;
  if (source_name.empty() || positional.size() != 2) {
    std::cerr << (source_name.empty() ? "fmbd-studentify: --source-name NAME is required\n"
                                      : "fmbd-studentify: expected two file arguments\n")
              << fmbd::cli::program_usage(command);
    return 2;
  }
  const std::string& in_path = positional[0];
  const std::string& out_path = positional[1];

  std::string content;
  if (!read_file(in_path, content)) {
    std::cerr << in_path << ": error: cannot read the solution file\n";
    return 2;
  }
  const Result result = studentify(content, source_name);
  if (!result.diagnostics.empty()) {
    for (const Diagnostic& d : result.diagnostics)
      std::cerr << in_path << ':' << d.line << ": error: " << d.message << '\n';
    return 1;
  }

  if (check) {
    std::string committed;
    if (!read_file(out_path, committed)) {
      std::cerr << out_path << ": error: the student file is missing (generated from " << in_path
                << ")\nGenerate it with: " << kRegenerateCommand << '\n';
      return 1;
    }
    if (committed != result.output) {
      report_difference(out_path, in_path, committed, result.output);
      return 1;
    }
    return 0;
  }

  if (!write_if_changed(out_path, result.output)) {
    std::cerr << out_path << ": error: cannot write the student file\n";
    return 2;
  }
  return 0;
}
