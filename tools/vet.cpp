// fmbd-vet: the source check of exercise files, run before their tests count (issue 17).
//
//   fmbd-vet --allow FILE --cxx COMPILER --report FILE [--nm NM] [--root DIR]
//            [--include-dirs "A;B"] [--defines "X;Y=1"] [--given "OBJECT;..."]...
//            [--exit-zero] --library LIB.a SOURCE... [--library LIB.a SOURCE...]...
//
// For each SOURCE (an exercise file compiled into the static library LIB as member NAME.o):
//   1. its directives, read from the file itself (lines spliced, comments removed): only
//      #include, #define, #undef, #if..., #error and #warning; every #include names its header
//      literally (no macro, no "..") and the header is on the allow-list;
//   2. its tokens as the compiler sees them (`COMPILER -E`, keeping the lines that the line
//      markers give to SOURCE itself), so that macros are checked expanded: no asm, extern,
//      __attribute__, attributes other than the standard ones, #pragma or _Pragma,
//      __builtin_* other than libm's, main, Catch, or the harness's namespaces;
//   3. its object (`NM LIB`): every symbol it uses is on the allow-list (C names exactly; C++
//      names by top-level namespace, less the refused ones such as file streams); every
//      global symbol it defines lies in namespace fmbd (no replacing a C library function,
//      the global operator new or a function of the harness), and none redefines what the
//      given code, the tests (--given) or another member of LIB define. Weak data that the
//      compiler emits by itself is not the student's definition: the typeinfo of any type other
//      than a class named outside fmbd (a function type, a pointer, an instantiation, whatever
//      types it mentions), and <new>'s inline placement new and delete (tests/tools/data/vet:
//      legal constructs; tools/vet_variants.cpp: every task function through std::function).
// The allow-list (autograder/vet_allow.txt) documents its format.
//
// Writes the findings to --report, one "FILE:LINE: reason" line and one "  fix: ..." line
// each, FILE relative to --root; an empty report when all is well.
// Exit status: 0 clean (or refused, with --exit-zero), 1 refused, 2 usage or tool error.

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "process.hpp"
#include "strings.hpp"
#include "vet_support.hpp"

namespace fmbd::vet {
namespace {

using fmbd::tools::is_identifier_char;
using fmbd::tools::is_identifier_start;

std::string trim_left(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t\f\v\r");
  return first == std::string::npos ? "" : text.substr(first);
}

class Vet {
 public:
  Vet(const AllowList& allow, std::string display_name)
      : allow_(allow), file_(std::move(display_name)) {}

  const std::vector<Finding>& findings() const { return findings_; }

  // Drops the findings so far: with --checks symbols, checks 1 and 2 run only for the lines that
  // check 3 names (the first line of each identifier, macros expanded), and their own report is
  // another run's (--checks sources).
  void forget_findings() { findings_.clear(); }

  // 1. Directives of the file as written.
  void check_directives(const std::string& source) {
    // Splice continued lines, remembering where each logical line starts.
    std::vector<std::pair<int, std::string>> lines;
    std::istringstream in(source);
    std::string physical;
    int number = 0;
    int start = 1;
    std::string logical;
    while (std::getline(in, physical)) {
      ++number;
      if (!physical.empty() && physical.back() == '\r') physical.pop_back();
      if (logical.empty()) start = number;
      if (!physical.empty() && physical.back() == '\\') {
        logical += physical.substr(0, physical.size() - 1);
        continue;
      }
      lines.emplace_back(start, logical + physical);
      logical.clear();
    }
    if (!logical.empty()) lines.emplace_back(start, logical);

    bool in_comment = false;
    for (auto& [line, text] : lines) {
      text = strip_comments(text, in_comment);
      std::string rest = trim_left(text);
      if (rest.compare(0, 1, "#") == 0) {
        rest = trim_left(rest.substr(1));
      } else if (rest.compare(0, 2, "%:") == 0) {
        rest = trim_left(rest.substr(2));
      } else {
        continue;
      }
      std::size_t end = 0;
      while (end < rest.size() && is_identifier_char(rest[end])) ++end;
      const std::string directive = rest.substr(0, end);
      static const std::set<std::string> kAllowed = {"",      "define", "undef", "if",    "ifdef", "ifndef",
                                                     "elif",  "else",   "endif", "error", "warning"};
      if (directive == "include") {
        check_include(line, trim_left(rest.substr(end)));
      } else if (!kAllowed.count(directive)) {
        add(line, "#" + directive + " is not allowed in exercise files",
            directive == "pragma" ? "remove the #pragma; silence a warning in code instead, e.g. (void)x"
                                  : "remove the directive");
      }
    }
  }

