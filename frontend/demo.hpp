#pragma once
// ./workbook demo: the lecture demos of the course manifest, built one at a time in build/student
// and run with the lecturer's parameters.
//
//   demo [NAME] [--out DIR | --csv DIR] [-- DEMO-PARAMETERS...]
//
// With a DISPLAY the demos open gnuplot windows (--csv DIR: the CSV files too, in DIR/NAME); without
// one, or with --out DIR, they write PNG and CSV files to DIR/NAME (default out/demos). After --,
// the parameters of demo NAME; a demo that refuses one exits 2 and so does the command.
//
// A build configured before the demo packages were installed lists no demos: the command
// configures it again once. Still none: exit 1 with the command that installs the packages
// (FMBD_DEMO_PACKAGES, which ./workbook sets), or exit 2 when FMBD_BUILD_DEMOS is OFF. A demo that
// does not build or fails is named at the end (exit 2); the others still run.

#include <string>
#include <vector>

#include "context.hpp"
#include "options.hpp"

namespace fmbd::frontend {

const CommandSpec& demo_command();
int run_demo(const std::vector<std::string>& args, const Context& context);

}  // namespace fmbd::frontend
