// fmbd-hidden-only-helpers: names that a module's released checks header declares but that
// nothing released needs.
//
//   fmbd-hidden-only-helpers RELEASE
//
// For every autograder/moduleNN_*/NAME_checks.hpp of the tree RELEASE (a student release, or the
// instructor's copy: hidden/ folders are skipped either way), the header and its NAME_checks.cpp
// are split into their namespace-scope items (functions, types, constants; the anonymous
// namespace's too), each with its text. A name is needed when a released file of the module
// folder other than these two (a visible test) mentions it, or when the text of a needed item
// does (a helper that a needed helper calls). Every name the header declares that is not needed
// is printed as "HEADER: NAME" (with the header relative to RELEASE), and the exit status is 1;
// an item that only hidden tests use belongs in hidden/ with them. The module's headers are
// only included by its own test files, so uses elsewhere do not count.
//
// Names are matched as words, so a needed item that mentions a name in another sense (a member
// or a local of the same name) keeps it needed: the check can miss such a name, never blame a
// needed one. Exits 2 for a wrong command line or a file it cannot read.
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli.hpp"

namespace fs = std::filesystem;

namespace {

using Item = std::pair<std::string, std::string>;  // name, text
using Words = std::set<std::string>;

struct Unreadable {
  std::string message;
};

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

bool is_word(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

std::size_t skip_space(const std::string& text, std::size_t at) {
  while (at < text.size() && is_space(text[at])) ++at;
  return at;
}

std::size_t skip_word(const std::string& text, std::size_t at) {
  while (at < text.size() && is_word(text[at])) ++at;
  return at;
}

bool starts_with(const std::string& text, std::size_t at, const char* prefix) {
  return text.compare(at, std::strlen(prefix), prefix) == 0;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Unreadable{"hidden_only_helpers: cannot read " + path + ": " + std::strerror(errno)};
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

// Each /* ... */ one space; each // to the end of its line gone.
std::string without_comments(const std::string& text) {
  std::string blocks;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t end = starts_with(text, i, "/*") ? text.find("*/", i + 2) : std::string::npos;
    if (end == std::string::npos) {
      blocks += text[i++];
      continue;
    }
    blocks += ' ';
    i = end + 2;
  }
  std::string out;
  for (std::size_t i = 0; i < blocks.size();) {
    if (!starts_with(blocks, i, "//")) {
      out += blocks[i++];
      continue;
    }
    i = std::min(blocks.find('\n', i), blocks.size());
  }
  return out;
}

// The end of a literal opened by `quote` at `at` (escapes, no newline), or npos. A character
// literal holds one character or one escape.
std::size_t literal_end(const std::string& text, std::size_t at, char quote) {
  std::size_t k = at + 1;
  int count = 0;
  for (; k < text.size() && (quote == '"' || count < 1); ++count) {
    if (text[k] == '\\' && k + 1 < text.size() && text[k + 1] != '\n') k += 2;
    else if (text[k] != quote && text[k] != '\\' && text[k] != '\n') k += 1;
    else break;
  }
  if (quote == '\'' && count != 1) return std::string::npos;
  return k < text.size() && text[k] == quote ? k + 1 : std::string::npos;
}

// Each string literal "", then each character literal ' '.
std::string without_literals(const std::string& text) {
  std::string strings;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t end = text[i] == '"' ? literal_end(text, i, '"') : std::string::npos;
    if (end == std::string::npos) {
      strings += text[i++];
      continue;
    }
    strings += "\"\"";
    i = end;
  }
  std::string out;
  for (std::size_t i = 0; i < strings.size();) {
    const std::size_t end = strings[i] == '\'' ? literal_end(strings, i, '\'') : std::string::npos;
    if (end == std::string::npos) {
      out += strings[i++];
      continue;
    }
    out += "' '";
    i = end;
  }
  return out;
}

// Each preprocessor line gone: from a line's start, white space (blank lines too), # and the
// rest of that line.
std::string without_preprocessor(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const bool line_start = i == 0 || text[i - 1] == '\n';
    const std::size_t hash = line_start ? skip_space(text, i) : text.size();
    if (hash >= text.size() || text[hash] != '#') {
      out += text[i++];
      continue;
    }
    i = std::min(text.find('\n', hash), text.size());
  }
  return out;
}

