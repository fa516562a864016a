// fmbd-similarity: finds code in a tree that restates a solution block.
//
//   fmbd-similarity [--window W] [--min-length N] [--allow FILE] TREE [SOLUTION...]
//
// Reads every solution block (the lines between "// BEGIN SOLUTION" and "// END SOLUTION") of
// the SOLUTION files, and every .cpp, .hpp and .h file below TREE (except build/, out/ and
// .git/). Each line is normalised: comments and whitespace are removed, every identifier
// becomes '$', every number '#', every string or character literal '"'; C++ keywords stay.
// Lines shorter than N characters after that (default 12) are dropped, which drops pure braces
// and short statements such as "return x;". A match is a run of W (default 4) consecutive
// normalised lines of a file in TREE equal to W consecutive normalised lines of one solution
// block: the same statements with renamed variables and changed constants.
//
// Each match is printed as "TREE_FILE:first-last: restates SOLUTION:first-last" (merged over
// overlapping windows). Without SOLUTION files there is nothing to restate: no match. Exit
// status: 0 no match, 1 a match, 2 usage or I/O error, or SOLUTION files without any block of W
// significant lines (a misspelt marker would otherwise make every check pass).
//
// --allow FILE names files of TREE that may match, one per line: "PATH  # reason", PATH relative
// to TREE. Every entry needs a reason after '#'; blank lines and lines starting with '#' are
// comments. Matches in an allowed file are counted and reported as allowed, not as errors.

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "cli.hpp"
#include "file_io.hpp"
#include "strings.hpp"

namespace {

namespace fs = std::filesystem;

struct Line {
  std::size_t number;  // 1-based line of the original file
  std::string text;    // normalised
};

const std::set<std::string>& keywords() {
  static const std::set<std::string> words = {
      "alignas", "alignof", "auto", "bool", "break", "case", "catch", "char", "class", "const",
      "constexpr", "const_cast", "continue", "decltype", "default", "delete", "do", "double",
      "dynamic_cast", "else", "enum", "explicit", "extern", "false", "float", "for", "friend",
      "goto", "if", "inline", "int", "long", "mutable", "namespace", "new", "noexcept", "nullptr",
      "operator", "private", "protected", "public", "return", "short", "signed", "sizeof",
      "static", "static_assert", "static_cast", "struct", "switch", "template", "this", "throw",
      "true", "try", "typedef", "typename", "union", "unsigned", "using", "virtual", "void",
      "volatile", "while"};
  return words;
}

bool identifier_start(char c) { return fmbd::tools::is_identifier_start(c); }
bool identifier_char(char c) { return fmbd::tools::is_identifier_char(c); }

// Normalises a whole file into lines; `in_comment` carries a /* */ comment across lines.
std::vector<std::string> normalise(const std::string& content) {
  std::vector<std::string> out;
  std::string line;
  bool in_comment = false;
  std::size_t i = 0;
  const std::size_t n = content.size();
  while (i < n) {
    const char c = content[i];
    if (c == '\n') {
      out.push_back(line);
      line.clear();
      ++i;
    } else if (in_comment) {
      if (c == '*' && i + 1 < n && content[i + 1] == '/') {
        in_comment = false;
        i += 2;
      } else {
        ++i;
      }
    } else if (c == '/' && i + 1 < n && content[i + 1] == '/') {
      while (i < n && content[i] != '\n') ++i;
    } else if (c == '/' && i + 1 < n && content[i + 1] == '*') {
      in_comment = true;
      i += 2;
    } else if (c == '"' || c == '\'') {
      ++i;
      while (i < n && content[i] != c && content[i] != '\n') i += content[i] == '\\' ? 2 : 1;
      if (i < n && content[i] == c) ++i;
      line += '"';
    } else if (identifier_start(c)) {
      std::size_t end = i;
      while (end < n && identifier_char(content[end])) ++end;
      const std::string word = content.substr(i, end - i);
      line += keywords().count(word) ? word : "$";
      i = end;
    } else if (std::isdigit(static_cast<unsigned char>(c)) ||
               (c == '.' && i + 1 < n && std::isdigit(static_cast<unsigned char>(content[i + 1])))) {
      // 12, 0.5, 1e-9, 3.0f, 0x1F: digits, letters, dots, and a sign after an exponent.
      std::size_t end = i + 1;
      while (end < n && (identifier_char(content[end]) || content[end] == '.' ||
                         ((content[end] == '-' || content[end] == '+') &&
                          (content[end - 1] == 'e' || content[end - 1] == 'E'))))
        ++end;
      line += '#';
      i = end;
    } else {
      if (!std::isspace(static_cast<unsigned char>(c))) line += c;
      ++i;
    }
  }
  if (!line.empty()) out.push_back(line);
  return out;
}

// The lines of `raw` (normalised) that are long enough to count, with their line numbers.
std::vector<Line> significant(const std::vector<std::string>& raw, std::size_t first,
                              std::size_t last, std::size_t min_length) {
  std::vector<Line> lines;
  for (std::size_t k = first; k < last && k < raw.size(); ++k)
    if (raw[k].size() >= min_length) lines.push_back({k + 1, raw[k]});
  return lines;
}

using fmbd::tools::trim;

std::string window_key(const std::vector<Line>& lines, std::size_t start, std::size_t w) {
  std::string key;
  for (std::size_t k = start; k < start + w; ++k) key += lines[k].text + '\n';
  return key;
}

struct Block {  // one solution block
  std::string file;
  std::vector<Line> lines;
};

struct Hit {
  std::size_t block, block_index;  // window start in the block's significant lines
};

// The command line (its usage comes from this table).
fmbd::cli::Command command_line() {
  using fmbd::cli::Kind;
  return fmbd::cli::program("fmbd-similarity",
                            {{"--window", Kind::value, "W", "a positive number", ""},
                             {"--min-length", Kind::value, "N", "a positive number", ""},
                             {"--allow", Kind::value, "FILE", "a file name", ""}},
                            "TREE", -1, "[--window W] [--min-length N] [--allow FILE] TREE [SOLUTION...]",
                            {"Reports every W consecutive lines of a .cpp/.hpp/.h file below TREE that equal, after",
                             "normalisation, W consecutive lines of a BEGIN/END SOLUTION block of a SOLUTION file."});
}

bool parse_count(const std::string& text, std::size_t& value) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return false;
  value = std::stoul(text);
  return value > 0;
}

