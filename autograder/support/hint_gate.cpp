// The hint gate (hint_gate.hpp).
#include "hint_gate.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "grading_protocol.hpp"  // common/: the hints.opened file and its reader, inline

#ifndef FMBD_SOURCE_TREE
#define FMBD_SOURCE_TREE ""  // no tree: no levels unless FMBD_HINTS_OPENED names a file
#endif

namespace fmbd::testing {

namespace {

std::string& task_storage() {
  static std::string task;
  return task;
}

// The text of the hints.opened file in force, read once: "" when there is none.
const std::string& opened_text() {
  static const std::string text = [] {
    const char* named = std::getenv(protocol::kHintsOpenedVariable);
    const std::string tree = FMBD_SOURCE_TREE;
    const std::string path = named != nullptr ? named : tree.empty() ? "" : tree + "/" + protocol::kHintsOpenedFile;
    if (path.empty()) return std::string();
    std::ifstream in(path, std::ios::binary);
    std::ostringstream content;
    content << in.rdbuf();
    return content.str();
  }();
  return text;
}

// The digits after `letter` in the first tag "[<letter>digits]" of `tags`, or "".
std::string tag_digits(std::string_view tags, char letter) {
  for (std::size_t at = tags.find(std::string("[") + letter); at != std::string_view::npos;
       at = tags.find(std::string("[") + letter, at + 1)) {
    const std::size_t close = tags.find(']', at);
    if (close == std::string_view::npos || close == at + 2) continue;
    const std::string_view digits = tags.substr(at + 2, close - at - 2);
    if (digits.find_first_not_of("0123456789") == std::string_view::npos) return std::string(digits);
  }
  return "";
}

}  // namespace

std::string task_of_tags(std::string_view tags) {
  const std::string module = tag_digits(tags, 'M'), task = tag_digits(tags, 'T');
  return module.empty() || task.empty() ? "" : "M" + module + "T" + task;
}

void set_running_task(std::string task) { task_storage() = std::move(task); }

const std::string& running_task() { return task_storage(); }

int running_hint_level() {
  if (running_task().empty()) return 0;
  return protocol::opened_hint_level(opened_text(), running_task());
}

std::string with_formula(std::string_view words, std::string_view formula) {
  std::string out(words);
  if (formula.empty()) return out;
  if (running_hint_level() >= protocol::kFormulaHintLevel) return out + "; the formula: " + std::string(formula);
  const std::string task = running_task().empty() ? "TASK" : running_task();
  return out + " (more: ./workbook hint " + task + ")";
}

}  // namespace fmbd::testing
