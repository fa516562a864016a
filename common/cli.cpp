#include "cli.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>
#include <utility>

namespace fmbd::cli {
namespace {

bool is_number(const std::string& text) {
  return !text.empty() && text.find_first_not_of("0123456789.") == std::string::npos;
}

bool starts_with(const std::string& text, const std::string& prefix) { return text.compare(0, prefix.size(), prefix) == 0; }

UsageError unknown_option(const Command& command, const std::string& arg) {
  std::string hint = command.unknown_hint;
  for (std::size_t at = hint.find("{option}"); at != std::string::npos; at = hint.find("{option}", at + arg.size())) {
    hint.replace(at, 8, arg);
  }
  return UsageError((command.is_program ? "" : command.name + ": ") + "unknown option '" + arg + "'" + hint);
}

// CLI11's error for an option whose value is missing names the option first ("--out: 1 required
// FILE missing"): the option of the table it names, or null.
const Option* option_named_by(const Command& command, const std::string& message) {
  for (const Option& option : command.options) {
    if (starts_with(message, option.name + ":")) return &option;
  }
  return nullptr;
}

// The App that reads `command`'s options: each a repeatable CLI11 option of one value (or a flag),
// whose results are then read in the order CLI11 met them.
void add_options(CLI::App& app, const Command& command, std::vector<std::string>& positionals) {
  app.allow_extras();
  if (command.passes_unknown) app.set_help_flag();
  for (const Option& option : command.options) {
    if (option.kind == Kind::flag) {
      app.add_flag(option.name, option.help)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    } else {
      app.add_option(option.name, option.help)
          ->type_name(option.value_name)
          ->expected(1)
          ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    }
  }
  if (command.stops_at_positional) {
    app.prefix_command();
  } else if (!command.positional.empty()) {
    app.add_option(command.positional, positionals);
  }
}

// The values of each option, and the sequence of options and positionals, from CLI11's results.
void collect(const CLI::App& app, const Command& command, Parsed& parsed,
             std::map<std::string, std::vector<std::string>>& values) {
  std::map<const CLI::Option*, std::size_t> taken;
  for (const CLI::Option* option : app.parse_order()) {
    const std::string name = option->get_name();
    const std::size_t index = taken[option]++;
    const auto& results = option->results();
    std::string value = index < results.size() ? results[index] : "";
    if (name == command.positional) {
      parsed.sequence.emplace_back(name, value);
      continue;
    }
    const auto found = std::find_if(command.options.begin(), command.options.end(),
                                    [&name](const Option& o) { return o.name == name; });
    if (found == command.options.end()) continue;  // -h, --help
    if (found->kind == Kind::flag) {  // CLI11 gives "true", or the value of --flag=VALUE
      if (value != "true") throw UsageError(name + " takes no value");
      value.clear();
    }
    if (found->kind != Kind::flag && value.empty()) throw UsageError(name + " needs " + found->needs);
    if (found->kind == Kind::number && !is_number(value)) {
      throw UsageError(name + " needs " + found->needs + ", got '" + value + "'");
    }
    values[name].push_back(value);
    parsed.sequence.emplace_back(name, value);
  }
}

// What CLI11 left over: an unknown option, a positional too many, or (stops_at_positional) the
// command and its arguments.
void check_remaining(const Command& command, std::vector<std::string> remaining, Parsed& parsed) {
  if (command.passes_unknown) {
    parsed.rest = std::move(remaining);
    return;
  }
  if (command.stops_at_positional && !remaining.empty() && !starts_with(remaining.front(), "-")) {
    parsed.ended = true;
    parsed.rest = std::move(remaining);
    return;
  }
  if (!remaining.empty()) throw unknown_option(command, remaining.front());
  const auto max = static_cast<std::size_t>(command.max_positionals);
  if (command.max_positionals >= 0 && parsed.positionals.size() > max) {
    const std::string& extra = parsed.positionals[max];
    if (starts_with(extra, "-")) throw unknown_option(command, extra);
    throw UsageError(command.too_many.empty() ? unknown_option(command, extra).what() : command.too_many);
  }
}

}  // namespace

const Option& Parsed::option(const std::string& name) const {
  for (const Option& option : options_) {
    if (option.name == name) return option;
  }
  throw std::logic_error("the command " + command_ + " has no option " + name);
}

bool Parsed::has(const std::string& option) const {
  this->option(option);
  return values_.count(option) > 0;
}

std::string Parsed::value(const std::string& option, const std::string& fallback) const {
  const std::vector<std::string> values = all(option);
  return values.empty() ? fallback : values.back();
}

std::vector<std::string> Parsed::all(const std::string& option) const {
  this->option(option);
  const auto found = values_.find(option);
  return found == values_.end() ? std::vector<std::string>{} : found->second;
}

std::optional<double> Parsed::number(const std::string& option) const {
  if (this->option(option).kind != Kind::number) throw std::logic_error(option + " is not a number option");
  return has(option) ? std::optional<double>(std::stod(value(option))) : std::nullopt;
}

Parsed parse(const Command& command, const std::vector<std::string>& args) {
  Parsed parsed;
  parsed.command_ = command.name;
  parsed.options_ = command.options;
  std::vector<std::string> own = args;
  if (command.pass_rest) {  // the command's own arguments end at "--"
    const auto end = std::find(own.begin(), own.end(), "--");
    if (end != own.end()) {
      parsed.ended = true;
      parsed.rest.assign(end + 1, own.end());
      own.erase(end, own.end());
    }
  }
  CLI::App app("", command.name);
  add_options(app, command, parsed.positionals);
  std::vector<std::string> reversed(own.rbegin(), own.rend());  // CLI11 takes them last first
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    parsed.help = true;
    try {  // the options before it still count (fmbd-workbook's --source); their errors do not
      collect(app, command, parsed, parsed.values_);
    } catch (const UsageError&) {
    }
    return parsed;
  } catch (const CLI::ParseError& error) {
    const Option* option = option_named_by(command, error.what());
    if (option != nullptr) throw UsageError(option->name + " needs " + option->needs);
    throw UsageError((command.is_program ? "" : command.name + ": ") + error.what());
  }
  collect(app, command, parsed, parsed.values_);
  check_remaining(command, app.remaining(), parsed);
  return parsed;
}