// An error that ends the run with status 2: what to print on stderr (without a newline).
struct Failure {
  std::string message;
};

struct Settings {
  std::size_t window = 4, min_length = 12;
  std::string allow_path;
  std::vector<std::string> positional;  // TREE SOLUTION...
};

Settings read_settings(const fmbd::cli::Parsed& parsed) {
  Settings settings;
  settings.allow_path = parsed.value("--allow");
  for (const char* option : {"--window", "--min-length"}) {
    if (!parsed.has(option)) continue;
    const std::string value = parsed.value(option);
    if (!parse_count(value, std::string(option) == "--window" ? settings.window : settings.min_length)) {
      throw Failure{"fmbd-similarity: " + std::string(option) + " needs a positive number, got '" + value + "'"};
    }
  }
  settings.positional = parsed.positionals;
  return settings;
}

// The allow-list: path -> reason ("PATH  # why it may match" per line).
std::map<std::string, std::string> read_allow_list(const std::string& allow_path) {
  std::map<std::string, std::string> allowed;
  if (allow_path.empty()) return allowed;
  std::string content;
  if (!fmbd::tools::read_file(allow_path, content)) throw Failure{allow_path + ": error: cannot read the allow-list"};
  std::size_t number = 0, start = 0;
  while (start <= content.size()) {
    std::size_t end = content.find('\n', start);
    if (end == std::string::npos) end = content.size();
    const std::string line = trim(content.substr(start, end - start));
    ++number;
    start = end + 1;
    if (line.empty() || line[0] == '#') continue;
    const std::size_t hash = line.find('#');
    const std::string path = trim(line.substr(0, hash));
    const std::string reason = hash == std::string::npos ? "" : trim(line.substr(hash + 1));
    if (reason.empty()) {
      throw Failure{allow_path + ':' + std::to_string(number) + ": error: '" + path +
                    "' has no reason; write 'PATH  # why it may match'"};
    }
    allowed[path] = reason;
  }
  return allowed;
}

// Every window of every solution block of the solution files.
struct SolutionIndex {
  std::vector<Block> blocks;
  std::unordered_map<std::string, std::vector<Hit>> windows;
};

void index_file(const std::string& path, const Settings& settings, SolutionIndex& index) {
  std::string content;
  if (!fmbd::tools::read_file(path, content)) throw Failure{path + ": error: cannot read the solution file"};
  // Block boundaries come from the raw lines; their content from the normalised ones.
  std::vector<std::string> raw_lines;
  for (std::size_t start = 0; start < content.size();) {
    std::size_t end = content.find('\n', start);
    if (end == std::string::npos) end = content.size();
    raw_lines.push_back(trim(content.substr(start, end - start)));
    start = end + 1;
  }
  const std::vector<std::string> normalised = normalise(content);
  std::size_t open = 0;
  bool inside = false;
  for (std::size_t k = 0; k < raw_lines.size(); ++k) {
    if (raw_lines[k] == "// BEGIN SOLUTION") {
      inside = true;
      open = k + 1;
    } else if (raw_lines[k] == "// END SOLUTION" && inside) {
      inside = false;
      Block block{path, significant(normalised, open, k, settings.min_length)};
      if (block.lines.size() < settings.window) continue;
      index.blocks.push_back(std::move(block));
      const Block& b = index.blocks.back();
      for (std::size_t s = 0; s + settings.window <= b.lines.size(); ++s)
        index.windows[window_key(b.lines, s, settings.window)].push_back({index.blocks.size() - 1, s});
    }
  }
}

