#pragma once
// ./workbook classroom: the GitHub Classroom workflow of a student copy, one command-grader step
// per task of the course manifest's graded items, worth the points of its visible tests (the
// grade driver's --list-tasks). It refuses the instructor's copy: the steps grade with the
// visible tests only, so the copy must hold no hidden ones.

#include <iosfwd>
#include <string>
#include <vector>

#include "manifest.hpp"
#include "options.hpp"

namespace fmbd::frontend {

const CommandSpec& classroom_command();

// Runs ./workbook classroom in the tree `root`, whose build `manifest` describes (the items with
// the capability classroom are the workflow's); `packages` are the Debian packages the workflow
// installs before it builds.
int run_classroom(const std::string& root, const Manifest& manifest, const std::vector<std::string>& args,
                  const std::string& packages, std::ostream& out);

}  // namespace fmbd::frontend