std::string synopsis(const Command& command) {
  if (!command.synopsis.empty()) return command.name + " " + command.synopsis;
  std::string line = command.name;
  if (!command.positional.empty()) line += " [" + command.positional + "]";
  for (const Option& option : command.options) {
    line += " [" + option.name;
    if (option.kind != Kind::flag) line += " " + option.value_name;
    line += option.kind == Kind::repeatable ? "]..." : "]";
  }
  return line;
}

Command program(std::string name, std::vector<Option> options, std::string positional, int max_positionals,
                std::string synopsis, std::vector<std::string> help) {
  Command command;
  command.name = std::move(name);
  command.is_program = true;
  command.options = std::move(options);
  command.positional = std::move(positional);
  command.max_positionals = max_positionals;
  command.synopsis = std::move(synopsis);
  command.help = std::move(help);
  return command;
}

std::string program_usage(const Command& command) {
  std::string text = "usage: " + synopsis(command) + "\n";
  for (const std::string& line : command.help) text += line + "\n";
  return text;
}

std::optional<int> parse_program(const Command& command, int argc, const char* const* argv, Parsed& parsed) {
  try {
    parsed = parse(command, std::vector<std::string>(argv + std::min(argc, 1), argv + argc));
  } catch (const UsageError& error) {
    std::cerr << command.name << ": " << error.what() << "\n" << program_usage(command);
    return 2;
  }
  if (!parsed.help) return std::nullopt;
  std::cout << program_usage(command);
  return 0;
}

std::string usage_text(const Command& command) {
  std::string text = "  " + synopsis(command) + "\n";
  for (const std::string& line : command.help) text += "        " + line + "\n";
  return text;
}

std::string option_table(const Command& command) {
  CLI::App app("", command.name);
  std::vector<std::string> positionals;
  add_options(app, command, positionals);
  app.set_help_flag("-h,--help", "show this help");
  CLI::Formatter formatter;
  formatter.column_width(29);  // where the help of each option starts
  std::string text;
  for (const CLI::Option* option : app.get_options()) {
    if (option->nonpositional() && option != app.get_help_ptr()) text += formatter.make_option(option, false);
  }
  return text + formatter.make_option(app.get_help_ptr(), false);
}

}  // namespace fmbd::cli