// Every source file of the tree, in a stable order (build/, out/ and .git/ at its top left out).
std::vector<fs::path> source_files(const fs::path& tree) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(tree, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (it->is_directory() && it.depth() == 0 && (name == "build" || name == "out" || name == ".git")) {
      it.disable_recursion_pending();
      continue;
    }
    const std::string ext = it->path().extension().string();
    if (it->is_regular_file() && (ext == ".cpp" || ext == ".hpp" || ext == ".h")) files.push_back(it->path());
  }
  if (ec) throw Failure{"fmbd-similarity: cannot list " + tree.string() + ": " + ec.message()};
  std::sort(files.begin(), files.end());
  return files;
}

struct Tally {
  std::size_t reported = 0, tolerated = 0;
  std::set<std::string> allowed_used;
};

// The runs of one file that restate a solution block: printed, or counted as allowed.
void compare_file(const fs::path& file, const std::string& relative, const SolutionIndex& index,
                  const std::map<std::string, std::string>& allowed, const Settings& settings, Tally& tally) {
  std::string content;
  if (!fmbd::tools::read_file(file.string(), content)) throw Failure{file.string() + ": error: cannot read"};
  const std::vector<Line> lines = significant(normalise(content), 0, SIZE_MAX, settings.min_length);
  // Matching windows, merged into runs: (file start, block, block start, length).
  std::size_t s = 0;
  while (s + settings.window <= lines.size()) {
    const auto found = index.windows.find(window_key(lines, s, settings.window));
    if (found == index.windows.end()) {
      ++s;
      continue;
    }
    const Hit hit = found->second.front();
    const Block& block = index.blocks[hit.block];
    std::size_t length = settings.window;
    while (s + length < lines.size() && hit.block_index + length < block.lines.size() &&
           lines[s + length].text == block.lines[hit.block_index + length].text)
      ++length;
    if (allowed.count(relative)) {
      ++tally.tolerated;
      tally.allowed_used.insert(relative);
    } else {
      ++tally.reported;
      std::cout << relative << ':' << lines[s].number << '-' << lines[s + length - 1].number << ": restates "
                << block.file << ':' << block.lines[hit.block_index].number << '-'
                << block.lines[hit.block_index + length - 1].number << '\n';
    }
    s += length;
  }
}

int run(const Settings& settings) {
  const fs::path tree = settings.positional[0];
  std::error_code ec;
  if (!fs::is_directory(tree, ec)) throw Failure{"fmbd-similarity: " + tree.string() + " is not a folder"};
  const std::map<std::string, std::string> allowed = read_allow_list(settings.allow_path);
  SolutionIndex index;
  for (std::size_t f = 1; f < settings.positional.size(); ++f) index_file(settings.positional[f], settings, index);
  if (index.blocks.empty() && settings.positional.size() > 1) {
    throw Failure{"fmbd-similarity: no solution block of " + std::to_string(settings.window) +
                  " or more significant lines in the files given"};
  }
  const std::vector<fs::path> files = source_files(tree);
  Tally tally;
  for (const fs::path& file : files)
    compare_file(file, fs::relative(file, tree).generic_string(), index, allowed, settings, tally);
  for (const std::string& path : tally.allowed_used)
    std::cout << "allowed: " << path << " (" << allowed.at(path) << ")\n";
  // An entry that no longer matches is a debt paid: say so, so that it gets removed.
  for (const auto& [path, reason] : allowed)
    if (!tally.allowed_used.count(path)) std::cout << "note: the allow-list entry " << path << " matches nothing\n";
  std::cout << "fmbd-similarity: " << files.size() << " files against " << index.blocks.size()
            << " solution blocks (window " << settings.window << ", lines of " << settings.min_length
            << "+ characters): " << tally.reported << " match" << (tally.reported == 1 ? "" : "es")
            << (tally.tolerated ? ", " + std::to_string(tally.tolerated) + " allowed" : "") << '\n';
  return tally.reported ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  const fmbd::cli::Command command = command_line();
  fmbd::cli::Parsed parsed;
  if (const auto status = fmbd::cli::parse_program(command, argc, argv, parsed)) return *status;
  try {
    const Settings settings = read_settings(parsed);
    if (settings.positional.empty()) {
      std::cerr << fmbd::cli::program_usage(command);
      return 2;
    }
    return run(settings);
  } catch (const Failure& failure) {
    std::cerr << failure.message << '\n';
    return 2;
  }
}
