#include "options.hpp"

#include <ostream>

#include "text.hpp"

namespace fmbd::frontend {

void check_visibility(const std::string& value) {
  if (!grade::is_visibility(value)) {
    throw UsageError("--hidden-visibility: one of hidden, after_due_date, after_published, visible; not '" + value + "'");
  }
}

bool print_usage_if_asked(const ParsedOptions& parsed, const CommandSpec& spec, std::ostream& out) {
  if (!parsed.help) return false;
  out << "usage: ./workbook COMMAND [OPTIONS]\n\n" << usage_text(spec) << "  (./workbook help: every command)\n";
  return true;
}

}  // namespace fmbd::frontend
