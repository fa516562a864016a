#pragma once
// The options of the front end's commands: each command is a table (cli::Command, in
// common/cli.hpp, the option layer on CLI11 that fmbd-grade shares), from which come
// both the parsing and the command's part of the usage text. This header gives the layer the front
// end's names and adds what only the front end needs.
//
// A command line is parsed by cli::parse; the first problem ends it with a UsageError whose
// message main() prints after "workbook: " (exit status 2):
//   an unknown option            "handin: unknown option '--x'" (+ the command's unknown_hint)
//   a value missing              "--out needs a file name"  (the option's `needs`)
//   a number that is none        "--timeout needs a number, got 'x'"
//   a positional too many        the command's too_many text, or "unknown option" when the
//                                command takes none
// -h and --help ask for the usage (ParsedOptions::help); after "--" the rest is the command's
// when it takes it (pass_rest), else "--" is an unknown option.

#include <iosfwd>
#include <string>
#include <vector>

#include "cli.hpp"

namespace fmbd::frontend {

// A wrong command line, or a command that cannot go on here: what() is the message, without
// "workbook: " (exit status 2, exit_status.hpp).
using UsageError = cli::UsageError;
using OptionKind = cli::Kind;
using OptionSpec = cli::Option;
using CommandSpec = cli::Command;
using ParsedOptions = cli::Parsed;
using cli::synopsis;
using cli::usage_text;

// The arguments after the command's name, parsed after `spec`. Throws UsageError. With -h or
// --help, the rest is not checked.
inline ParsedOptions parse_options(const CommandSpec& spec, const std::vector<std::string>& args) {
  return cli::parse(spec, args);
}

// With -h or --help (parsed.help): the command's usage (usage_text, under the workbook's usage
// line, and where the whole text is) on `out`, and true; else false.
bool print_usage_if_asked(const ParsedOptions& parsed, const CommandSpec& spec, std::ostream& out);

// The value of --hidden-visibility (grade, gradescope): one of Gradescope's visibilities, or a
// UsageError that lists them.
void check_visibility(const std::string& value);

}  // namespace fmbd::frontend