  // 2. Tokens after preprocessing, on the lines that come from the file itself.
  void check_tokens(const std::string& preprocessed, const std::string& compiled_name) {
    std::istringstream in(preprocessed);
    std::string text;
    std::string current;
    int line = 0;
    TokenState state;
    while (std::getline(in, text)) {
      if (is_line_marker(text)) {
        const std::size_t quote = text.find('"');
        line = std::atoi(text.c_str() + 2);
        current = unquote(text.substr(quote));
        continue;
      }
      if (current == compiled_name) {
        if (!state.in_raw_string && trim_left(text).compare(0, 1, "#") == 0) {
          add(line, "#pragma or _Pragma is not allowed in exercise files",
              "remove it; silence a warning in code instead, e.g. (void)x");
        } else {
          tokenize(text, line, state);
        }
      }
      ++line;
    }
  }

  // 3. The symbols of the compiled file. `symbols`: (type, mangled, demangled) each.
  void check_symbols(const std::vector<std::tuple<char, std::string, std::string>>& symbols,
                     const std::set<std::string>& defined_elsewhere) {
    for (const auto& [type, mangled, demangled] : symbols) {
      if (mangled.compare(0, 7, "DW.ref.") == 0) continue;  // the compiler's, for exception handling
      const std::string root = root_namespace(mangled);
      const std::string shown = demangled.size() > 120 ? demangled.substr(0, 117) + "..." : demangled;
      if (type == 'U' || type == 'w' || type == 'v') {
        if (!use_allowed(mangled, demangled, root)) {
          add(line_of(demangled), "uses " + shown + ", which exercise files may not use",
              "remove it: an exercise needs no files, processes, system calls or exit(); print "
              "debug output with std::cout or printf");
        }
        continue;
      }
      if (type == 'i') {
        add(line_of(demangled), "defines the indirect function " + shown, "remove it");
        continue;
      }
      const bool strong = std::strchr("TDBRGSC", type) != nullptr;
      const bool weak = std::strchr("WVu", type) != nullptr;
      if (!strong && !weak) continue;  // local to the file
      if (refused(demangled) || root == "Catch") {
        add(line_of(demangled), "defines " + shown + " in the test harness",
            "exercise files implement the course's functions only");
      } else if (strong && root != "fmbd") {
        add(line_of(demangled), outside_reason(shown, root), outside_fix(root));
      } else if (weak && root != "fmbd" && !allow_.namespaces.count(root) &&
                 !(root.empty() && allow_.symbols.count(mangled)) &&  // a compiler's own helper
                 !compiler_data(mangled)) {
        add(line_of(demangled), outside_reason(shown, root), outside_fix(root));
      } else if (strong && defined_elsewhere.count(mangled)) {
        add(line_of(demangled), "defines " + shown + ", which the course's own code defines",
            "rename your function, or use the course's one");
      }
    }
  }

 private:
  struct TokenState {
    bool in_raw_string = false;
    std::string raw_end;  // )delimiter"
    std::string previous;  // the last token
    std::string before_previous;
    bool in_attribute = false;
    int attribute_line = 0;
    bool attribute_bad = false;
  };

  static bool is_line_marker(const std::string& text) {
    return text.size() > 3 && text[0] == '#' && text[1] == ' ' &&
           std::isdigit(static_cast<unsigned char>(text[2])) && text.find('"') != std::string::npos;
  }

  // "\"a\\\\b\" 1 3" -> a\b
  static std::string unquote(const std::string& text) {
    std::string out;
    for (std::size_t i = 1; i < text.size() && text[i] != '"'; ++i) {
      if (text[i] == '\\' && i + 1 < text.size()) ++i;
      out += text[i];
    }
    return out;
  }

  // Removes comments and the contents of string and character literals (kept as "").
  static std::string strip_comments(const std::string& text, bool& in_comment) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
      if (in_comment) {
        if (text.compare(i, 2, "*/") == 0) {
          in_comment = false;
          ++i;
          out += ' ';
        }
        continue;
      }
      if (text.compare(i, 2, "//") == 0) break;
      if (text.compare(i, 2, "/*") == 0) {
        in_comment = true;
        ++i;
        continue;
      }
      out += text[i];
      if (text[i] == '"' || text[i] == '\'') {
        const char quote = text[i];
        const bool header = quote == '"' && out.find("include") != std::string::npos;
        std::size_t j = i + 1;
        while (j < text.size() && text[j] != quote) {
          if (text[j] == '\\') ++j;
          ++j;
        }
        if (header) out += text.substr(i + 1, j - i - 1);  // the name of a quoted #include
        out += quote;
        i = j;
      }
    }
    return out;
  }

