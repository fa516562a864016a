#pragma once
// fmbd-vet's ground floor (tools/vet.cpp is the program and its checks): the allow-list, the
// findings, the symbol tables that nm gives, the command line, and the top-level namespace of a
// mangled name. tools/vet_support.cpp defines the functions.

#include <map>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "cli.hpp"

namespace fmbd::vet {

/// A usage or tool error: fmbd-vet prints it (and the usage when `usage`) and exits 2.
struct Failure {
  std::string message;
  bool usage = false;  // print the usage after the message
};

/// autograder/vet_allow.txt, read (its header documents the format).
struct AllowList {
  std::vector<std::string> headers;  // exact, or a folder prefix ending in '/'
  std::set<std::string> symbols;
  std::set<std::string> math;
  std::set<std::string> namespaces;
  std::vector<std::string> refused;
};

/// Reads the allow-list at `path`; a Failure names a malformed line.
AllowList read_allow_list(const std::string& path);
/// Whether an #include of `name` is allowed (exact, or below a folder entry ending in '/').
bool header_allowed(const AllowList& allow, const std::string& name);
/// Whether `name` is NAME, NAMEf or NAMEl of a libm entry.
bool math_allowed(const AllowList& allow, const std::string& name);

/// One refusal: FILE:LINE: reason, and its fix.
struct Finding {
  std::string file;
  int line = 0;  // 0: the file as a whole
  std::string reason;
  std::string fix;
};

/// By file, then by line; findings without a line last.
bool operator<(const Finding& a, const Finding& b);

/// Runs argv and returns its exit status and standard output (stderr passes through).
std::pair<int, std::string> run(const std::vector<std::string>& argv);
/// The non-empty fields of a CMake list or path list.
std::vector<std::string> split(const std::string& text, char separator);

/// The top-level namespace of a mangled C++ name ("std", "fmbd", ...), "operator new" for the
/// global allocation functions, "" for a C name, "?" when unknown.
std::string root_namespace(const std::string& mangled);

/// The symbols of an object or archive, by member.
struct Symbols {
  // member -> (type, mangled, demangled)
  std::map<std::string, std::vector<std::tuple<char, std::string, std::string>>> members;
};

/// nm's lines: "MEMBER:" headers, "VALUE T NAME" and "         U NAME".
std::vector<std::pair<std::string, std::pair<char, std::string>>> parse_nm(const std::string& output);
/// `NM -p` and `NM -p -C` of `file`, paired: (type, mangled, demangled) of each symbol by member.
Symbols read_symbols(const std::string& nm, const std::string& file);
/// The file name of a path; the whole file at a path (a Failure if it cannot be read).
std::string base_name(const std::string& path);
std::string read_whole(const std::string& path);

/// The command line (its table: command_line()).
struct Options {
  std::string allow_file;
  std::string cxx;
  std::string nm = "nm";
  std::string report;
  std::string root;
  std::vector<std::string> include_dirs;
  std::vector<std::string> defines;
  std::vector<std::string> given;
  std::vector<std::pair<std::string, std::vector<std::string>>> libraries;  // library, sources
  bool exit_zero = false;
  bool sources = true;  // checks 1 and 2 (--checks sources|symbols|all)
  bool symbols = true;  // check 3
};

/// The command line's table (fmbd_cli): its parsing and its usage.
cli::Command command_line();
/// The options of a parsed command line; a Failure with the usage on an error.
Options options_of(const cli::Parsed& parsed);
/// `path` relative to --root, as reports show it.
std::string display_name(const Options& options, const std::string& path);

}  // namespace fmbd::vet
