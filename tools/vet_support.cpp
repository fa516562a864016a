// Definitions of tools/vet_support.hpp.
#include "vet_support.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include "cli.hpp"
#include "process.hpp"
#include "strings.hpp"

namespace fmbd::vet {

AllowList read_allow_list(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Failure{"cannot read the allow-list " + path};
  AllowList allow;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line);
    std::string kind, name;
    if (!(words >> kind) || kind[0] == '#') continue;
    if (!(words >> name)) throw Failure{path + ":" + std::to_string(number) + ": " + kind + " needs a name"};
    if (kind == "header") {
      allow.headers.push_back(name);
    } else if (kind == "symbol") {
      allow.symbols.insert(name);
    } else if (kind == "math") {
      allow.math.insert(name);
    } else if (kind == "namespace") {
      allow.namespaces.insert(name);
    } else if (kind == "refuse") {
      allow.refused.push_back(name);
    } else {
      throw Failure{path + ":" + std::to_string(number) + ": unknown entry '" + kind + "'"};
    }
  }
  return allow;
}

bool header_allowed(const AllowList& allow, const std::string& name) {
  for (const std::string& entry : allow.headers) {
    if (entry.back() == '/' ? name.compare(0, entry.size(), entry) == 0 && name.size() > entry.size()
                            : name == entry) {
      return true;
    }
  }
  return false;
}

// NAME, NAMEf or NAMEl of a libm entry.
bool math_allowed(const AllowList& allow, const std::string& name) {
  if (allow.math.count(name)) return true;
  const char last = name.empty() ? '\0' : name.back();
  return (last == 'f' || last == 'l') && allow.math.count(name.substr(0, name.size() - 1));
}


// By file, then by line; findings without a line last.
bool operator<(const Finding& a, const Finding& b) {
  return std::make_tuple(a.file, a.line == 0, a.line, a.reason) <
         std::make_tuple(b.file, b.line == 0, b.line, b.reason);
}

// Runs argv and returns its exit status and standard output (stderr passes through).
std::pair<int, std::string> run(const std::vector<std::string>& argv) {
  int status = 0;
  std::string output = tools::capture(tools::Command(argv), status);
  return {status, std::move(output)};
}

// The non-empty fields of a CMake list or path list.
std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts = tools::split(text, separator);
  parts.erase(std::remove(parts.begin(), parts.end(), std::string()), parts.end());
  return parts;
}


// The top-level namespace of a mangled C++ name ("std", "fmbd", ...), "operator new" for the
// global allocation functions, "" for a C name, "?" when unknown.
std::string root_namespace(const std::string& mangled) {
  if (mangled.compare(0, 2, "_Z") != 0) return "";
  std::string s = mangled.substr(2);
  for (const char* special : {"TV", "TI", "TS", "TT", "TC", "GV", "GR", "TH", "TW"}) {
    if (s.compare(0, 2, special) == 0) {
      s = s.substr(2);
      break;
    }
  }
  if (s.compare(0, 2, "Th") == 0 || s.compare(0, 2, "Tv") == 0) {
    const std::size_t underscore = s.find('_', 2);
    if (underscore == std::string::npos) return "?";
    s = s.substr(underscore + 1);
    if (s.compare(0, 1, "n") == 0 || s.compare(0, 1, "_") == 0) s = s.substr(s.find('_') + 1);
  }
  for (const char* allocation : {"nw", "na", "dl", "da"}) {
    if (s.compare(0, 2, allocation) == 0) return "operator new";
  }
  for (std::size_t i = 0; i < s.size();) {
    if (s[i] == 'L' || s[i] == 'Z') {
      ++i;
    } else if (s[i] == 'N') {
      ++i;
      while (i < s.size() && std::strchr("rVKRO", s[i])) ++i;
    } else if (s.compare(i, 2, "St") == 0 || (s[i] == 'S' && i + 1 < s.size() && std::strchr("absiod", s[i + 1]))) {
      return "std";
    } else if (std::isdigit(static_cast<unsigned char>(s[i]))) {
      std::size_t length = 0;
      while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) length = length * 10 + static_cast<std::size_t>(s[i++] - '0');
      return s.substr(i, length);
    } else {
      return "?";
    }
  }
  return "?";
}