  void check_include(int line, const std::string& rest) {
    const char open = rest.empty() ? '\0' : rest[0];
    const char close = open == '<' ? '>' : '"';
    const std::size_t end = rest.find(close, 1);
    if ((open != '<' && open != '"') || end == std::string::npos ||
        !trim_left(rest.substr(end + 1)).empty()) {
      add(line, "#include must name its header directly, as <name> or \"name\"",
          "write the header's name; a macro may not name it");
      return;
    }
    const std::string name = rest.substr(1, end - 1);
    if (name.find("..") != std::string::npos || !header_allowed(allow_, name)) {
      add(line, "#include " + std::string(1, open) + name + std::string(1, close) +
                    ": this header is not allowed in exercise files",
          "use the course's headers (fmbd/...), Eigen and the standard headers listed in "
          "autograder/vet_allow.txt; for debug output <iostream> or <cstdio>");
    }
  }

  void tokenize(const std::string& text, int line, TokenState& state) {
    std::size_t i = 0;
    if (state.in_raw_string) {
      const std::size_t end = text.find(state.raw_end);
      if (end == std::string::npos) return;
      state.in_raw_string = false;
      i = end + state.raw_end.size();
    }
    while (i < text.size()) {
      const char c = text[i];
      if (std::isspace(static_cast<unsigned char>(c))) {
        ++i;
      } else if (is_identifier_start(c)) {
        std::size_t end = i;
        while (end < text.size() && is_identifier_char(text[end])) ++end;
        const std::string word = text.substr(i, end - i);
        i = end;
        if (i < text.size() && (text[i] == '"' || text[i] == '\'')) {
          if (text[i] == '"' && (word == "R" || word == "u8R" || word == "uR" || word == "UR" || word == "LR")) {
            const std::size_t paren = text.find('(', i);
            state.raw_end = ")" + text.substr(i + 1, paren == std::string::npos ? 0 : paren - i - 1) + "\"";
            const std::size_t close = paren == std::string::npos ? std::string::npos : text.find(state.raw_end, paren);
            if (close == std::string::npos) {
              state.in_raw_string = true;
              return;
            }
            i = close + state.raw_end.size();
            continue;
          }
          if (word == "u8" || word == "u" || word == "U" || word == "L") continue;  // literal next
        }
        identifier(word, line, state);
      } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                 (c == '.' && i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1])))) {
        ++i;
        while (i < text.size() && (is_identifier_char(text[i]) || text[i] == '.' || text[i] == '\'' ||
                                   ((text[i] == '+' || text[i] == '-') &&
                                    std::strchr("eEpP", text[i - 1]) != nullptr))) {
          ++i;
        }
        push(state, "0");
      } else if (c == '"' || c == '\'') {
        std::size_t j = i + 1;
        while (j < text.size() && text[j] != c) {
          if (text[j] == '\\') ++j;
          ++j;
        }
        i = j + 1;
        push(state, "\"\"");
      } else {
        std::string punct(1, c);
        if ((c == ':' || c == '[' || c == ']') && i + 1 < text.size() && text[i + 1] == c) punct += c;
        i += punct.size();
        punctuation(punct, line, state);
      }
    }
  }

  void push(TokenState& state, const std::string& token) {
    state.before_previous = state.previous;
    state.previous = token;
  }

  void punctuation(const std::string& punct, int line, TokenState& state) {
    if (punct == "[[" && !state.in_attribute) {
      state.in_attribute = true;
      state.attribute_line = line;
      state.attribute_bad = false;
    } else if (punct == "]]" && state.in_attribute) {
      state.in_attribute = false;
      if (state.attribute_bad) {
        add(state.attribute_line, "this attribute is not allowed in exercise files",
            "remove it; [[nodiscard]], [[maybe_unused]], [[fallthrough]], [[likely]], "
            "[[unlikely]], [[noreturn]] and [[deprecated]] are fine");
      }
    } else if (state.in_attribute && punct == "::") {
      state.attribute_bad = true;
    }
    push(state, punct);
  }

  void identifier(const std::string& word, int line, TokenState& state) {
    first_line_.emplace(word, line);
    if (state.in_attribute) {
      static const std::set<std::string> kStandard = {"maybe_unused", "nodiscard", "fallthrough", "likely",
                                                      "unlikely",     "noreturn",  "deprecated"};
      if (!kStandard.count(word)) state.attribute_bad = true;
    }
    if (word == "asm" || word == "__asm" || word == "__asm__") {
      add(line, "inline assembly (" + word + ") is not allowed in exercise files", "write plain C++");
    } else if (word == "extern") {
      add(line, "'extern' is not allowed in exercise files",
          "remove it: include the header that declares what you need, and define your functions "
          "without extern \"C\"");
    } else if (word == "__attribute__" || word == "__attribute") {
      add(line, "__attribute__ is not allowed in exercise files",
          "remove it; the standard attributes such as [[maybe_unused]] are fine");
    } else if (word == "_Pragma") {
      add(line, "_Pragma is not allowed in exercise files", "remove it");
    } else if (word.compare(0, 10, "__builtin_") == 0 && !math_allowed(allow_, word.substr(10))) {
      add(line, word + " is not allowed in exercise files", "use the function of <cmath> or <cstring>");
    } else if (word == "Catch" || word.compare(0, 6, "CATCH_") == 0) {
      add(line, "'" + word + "' names the test framework", "exercise files implement the course's functions only");
    } else if ((word == "testing" || word == "grade") && (state.previous == "::" || state.previous == "namespace") &&
               (state.previous == "namespace" || state.before_previous == "fmbd")) {
      add(line, "'fmbd::" + word + "' is the test harness's namespace",
          "exercise files implement the course's functions only");
    } else if ((word == "new" || word == "delete") && state.previous == "operator") {
      names_allocation_ = true;  // defines or calls an operator new or delete by name
    } else if (word == "main") {
      add(line, "an exercise file may not define or call main()",
          "remove main(); run your code from the tests (./workbook grade) or a demo");
    }
    push(state, word);
  }

  // A weak definition that the compiler emits by itself, not the student's code:
  //   - the typeinfo object or name (_ZTI, _ZTS) of any type that is not itself a class named
  //     outside fmbd and the allowed namespaces: a function type, a pointer, a reference, an
  //     instantiation of a library template, whatever types it mentions (std::function made from
  //     a function pointer over Eigen types, say). A class of the student's own outside fmbd is
  //     refused through its own typeinfo and its member functions;
  //   - the library's inline placement new and delete (<new>, emitted by unoptimised builds),
  //     when the file does not name an operator new or delete itself.
  bool compiler_data(const std::string& mangled) const {
    static const std::set<std::string> kPlacement = {"_ZnwmPv", "_ZnamPv", "_ZnwjPv", "_ZnajPv",
                                                     "_ZdlPvS_", "_ZdaPvS_"};
    if (kPlacement.count(mangled)) return !names_allocation_;
    if (mangled.compare(0, 4, "_ZTI") != 0 && mangled.compare(0, 4, "_ZTS") != 0) return false;
    return !names_a_class(mangled.substr(4));
  }

  // Whether a mangled <type> is a class type by its name: <source-name>, N...E or a local Z...
  static bool names_a_class(const std::string& type) {
    return !type.empty() && (std::isdigit(static_cast<unsigned char>(type[0])) || type[0] == 'N' || type[0] == 'Z');
  }

  static std::string outside_reason(const std::string& shown, const std::string& root) {
    return "defines " + shown + (root.empty() ? " with a C name, outside every namespace" : " outside namespace fmbd");
  }

  // The fix for a definition outside namespace fmbd whose top-level name is `root`.
  static std::string outside_fix(const std::string& root) {
    if (root.empty()) {
      return "put it inside namespace fmbd, outside any extern \"C\" block (a C name has no namespace)";
    }
    if (root == "?") return "put your functions and helpers inside namespace fmbd";
    return "put " + root + " inside namespace fmbd, with your functions and helpers";
  }

  bool refused(const std::string& demangled) const {
    for (const std::string& text : allow_.refused) {
      if (demangled.find(text) != std::string::npos) return true;
    }
    return false;
  }

  bool use_allowed(const std::string& mangled, const std::string& demangled, const std::string& root) const {
    if (root.empty()) return allow_.symbols.count(mangled) || math_allowed(allow_, mangled);
    if (root == "operator new") return true;
    return allow_.namespaces.count(root) && !refused(demangled);
  }

  // The first line of the file that names a word of `name` (not a common type or namespace).
  int line_of(const std::string& name) const {
    static const std::set<std::string> kCommon = {"std", "__cxx11", "char", "const", "int", "long", "unsigned",
                                                  "double", "float", "void", "bool", "fmbd", "Eigen", "for",
                                                  "operator", "vtable", "typeinfo", "guard", "variable", "name"};
    for (std::size_t i = 0; i < name.size();) {
      if (!is_identifier_start(name[i])) {
        ++i;
        continue;
      }
      std::size_t end = i;
      while (end < name.size() && is_identifier_char(name[end])) ++end;
      const std::string word = name.substr(i, end - i);
      i = end;
      if (kCommon.count(word)) continue;
      const auto found = first_line_.find(word);
      if (found != first_line_.end()) return found->second;
    }
    return 0;
  }

  void add(int line, const std::string& reason, const std::string& fix) {
    findings_.push_back({file_, line, reason, fix});
  }

  const AllowList& allow_;
  std::string file_;
  std::vector<Finding> findings_;
  std::map<std::string, int> first_line_;  // identifier -> first line that names it
  bool names_allocation_ = false;           // the file writes `operator new` or `operator delete`
};

