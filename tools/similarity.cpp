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
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

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

void usage(std::ostream& os) {
  os << "usage: fmbd-similarity [--window W] [--min-length N] [--allow FILE] TREE [SOLUTION...]\n"
        "Reports every W consecutive lines of a .cpp/.hpp/.h file below TREE that equal, after\n"
        "normalisation, W consecutive lines of a BEGIN/END SOLUTION block of a SOLUTION file.\n";
}

bool parse_count(const std::string& text, std::size_t& value) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return false;
  value = std::stoul(text);
  return value > 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t window = 4, min_length = 12;
  std::string allow_path;
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if ((arg == "--window" || arg == "--min-length" || arg == "--allow") && i + 1 < argc) {
      const std::string value = argv[++i];
      if (arg == "--allow") {
        allow_path = value;
      } else if (!parse_count(value, arg == "--window" ? window : min_length)) {
        std::cerr << "fmbd-similarity: " << arg << " needs a positive number, got '" << value << "'\n";
        return 2;
      }
    } else if (arg == "-h" || arg == "--help") {
      usage(std::cout);
      return 0;
    } else if (!arg.empty() && arg[0] == '-') {
      std::cerr << "fmbd-similarity: unknown option or missing value: '" << arg << "'\n";
      usage(std::cerr);
      return 2;
    } else {
      positional.push_back(arg);
    }
  }
  if (positional.empty()) {
    usage(std::cerr);
    return 2;
  }
  const fs::path tree = positional[0];
  std::error_code ec;
  if (!fs::is_directory(tree, ec)) {
    std::cerr << "fmbd-similarity: " << tree.string() << " is not a folder\n";
    return 2;
  }

  // The allow-list: path -> reason.
  std::map<std::string, std::string> allowed;
  if (!allow_path.empty()) {
    std::string content;
    if (!fmbd::tools::read_file(allow_path, content)) {
      std::cerr << allow_path << ": error: cannot read the allow-list\n";
      return 2;
    }
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
        std::cerr << allow_path << ':' << number << ": error: '" << path
                  << "' has no reason; write 'PATH  # why it may match'\n";
        return 2;
      }
      allowed[path] = reason;
    }
  }

  // Every window of every solution block.
  std::vector<Block> blocks;
  std::unordered_map<std::string, std::vector<Hit>> windows;
  for (std::size_t f = 1; f < positional.size(); ++f) {
    const std::string& path = positional[f];
    std::string content;
    if (!fmbd::tools::read_file(path, content)) {
      std::cerr << path << ": error: cannot read the solution file\n";
      return 2;
    }
    // Block boundaries come from the raw lines; their content from the normalised ones.
    std::vector<std::string> raw_lines;
    {
      std::size_t start = 0;
      while (start < content.size()) {
        std::size_t end = content.find('\n', start);
        if (end == std::string::npos) end = content.size();
        raw_lines.push_back(trim(content.substr(start, end - start)));
        start = end + 1;
      }
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
        Block block{path, significant(normalised, open, k, min_length)};
        if (block.lines.size() < window) continue;
        blocks.push_back(std::move(block));
        const Block& b = blocks.back();
        for (std::size_t s = 0; s + window <= b.lines.size(); ++s)
          windows[window_key(b.lines, s, window)].push_back({blocks.size() - 1, s});
      }
    }
  }
  if (blocks.empty() && positional.size() > 1) {
    std::cerr << "fmbd-similarity: no solution block of " << window
              << " or more significant lines in the files given\n";
    return 2;
  }

  // Every source file of the tree, in a stable order.
  std::vector<fs::path> files;
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
  if (ec) {
    std::cerr << "fmbd-similarity: cannot list " << tree.string() << ": " << ec.message() << '\n';
    return 2;
  }
  std::sort(files.begin(), files.end());

  std::size_t reported = 0, tolerated = 0;
  std::set<std::string> allowed_used;
  for (const fs::path& file : files) {
    const std::string relative = fs::relative(file, tree).generic_string();
    std::string content;
    if (!fmbd::tools::read_file(file.string(), content)) {
      std::cerr << file.string() << ": error: cannot read\n";
      return 2;
    }
    const std::vector<Line> lines = significant(normalise(content), 0, SIZE_MAX, min_length);
    // Matching windows, merged into runs: (file start, block, block start, length).
    std::size_t s = 0;
    while (s + window <= lines.size()) {
      const auto found = windows.find(window_key(lines, s, window));
      if (found == windows.end()) {
        ++s;
        continue;
      }
      const Hit hit = found->second.front();
      const Block& block = blocks[hit.block];
      std::size_t length = window;
      while (s + length < lines.size() && hit.block_index + length < block.lines.size() &&
             lines[s + length].text == block.lines[hit.block_index + length].text)
        ++length;
      const auto allow = allowed.find(relative);
      if (allow != allowed.end()) {
        ++tolerated;
        allowed_used.insert(relative);
      } else {
        ++reported;
        std::cout << relative << ':' << lines[s].number << '-' << lines[s + length - 1].number
                  << ": restates " << block.file << ':' << block.lines[hit.block_index].number << '-'
                  << block.lines[hit.block_index + length - 1].number << '\n';
      }
      s += length;
    }
  }
  for (const std::string& path : allowed_used)
    std::cout << "allowed: " << path << " (" << allowed.at(path) << ")\n";
  // An entry that no longer matches is a debt paid: say so, so that it gets removed.
  for (const auto& [path, reason] : allowed)
    if (!allowed_used.count(path)) std::cout << "note: the allow-list entry " << path << " matches nothing\n";
  std::cout << "fmbd-similarity: " << files.size() << " files against " << blocks.size()
            << " solution blocks (window " << window << ", lines of " << min_length
            << "+ characters): " << reported << " match" << (reported == 1 ? "" : "es")
            << (tolerated ? ", " + std::to_string(tolerated) + " allowed" : "") << '\n';
  return reported ? 1 : 0;
}
