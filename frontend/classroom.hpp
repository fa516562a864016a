#pragma once
// ./workbook classroom: the GitHub Classroom workflow of a student copy, one command-grader step
// per task of the course manifest's graded items, worth the points of its visible tests (the
// grade driver's --list-tasks). It refuses the instructor's copy: the steps grade with the
// visible tests only, so the copy must hold no hidden ones.

#include <iosfwd>
#include <string>
#include <vector>

#include "context.hpp"
#include "manifest.hpp"
#include "options.hpp"

namespace fmbd::frontend {

const CommandSpec& classroom_command();

// Runs ./workbook classroom in the tree context.source_dir, whose build context.manifest describes
// (the items with the capability classroom are the workflow's). The workflow installs the Debian
// packages ./workbook installs (FMBD_BUILD_PACKAGES, which ./workbook sets) before it builds.
int run_classroom(const std::vector<std::string>& args, const Context& context);

// A command-grader step of a workflow that run_classroom wrote: its id ("m01-t1"), its command
// and its points.
struct ClassroomStep {
  std::string id;
  std::string command;
  double max_score = 0;
};

// The command-grader steps of the workflow `text`, in order (the reader beside run_classroom's
// writer; `origin` names the file in errors). Throws StepFailed for a step without its id,
// command or a max-score that is a number.
std::vector<ClassroomStep> parse_classroom_steps(const std::string& text, const std::string& origin);

}  // namespace fmbd::frontend