// Code without comments, string literals and preprocessor lines.
std::string code_of(const std::string& text) {
  return without_preprocessor(without_literals(without_comments(text)));
}

// Each "template <...>" (to the first >) and the white space after it gone.
std::string without_template_heads(const std::string& head) {
  std::string out;
  for (std::size_t i = 0; i < head.size();) {
    std::size_t end = std::string::npos;
    if (starts_with(head, i, "template") && (i == 0 || !is_word(head[i - 1]))) {
      const std::size_t open = skip_space(head, i + 8);
      const std::size_t close = open < head.size() && head[open] == '<' ? head.find_first_of(";{>", open + 1)
                                                                       : std::string::npos;
      if (close != std::string::npos && head[close] == '>') end = skip_space(head, close + 1);
    }
    if (end == std::string::npos) {
      out += head[i++];
      continue;
    }
    i = end;
  }
  return out;
}

// The name after struct, class, union or enum (class|struct) at the head's start.
std::optional<std::string> type_name(const std::string& head) {
  const std::size_t at = skip_space(head, 0);
  for (const char* key : {"struct", "class", "union", "enum"}) {
    if (!starts_with(head, at, key)) continue;
    const std::size_t after = at + std::strlen(key);
    std::vector<std::size_t> ends{after};  // after the keyword; for enum, after its class|struct first
    const std::size_t scoped = skip_space(head, after);
    if (std::string(key) == "enum" && scoped > after) {
      for (const char* kind : {"class", "struct"})
        if (starts_with(head, scoped, kind)) ends.insert(ends.begin(), scoped + std::strlen(kind));
    }
    for (const std::size_t end : ends) {
      const std::size_t name = skip_space(head, end);
      if (name > end && name < head.size() && is_word(head[name]))
        return head.substr(name, skip_word(head, name) - name);
    }
    return std::nullopt;
  }
  return std::nullopt;
}

// Whether the word "word" stands in text as a whole word.
bool has_word(const std::string& text, const std::string& word) {
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    const std::size_t end = at + word.size();
    if ((at == 0 || !is_word(text[at - 1])) && (end == text.size() || !is_word(text[end]))) return true;
  }
  return false;
}

// The first word of text (whole, from where it starts) whose end satisfies `follows`.
template <typename Follows>
std::optional<std::string> first_word(const std::string& text, Follows follows) {
  for (std::size_t at = 0; at < text.size();) {
    if (!is_word(text[at])) {
      ++at;
      continue;
    }
    const std::size_t end = skip_word(text, at);
    if (follows(end)) return text.substr(at, end - at);
    at = end;
  }
  return std::nullopt;
}

// A member defined outside its class: the class's name before "::NAME (" or "::~NAME (".
std::optional<std::string> owner_name(const std::string& head) {
  return first_word(head, [&head](std::size_t end) {
    if (!starts_with(head, end, "::")) return false;
    std::size_t at = end + 2;
    if (at < head.size() && head[at] == '~') ++at;
    const std::size_t after = skip_word(head, at);
    if (after == at) return false;
    const std::size_t open = skip_space(head, after);
    return open < head.size() && head[open] == '(';
  });
}