// The mangled names that the members of `symbols` other than `except` define.
void add_definitions(const Symbols& symbols, const std::string& except, std::set<std::string>& defined) {
  for (const auto& [member, member_symbols] : symbols.members) {
    if (member == except) continue;
    for (const auto& [type, mangled, demangled] : member_symbols)
      if (type != 'U' && type != 'w' && type != 'v' && std::isupper(static_cast<unsigned char>(type)))
        defined.insert(mangled);
  }
}

// Checks 1 and 2 of one source: its directives and its preprocessed tokens.
void check_source(const Options& options, const std::string& source, Vet& check) {
  check.check_directives(read_whole(source));
  std::vector<std::string> command = {options.cxx, "-std=c++17", "-E"};
  for (const std::string& dir : options.include_dirs) command.push_back("-I" + dir);
  for (const std::string& define : options.defines) command.push_back("-D" + define);
  command.push_back(source);
  const auto [status, preprocessed] = run(command);
  if (status != 0) throw Failure{"the compiler could not preprocess " + source};
  check.check_tokens(preprocessed, source);
}

int vet(const Options& options) {
  const AllowList allow = read_allow_list(options.allow_file);
  std::vector<Finding> findings;
  std::set<std::string> given_defined;  // mangled names the given code and the tests define
  if (options.symbols)
    for (const std::string& object : options.given) add_definitions(read_symbols(options.nm, object), "", given_defined);
  for (const auto& [library, sources] : options.libraries) {
    const Symbols symbols = options.symbols ? read_symbols(options.nm, library) : Symbols{};
    for (const std::string& source : sources) {
      Vet check(allow, display_name(options, source));
      check_source(options, source, check);
      if (!options.sources) check.forget_findings();
      if (options.symbols) {
        const std::string member = base_name(source) + ".o";
        const auto own = symbols.members.find(member);
        if (own == symbols.members.end()) throw Failure{library + " has no member " + member + " (build it first)"};
        std::set<std::string> elsewhere = given_defined;
        add_definitions(symbols, member, elsewhere);
        check.check_symbols(own->second, elsewhere);
      }
      findings.insert(findings.end(), check.findings().begin(), check.findings().end());
    }
  }

  std::sort(findings.begin(), findings.end());
  findings.erase(std::unique(findings.begin(), findings.end(),
                             [](const Finding& a, const Finding& b) {
                               return a.file == b.file && a.line == b.line && a.reason == b.reason;
                             }),
                 findings.end());
  std::string report;
  for (const Finding& finding : findings) {
    report += finding.file + (finding.line > 0 ? ":" + std::to_string(finding.line) : std::string()) + ": " +
              finding.reason + "\n  fix: " + finding.fix + "\n";
  }
  std::ofstream out(options.report, std::ios::trunc);
  out << report;
  out.close();
  if (!out) throw Failure{"cannot write " + options.report};
  std::cout << report;
  return findings.empty() || options.exit_zero ? 0 : 1;
}

}  // namespace
}  // namespace fmbd::vet

int main(int argc, char** argv) {
  using namespace fmbd::vet;
  const fmbd::cli::Command command = command_line();
  fmbd::cli::Parsed parsed;
  if (const auto status = fmbd::cli::parse_program(command, argc, argv, parsed)) return *status;
  try {
    return vet(options_of(parsed));
  } catch (const Failure& failure) {
    std::cerr << "fmbd-vet: " << failure.message << "\n" << (failure.usage ? fmbd::cli::program_usage(command) : "");
    return 2;
  }
}
