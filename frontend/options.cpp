#include "options.hpp"

#include <ostream>

#include "text.hpp"

namespace fmbd::frontend {
namespace {

const OptionSpec* find_option(const CommandSpec& spec, std::string_view name) {
  for (const OptionSpec& option : spec.options) {
    if (option.name == name) return &option;
  }
  return nullptr;
}

bool is_number(std::string_view text) {
  return !text.empty() && text.find_first_not_of("0123456789.") == std::string_view::npos;
}

}  // namespace

std::string ParsedOptions::value(const std::string& option, const std::string& fallback) const {
  const auto found = values.find(option);
  return found == values.end() || found->second.empty() ? fallback : found->second.back();
}

std::vector<std::string> ParsedOptions::all(const std::string& option) const {
  const auto found = values.find(option);
  return found == values.end() ? std::vector<std::string>{} : found->second;
}

ParsedOptions parse_options(const CommandSpec& spec, const std::vector<std::string>& args) {
  ParsedOptions parsed;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "-h" || arg == "--help") {
      parsed.help = true;
      return parsed;
    }
    if (arg == "--" && spec.pass_rest) {
      parsed.ended = true;
      parsed.rest.assign(args.begin() + static_cast<std::ptrdiff_t>(i) + 1, args.end());
      return parsed;
    }
    const OptionSpec* option = find_option(spec, arg);
    if (option == nullptr) {
      const bool looks_like_option = !arg.empty() && arg[0] == '-';
      if (looks_like_option || spec.positional.empty()) {
        std::string hint = spec.unknown_hint;
        for (std::size_t at = hint.find("{option}"); at != std::string::npos; at = hint.find("{option}", at + arg.size())) {
          hint.replace(at, 8, arg);
        }
        throw UsageError(spec.name + ": unknown option '" + arg + "'" + hint);
      }
      if (static_cast<int>(parsed.positionals.size()) >= spec.max_positionals) throw UsageError(spec.too_many);
      parsed.positionals.push_back(arg);
      continue;
    }
    if (option->kind == OptionKind::flag) {
      parsed.values[option->name].emplace_back();
      continue;
    }
    if (i + 1 >= args.size()) throw UsageError(option->name + " needs " + option->needs);
    const std::string& value = args[++i];
    if (option->kind == OptionKind::number && !is_number(value)) {
      throw UsageError(option->name + " needs " + option->needs + ", got '" + value + "'");
    }
    parsed.values[option->name].push_back(value);
  }
  return parsed;
}

void check_visibility(const std::string& value) {
  if (!grade::is_visibility(value)) {
    throw UsageError("--hidden-visibility: one of hidden, after_due_date, after_published, visible; not '" + value + "'");
  }
}

std::string synopsis(const CommandSpec& spec) {
  if (!spec.synopsis.empty()) return spec.name + " " + spec.synopsis;
  std::string line = spec.name;
  if (!spec.positional.empty()) line += " [" + spec.positional + "]";
  for (const OptionSpec& option : spec.options) {
    line += " [" + option.name;
    if (option.kind != OptionKind::flag) line += " " + option.value_name;
    line += option.kind == OptionKind::repeatable ? "]..." : "]";
  }
  return line;
}

bool print_usage_if_asked(const ParsedOptions& parsed, const CommandSpec& spec, std::ostream& out) {
  if (!parsed.help) return false;
  out << "usage: ./workbook COMMAND [OPTIONS]\n\n" << usage_text(spec) << "  (./workbook help: every command)\n";
  return true;
}

std::string usage_text(const CommandSpec& spec) {
  std::string text = "  " + synopsis(spec) + "\n";
  for (const std::string& line : spec.help) text += "        " + line + "\n";
  return text;
}

}  // namespace fmbd::frontend