// The name an item defines or declares, from the text before its body or its end.
std::optional<std::string> name_of(const std::string& text) {
  const std::string head = without_template_heads(text);
  if (auto name = type_name(head)) return name;
  const std::size_t at = skip_space(head, 0);
  const bool using_word = starts_with(head, at, "using") && (at + 5 == head.size() || !is_word(head[at + 5]));
  if (using_word) {  // using NAME = ...
    const std::size_t name = skip_space(head, at + 5);
    const std::size_t end = skip_word(head, name);
    const std::size_t equals = skip_space(head, end);
    if (name > at + 5 && end > name && equals < head.size() && head[equals] == '=')
      return head.substr(name, end - name);
  }
  if (has_word(head, "operator")) return "operator";  // used where its operands are: always needed
  if (using_word) return std::nullopt;
  if (auto owner = owner_name(head)) return owner;  // a member defined outside its class belongs to it
  auto call = first_word(head, [&head](std::size_t end) {
    const std::size_t open = skip_space(head, end);
    return open < head.size() && head[open] == '(';
  });
  if (call) return call;
  return first_word(head, [&head](std::size_t end) {  // NAME, or NAME = ..., at the end
    const std::size_t next = skip_space(head, end);
    return next == head.size() || head[next] == '=';
  });
}

// Whether a head (the text up to a '{' at namespace scope) opens a function's body: ')' then
// perhaps const, noexcept, a trailing return type, then the brace.
bool opens_function(const std::string& head) {
  for (std::size_t close = head.find(')'); close != std::string::npos; close = head.find(')', close + 1)) {
    std::size_t at = skip_space(head, close + 1);
    if (starts_with(head, at, "const")) at = skip_space(head, at + 5);
    if (starts_with(head, at, "noexcept")) at = skip_space(head, at + 8);
    if (starts_with(head, at, "->")) at = head.find('{', at + 2);
    if (at != std::string::npos && at + 1 == head.size() && head[at] == '{') return true;
  }
  return false;
}

// Each "namespace NAME {" (or "namespace {") one space: namespace braces do not open a scope.
std::string without_namespace_opens(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    std::size_t end = std::string::npos;
    if (starts_with(text, i, "namespace") && (i == 0 || !is_word(text[i - 1]))) {
      const std::size_t after = i + 9;
      const std::size_t name = skip_space(text, after);
      std::size_t name_end = name;
      while (name_end < text.size() && (is_word(text[name_end]) || text[name_end] == ':')) ++name_end;
      const std::size_t named = skip_space(text, name_end);
      if (name > after && name_end > name && named < text.size() && text[named] == '{') end = named + 1;
      else if (name < text.size() && text[name] == '{') end = name + 1;
    }
    if (end == std::string::npos) {
      out += text[i++];
      continue;
    }
    out += ' ';
    i = end;
  }
  return out;
}

// Namespace-scope items of a file: (name, text) pairs of those with a name, namespaces opened
// through.
std::vector<Item> items_of(const std::string& file_text) {
  const std::string text = without_namespace_opens(code_of(file_text));
  std::vector<Item> items;
  auto add = [&items](std::optional<std::string> name, const std::string& item) {
    if (name) items.emplace_back(*name, item);
  };
  int depth = 0;
  std::string item;
  std::optional<std::string> head;
  for (const char c : text) {
    item += c;
    if (c == '{') {
      if (depth == 0 && !head) head = item;
      ++depth;
    } else if (c == '}') {
      if (depth == 0) {  // a namespace closes
        item.clear();
        continue;
      }
      --depth;
      // A function body ends the item; a type's or an initialiser's brace waits for its ';'.
      if (depth == 0 && head && opens_function(*head)) {
        add(name_of(head->substr(0, head->size() - 1)), item);
        item.clear();
        head.reset();
      }
    } else if (c == ';' && depth == 0) {
      add(name_of(head ? head->substr(0, head->size() - 1) : item.substr(0, item.size() - 1)), item);
      item.clear();
      head.reset();
    }
  }
  return items;
}

// The identifiers of a text.
Words words_of(const std::string& text) {
  Words words;
  for (std::size_t at = 0; at < text.size();) {
    if (!is_word(text[at])) {
      ++at;
      continue;
    }
    const std::size_t end = skip_word(text, at);
    if (!(text[at] >= '0' && text[at] <= '9')) words.insert(text.substr(at, end - at));
    at = end;
  }
  return words;
}

