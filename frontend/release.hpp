#pragma once
// ./workbook release and ./workbook gradescope: copies of this tree for students and for
// Gradescope, after the release policy (autograder/release_policy.txt, its header says what each
// rule does).
//
// A release: modules 1..N (--through) as the instructor's copy has them (skeletons and visible
// tests), the solutions of modules 1..M (--solutions-through), the hint ladders up to their
// ceiling (--hint-ceiling; by default level 2 for the modules whose solutions it keeps back), the
// timings of the visible tests only, and READMEs and guides (docs/) that are true of it
// (markdown.hpp). The Gradescope zip: the tree with its hidden tests and solutions, the Gradescope
// scripts at its top and their settings (gradescope.conf).

#include <iosfwd>
#include <string>
#include <vector>

#include "context.hpp"
#include "manifest.hpp"
#include "options.hpp"

namespace fmbd::frontend {

// The rules of the release policy file, each rule's arguments in file order.
struct ReleasePolicy {
  std::vector<std::string> omit;             // paths (a * matches within one name)
  std::vector<std::string> omit_engine;      // omitted unless the release carries every solution
  std::vector<std::string> strip;            // README and docs/*.md marks
  std::vector<std::string> strip_engine;     // the same, where the release has no engine
  std::vector<std::string> gradescope_omit;  // paths the Gradescope zip leaves out
};

// The policy in `text` (`origin` names it in errors). Throws UsageError for an unknown rule or a
// rule without its argument, with the line's number.
ReleasePolicy parse_policy(const std::string& text, const std::string& origin);

// The arguments of the rule named `rule` ("omit", "gradescope-omit", ...) in `policy`, in file
// order. Throws UsageError for a name that is no rule, listing the rules.
const std::vector<std::string>& policy_rule(const ReleasePolicy& policy, const std::string& rule);

// Whether the relative path `path` ("autograder/module01_kinematics/hidden/x.cpp") lies in or
// under one of `patterns` ("autograder/module*/hidden"): each pattern's names matched against
// the path's first names, '*' within one name.
bool excluded(const std::string& path, const std::vector<std::string>& patterns);

const CommandSpec& release_command();
const CommandSpec& gradescope_command();

// Both need the instructor's copy, and follow the course manifest of its build: its modules (a
// release copies those up to --through and the solutions of those up to --solutions-through) and
// its release policy.
int run_release(const std::vector<std::string>& args, const Context& context);
int run_gradescope(const std::vector<std::string>& args, const Context& context);

}  // namespace fmbd::frontend
