#pragma once
// Building with CMake and Ninja for the front end: configuring a preset once, a build that
// reports its progress as it goes, the first compiler errors of a failed build, and the warnings
// of the exercise files.
//
// Progress comes from the build's own outputs and status, never from the names of its object
// files: a line for each watched output (a module's library or test program, from the course
// manifest) when the build writes it anew, and Ninja's count of steps, in the status format the
// front end sets (NINJA_STATUS="[%f/%t] "). Which exercise files were compiled comes from
// compile_commands.json (each source's object) and the objects' times.

#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

namespace fmbd::frontend {

// A configure or build step that failed for a reason the user must see: what() is the message
// for "workbook: " (exit status 3, exit_status.hpp).
class BuildError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The CMake of this build (it configured the front end), or "cmake" on PATH where it has moved.
std::string cmake_program();

// The CTest beside that CMake, or "ctest" on PATH.
std::string ctest_program();

// The build folder of the preset `preset` in `tree`: TREE/build/PRESET, the binaryDir of every
// preset of CMakePresets.json. The course manifest of a configured build says it too (build_dir).
std::string preset_build_dir(const std::string& tree, const std::string& preset);

// Configures build/PRESET of `tree` with `cmake --preset PRESET`, the first time only (later
// builds re-run CMake when needed). A build folder configured for another folder (a moved or
// copied workbook) starts afresh. Throws BuildError when configuring fails (the log printed).
void configure(const std::string& tree, const std::string& preset, std::ostream& out);

// An output the build may write, and the line that says so ("module 1: your code compiled").
struct Watched {
  std::string path;
  std::string message;
};

// Builds `targets` in `build`, past errors (-k 0), into `log`: a line per watched output written,
// Ninja's count of steps every 10 s, and where the log is once the build takes 5 s (at once for a
// first build). Then records the warnings of the exercise files compiled (`exercises`: their
// absolute paths, each shown as its path relative to `tree`). The build's own failure is not an
// error here: each target is built again alone to find what failed.
void build_with_progress(const std::string& build, const std::string& log, const std::vector<std::string>& targets,
                         const std::vector<Watched>& watched, const std::string& tree,
                         const std::vector<std::string>& exercises, std::ostream& out);

// Builds one target quietly into `log`; whether it built.
bool build_target(const std::string& build, const std::string& target, const std::string& log);

// The recorded warnings of the exercise files (build/warnings/), under a line that says what they
// are, or nothing when there are none.
void show_warnings(const std::string& build, std::ostream& out);

// The first compiler errors of `log` (at most 40 lines), with the paths relative to the tree
// (every prefix in `roots` removed), and a first line that names the module to fix when the
// first error is in another module's file than `folder`'s. Without an error line: the log's last
// 20 lines.
std::string first_errors(const std::string& log, const std::string& folder, const std::vector<std::string>& roots);

}  // namespace fmbd::frontend