// nm's lines: "MEMBER:" headers, "VALUE T NAME" and "         U NAME".
std::vector<std::pair<std::string, std::pair<char, std::string>>> parse_nm(const std::string& output) {
  std::vector<std::pair<std::string, std::pair<char, std::string>>> rows;
  std::istringstream in(output);
  std::string line;
  std::string member;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (line.back() == ':' && line.find(' ') == std::string::npos) {
      member = line.substr(0, line.size() - 1);
      continue;
    }
    std::istringstream words(line);
    std::string first, second;
    words >> first >> second;
    std::string type = first;
    if (line[0] != ' ') type = second;  // a value comes first
    if (type.size() != 1) continue;
    const std::size_t at = line.find(std::string(" ") + type + " ");
    if (at == std::string::npos) continue;
    rows.push_back({member, {type[0], line.substr(at + 3)}});
  }
  return rows;
}

Symbols read_symbols(const std::string& nm, const std::string& file) {
  const auto mangled = run({nm, "-p", file});
  const auto demangled = run({nm, "-p", "-C", file});
  if (mangled.first != 0 || demangled.first != 0) throw Failure{"cannot read the symbols of " + file};
  const auto plain = parse_nm(mangled.second);
  const auto readable = parse_nm(demangled.second);
  if (plain.size() != readable.size()) throw Failure{"nm listed " + file + " differently with and without -C"};
  Symbols symbols;
  for (std::size_t i = 0; i < plain.size(); ++i) {
    symbols.members[plain[i].first].emplace_back(plain[i].second.first, plain[i].second.second,
                                                 readable[i].second.second);
  }
  return symbols;
}

std::string base_name(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string read_whole(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Failure{"cannot read " + path};
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}



cli::Command command_line() {
  using cli::Kind;
  return cli::program("fmbd-vet",
                      {{"--allow", Kind::value, "FILE", "a value", ""},
                       {"--cxx", Kind::value, "COMPILER", "a value", ""},
                       {"--nm", Kind::value, "NM", "a value", ""},
                       {"--report", Kind::value, "FILE", "a value", ""},
                       {"--root", Kind::value, "DIR", "a value", ""},
                       {"--include-dirs", Kind::value, "A;B", "a value", ""},
                       {"--defines", Kind::value, "X;Y=1", "a value", ""},
                       {"--given", Kind::repeatable, "OBJECT;...", "a value", ""},
                       {"--checks", Kind::value, "all|sources|symbols", "a value", ""},
                       {"--exit-zero", Kind::flag, "", "", ""},
                       {"--library", Kind::repeatable, "LIB.a", "a value", ""}},
                      "SOURCE", -1,
                      "--allow FILE --cxx COMPILER --report FILE [--nm NM] [--root DIR]\n"
                      "                [--include-dirs \"A;B\"] [--defines \"X;Y=1\"] [--given \"OBJECT;...\"]...\n"
                      "                [--checks all|sources|symbols] [--exit-zero]\n"
                      "                --library LIB.a SOURCE... [--library LIB.a SOURCE...]...");
}

Options options_of(const cli::Parsed& parsed) {
  Options options;
  options.allow_file = parsed.value("--allow");
  options.cxx = parsed.value("--cxx");
  options.nm = parsed.value("--nm", options.nm);
  options.report = parsed.value("--report");
  options.root = parsed.value("--root");
  options.include_dirs = split(parsed.value("--include-dirs"), ';');
  options.defines = split(parsed.value("--defines"), ';');
  for (const std::string& given : parsed.all("--given")) {
    for (const std::string& object : split(given, ';')) options.given.push_back(object);
  }
  options.exit_zero = parsed.has("--exit-zero");
  if (parsed.has("--checks")) {
    const std::string checks = parsed.value("--checks");
    if (checks != "all" && checks != "sources" && checks != "symbols")
      throw Failure{"--checks takes all, sources or symbols, not " + checks, true};
    options.sources = checks != "symbols";
    options.symbols = checks != "sources";
  }
  // Each SOURCE belongs to the --library before it.
  for (const auto& [name, value] : parsed.sequence) {
    if (name == "--library") {
      options.libraries.push_back({value, {}});
    } else if (name == "SOURCE") {
      if (options.libraries.empty()) throw Failure{"unexpected argument " + value, true};
      options.libraries.back().second.push_back(value);
    }
  }
  if (options.allow_file.empty() || options.cxx.empty() || options.report.empty() || options.libraries.empty())
    throw Failure{"--allow, --cxx, --report and --library are required", true};
  return options;
}

std::string display_name(const Options& options, const std::string& path) {
  const std::string root = options.root.empty() || options.root.back() == '/' ? options.root : options.root + "/";
  return !root.empty() && path.compare(0, root.size(), root) == 0 ? path.substr(root.size()) : path;
}

}  // namespace fmbd::vet