// The names of a folder that match "*" (no leading dot), each as FOLDER/NAME, sorted.
std::vector<std::string> glob_all(const std::string& folder) {
  std::vector<std::string> paths;
  std::error_code error;
  for (fs::directory_iterator entry(folder, error), end; !error && entry != end; entry.increment(error)) {
    const std::string name = entry->path().filename().string();
    if (!name.empty() && name[0] != '.') paths.push_back(folder + "/" + name);
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// RELEASE/autograder/moduleNN_*/*_checks.hpp, sorted.
std::vector<std::string> checks_headers(const std::string& root) {
  std::vector<std::string> headers;
  const std::string prefix = root + "/autograder/";
  for (const std::string& folder : glob_all(root + "/autograder")) {
    const std::string name = folder.substr(prefix.size());
    auto digit = [&name](std::size_t at) { return name[at] >= '0' && name[at] <= '9'; };
    if (name.size() < 9 || !starts_with(name, 0, "module") || !digit(6) || !digit(7) || name[8] != '_') continue;
    for (const std::string& file : glob_all(folder))
      if (ends_with(file, "_checks.hpp")) headers.push_back(file);
  }
  std::sort(headers.begin(), headers.end());
  return headers;
}

// The names that the header declares and nothing released of its module folder needs, sorted.
std::vector<std::string> unneeded(const std::string& header) {
  const std::string folder = header.substr(0, header.rfind('/'));
  const std::string source = header.substr(0, header.size() - 4) + ".cpp";
  const std::vector<Item> declared = items_of(slurp(header));
  std::vector<Item> items = declared;
  if (fs::is_regular_file(source)) {
    const std::vector<Item> defined = items_of(slurp(source));
    items.insert(items.end(), defined.begin(), defined.end());
  }
  std::map<std::string, std::string> text;
  for (const Item& item : items) text[item.first] += item.second + "\n";

  // The roots: every word of the module's other released files (hidden/ left out).
  Words roots;
  std::vector<std::string> files = glob_all(folder);
  const std::vector<std::string> visible = glob_all(folder + "/visible");
  files.insert(files.end(), visible.begin(), visible.end());
  for (const std::string& file : files) {
    if (!fs::is_regular_file(file) || file == header || file == source) continue;
    const Words words = words_of(code_of(slurp(file)));
    roots.insert(words.begin(), words.end());
  }
  roots.insert("operator");  // an operator is used wherever its operands are
  Words needed;
  std::deque<std::string> queue;
  for (const auto& entry : text)
    if (roots.count(entry.first)) queue.push_back(entry.first);
  while (!queue.empty()) {
    const std::string name = queue.front();
    queue.pop_front();
    if (!needed.insert(name).second) continue;
    const Words words = words_of(text[name]);
    for (const auto& entry : text)
      if (words.count(entry.first) && !needed.count(entry.first)) queue.push_back(entry.first);
  }
  Words unused;
  for (const Item& item : declared)
    if (!needed.count(item.first)) unused.insert(item.first);
  return {unused.begin(), unused.end()};
}

}  // namespace

int main(int argc, char** argv) {
  const fmbd::cli::Command command = fmbd::cli::program("fmbd-hidden-only-helpers", {}, "RELEASE", 1, "RELEASE");
  fmbd::cli::Parsed parsed;
  if (const auto status = fmbd::cli::parse_program(command, argc, argv, parsed)) return *status;
  std::string root = parsed.positionals.empty() ? "" : parsed.positionals.front();
  if (root.empty()) {
    std::cerr << fmbd::cli::program_usage(command);
    return 2;
  }
  while (!root.empty() && root.back() == '/') root.pop_back();
  bool found = false;
  try {
    for (const std::string& header : checks_headers(root)) {
      for (const std::string& name : unneeded(header)) {
        std::cout << header.substr(root.size() + 1) << ": " << name << "\n";
        found = true;
      }
    }
  } catch (const Unreadable& error) {
    std::cout.flush();
    std::cerr << error.message << "\n";
    return 2;
  }
  return found ? 1 : 0;
}
