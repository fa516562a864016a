#pragma once
// The paths of a tree and of its build folders that the front end reads and writes, each spelled
// here once: the build folder of a preset, its course manifest, its configure log, the logs of a
// grading, the reference's timings of the tree, and the hint levels its student opened.

#include <string>

#include "grading_protocol.hpp"  // kHintsOpenedFile, which the test programs read too

namespace fmbd::frontend {

// The reference's seconds per test (./workbook bench writes it, the grade driver's --timings
// reads it), relative to a tree.
inline constexpr const char* kTimingsFile = "autograder/timings.txt";

// `tree`'s timings file (kTimingsFile).
inline std::string timings_path(const std::string& tree) { return tree + "/" + kTimingsFile; }

// The hint levels opened in `tree` (./workbook hint writes them; grading hands them to the tests).
inline std::string hints_opened_path(const std::string& tree) { return tree + "/" + protocol::kHintsOpenedFile; }

// A build folder and the files in it.
struct BuildLayout {
  std::string dir;  // the build folder

  // build/PRESET, the folder of `cmake --preset PRESET`, relative to its tree (as messages name it).
  static BuildLayout of_preset(const std::string& preset) { return BuildLayout{"build/" + preset}; }
  // tree/build/PRESET.
  static BuildLayout of_preset(const std::string& tree, const std::string& preset) {
    return BuildLayout{tree + "/" + of_preset(preset).dir};
  }

  // The course manifest, which CMake writes at every configure (manifest.hpp).
  std::string course_json() const { return dir + "/course.json"; }
  // What configuring it printed.
  std::string configure_log() const { return dir + "/configure.log"; }
  // The first errors of each graded item that does not compile (errors_file()).
  std::string compile_logs() const { return dir + "/compile"; }
  // Those of the graded item `item_id` ("M01" -> compile/m01.txt, "M01P" -> compile/m01P.txt).
  std::string errors_file(const std::string& item_id) const {
    return compile_logs() + "/m" + item_id.substr(1) + ".txt";
  }
  // The log of a build of `what` ("grade", "fmbd-grade"): WHAT.build.log.
  std::string build_log(const std::string& what) const { return dir + "/" + what + ".build.log"; }
  // The compiler cache of the project's own tests (maintainer.cpp).
  std::string ccache() const { return dir + "/ccache"; }
};

}  // namespace fmbd::frontend
