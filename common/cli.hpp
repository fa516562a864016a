#pragma once
// The command line of every program of the course: one typed option layer on CLI11, the library
// fmbd_cli. fmbd-workbook (frontend/) and fmbd-grade (autograder/driver/) read theirs with parse();
// the tools (tools/), the tutorial problems' programs (problems/program.cpp) and the Catch main of
// every test program (autograder/support/catch_main.cpp, which passes Catch's own options on:
// passes_unknown) make theirs with program() and read it with parse_program() or parse().
//
// A command is a table (Command): its options, each with its kind, the name of its value and one
// line of help, its positional arguments, and the lines that describe it. From the same table
// come the parsing (CLI11 reads the command line) and the usage text, so that the help names
// every option a command takes and nothing else. The front end's registry of commands
// (frontend/commands.cpp) is a list of such tables, each with the function that runs it; the
// driver's is its one table (autograder/driver/options.cpp).
//
// The first problem on a command line ends it with a UsageError (exit status 2 in every program):
//   an unknown option            "handin: unknown option '--x'" (+ the command's unknown_hint)
//   a value missing              "--out needs a file name"  (the option's `needs`)
//   a number that is none        "--timeout needs a number, got 'x'"
//   a flag given a value         "--strict takes no value" (--strict=yes)
//   a positional too many        the command's too_many text, or "unknown option" when the
//                                command takes none
// -h and --help ask for the usage (Parsed::help), unless the command passes unknown options on.
// A value is the next argument whatever it looks like ("--out -h" writes to -h); "--out=FILE"
// works too. After "--" the rest is the command's when it takes it (pass_rest), else "--" is an
// unknown option. Only cli.cpp includes CLI11,
// whose headers take 6 s of CPU to compile: the programs that use this layer compile them once.

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fmbd::cli {

// A wrong command line, or a command that cannot go on here: what() is the message, without the
// program's name (exit status 2).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class Kind {
  flag,        // --strict: present or not
  value,       // --out FILE: one value, the last one given wins
  repeatable,  // --module N, as often as wanted: every value, in order
  number,      // --timeout SEC: one value of digits and dots
};

struct Option {
  std::string name;        // "--out"
  Kind kind = Kind::flag;
  std::string value_name;  // in the usage text: "FILE.zip"
  std::string needs;       // what a missing value is: "a file name" ("--out needs a file name")
  std::string help;        // for tables of options (option_table); "\n" starts a line of its own
};

struct Command {
  std::string name;                  // "hint"; the program's name for a program's own options
  bool is_program = false;           // its messages do not name it again (fmbd-grade, fmbd-workbook)
  std::vector<Option> options;
  std::string positional;            // "TASK", or empty: no positional arguments
  int max_positionals = 0;           // -1: any number
  std::string too_many;              // the message for one positional too many
  std::string unknown_hint;          // after "unknown option '...'", e.g. " (see ./workbook help)";
                                     // "{option}" in it stands for the option refused
  bool pass_rest = false;            // whether "--" ends the options and passes the rest on
  bool stops_at_positional = false;  // the first positional and all after it are `rest`
                                     // (fmbd-workbook: its own options, then COMMAND ARGS...)
  bool passes_unknown = false;       // unknown options and positionals go to `rest`, in order,
                                     // and -h is one of them (the Catch main: Catch's own options)
  std::string synopsis;              // the usage line after the name; empty: made from the table
  std::vector<std::string> help;     // the lines that describe the command
};

// A command line parsed after its Command. The accessors take only the names of the table's
// options (a name it lacks is a std::logic_error: a mistake of the program, not of its user).
class Parsed {
 public:
  bool help = false;               // -h or --help was given (the rest was not checked)
  std::vector<std::string> positionals;
  bool ended = false;              // "--" was given (pass_rest), or a positional (stops_at_positional)
  std::vector<std::string> rest;   // after "--", or from the first positional on
  // Every option and positional in the order given: (option name, value), a positional under
  // the command's `positional`, a flag with "".
  std::vector<std::pair<std::string, std::string>> sequence;

  bool has(const std::string& option) const;
  // The last value of `option`, or `fallback`.
  std::string value(const std::string& option, const std::string& fallback = "") const;
  // Every value of `option`, in order.
  std::vector<std::string> all(const std::string& option) const;
  // The value of a number option, if given.
  std::optional<double> number(const std::string& option) const;

 private:
  friend Parsed parse(const Command& command, const std::vector<std::string>& args);
  std::string command_;          // the command's name and options, for the accessors' checks
  std::vector<Option> options_;
  std::map<std::string, std::vector<std::string>> values_;  // option -> its values ("" for a flag)
  const Option& option(const std::string& name) const;
};

// The arguments after the command's name (or the program's), read by CLI11 after `command`.
// Throws UsageError.
Parsed parse(const Command& command, const std::vector<std::string>& args);

// The usage line of the command: "hint [TASK] [--reset]", made from the table (or `synopsis`).
std::string synopsis(const Command& command);

// The table of a program's own command line (is_program, so its messages do not name it again):
// its name, its options, its positionals (their name and how many at most, -1: any), the usage
// line after its name and the lines after that.
Command program(std::string name, std::vector<Option> options, std::string positional, int max_positionals,
                std::string synopsis, std::vector<std::string> help = {});

// A program's usage: "usage: " + synopsis, then its help lines as they are, each ending in "\n".
std::string program_usage(const Command& command);

// The command line of a program (argv[1] on) read after `command`, the usual way of the course's
// tools: with -h or --help, the usage on standard output and exit status 0; with a UsageError,
// "NAME: MESSAGE" and the usage on standard error and exit status 2. Either way the status is
// returned; nullopt means `parsed` holds the command line and the program goes on.
std::optional<int> parse_program(const Command& command, int argc, const char* const* argv, Parsed& parsed);

// The command's part of a list of commands: "  " + synopsis, then its help lines indented by
// eight spaces, each line ending in "\n".
std::string usage_text(const Command& command);

// The options as a table, by CLI11's formatter: "  --module N" and the option's help in a column
// after it, continued lines under it; "  -h,--help  show this help" last.
std::string option_table(const Command& command);

}  // namespace fmbd::cli
