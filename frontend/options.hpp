#pragma once
// The options of the front end's commands: one table per command, from which come both the
// parsing (with the messages ./workbook has always given) and the command's part of the usage
// text.
//
// A command line is parsed left to right; the first problem ends it with a UsageError whose
// message main() prints after "workbook: " (exit status 2):
//   an unknown option            "handin: unknown option '--x'" (+ the command's unknown_hint)
//   a value missing              "--out needs a file name"  (the option's `needs`)
//   a number that is none        "--module needs a number, got 'x'"
//   a positional too many        the command's too_many text, or "unknown option" when the
//                                command takes none
// -h and --help ask for the usage (ParsedOptions::help); after "--" the rest is the command's
// when it takes it (pass_rest), else "--" is an unknown option.

#include <iosfwd>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace fmbd::frontend {

// A wrong command line, or a command that cannot go on here: what() is the message, without
// "workbook: " (exit status 2, exit_status.hpp).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class OptionKind {
  flag,        // --reset: present or not
  value,       // --out FILE: one value, the last one given wins
  repeatable,  // --module N, as often as wanted: every value, in order
  number,      // --timeout SEC: one value of digits and dots
};

struct OptionSpec {
  std::string name;        // "--out"
  OptionKind kind = OptionKind::flag;
  std::string value_name;  // in the usage text: "FILE.zip"
  std::string needs;       // what a missing value is: "a file name" ("--out needs a file name")
  std::string help;        // one line, for tables of options (the usage text is the command's)
};

struct CommandSpec {
  std::string name;                  // "hint"
  std::vector<OptionSpec> options;
  std::string positional;            // "TASK", or empty: no positional arguments
  int max_positionals = 0;
  std::string too_many;              // the message for one positional too many
  std::string unknown_hint;          // after "unknown option '...'", e.g. " (see ./workbook help)";
                                     // "{option}" in it stands for the option refused
  bool pass_rest = false;            // whether "--" ends the options and passes the rest on
  std::string synopsis;              // the usage line after the name; empty: made from the table
  std::vector<std::string> help;     // the lines that describe the command, as the usage prints them
};

struct ParsedOptions {
  bool help = false;                                       // -h or --help was given
  std::map<std::string, std::vector<std::string>> values;  // option -> its values ("" for a flag)
  std::vector<std::string> positionals;
  bool ended = false;                                      // "--" was given (pass_rest)
  std::vector<std::string> rest;                           // after "--" (pass_rest)

  bool has(const std::string& option) const { return values.count(option) > 0; }
  // The last value of `option`, or `fallback`.
  std::string value(const std::string& option, const std::string& fallback = "") const;
  // Every value of `option`, in order.
  std::vector<std::string> all(const std::string& option) const;
};

// The arguments after the command's name, parsed after `spec`. Throws UsageError. With -h or
// --help, parsing stops there (the rest is not looked at).
ParsedOptions parse_options(const CommandSpec& spec, const std::vector<std::string>& args);

// With -h or --help (parsed.help): the command's usage (usage_text, under the workbook's usage
// line, and where the whole text is) on `out`, and true; else false.
bool print_usage_if_asked(const ParsedOptions& parsed, const CommandSpec& spec, std::ostream& out);

// The value of --hidden-visibility (grade, gradescope): one of Gradescope's visibilities, or a
// UsageError that lists them.
void check_visibility(const std::string& value);

// The usage line of the command: "hint [TASK] [--reset]", made from the table (or `synopsis`).
std::string synopsis(const CommandSpec& spec);

// The command's part of the usage text: "  " + synopsis, then its help lines indented by eight
// spaces, each line ending in "\n".
std::string usage_text(const CommandSpec& spec);

}  // namespace fmbd::frontend
