#pragma once
// The course manifest, <build>/course.json, which CMake writes at every configure
// (cmake/FmbdManifest.cmake): what this build has, for the front end.
//
// Schema 1 (every field required unless it says "or null"):
//   schema       1
//   source_dir   the folder CMake configured (absolute)
//   build_dir    the build folder (absolute)
//   grade_driver fmbd-grade (absolute), or null where the build has none (BUILD_TESTING=OFF)
//   modules      one per module folder of the build, in order:
//                  number (int), id ("M01"), folder ("module01_kinematics"),
//                  exercises, given, solutions (paths relative to source_dir; solutions: those
//                  this copy has, "solutions/module01_kinematics/planar.cpp"),
//                  tasks (["M01T1", ...]: the TASK markers of the solutions, or the TODO markers
//                  of the exercise files where the copy has no solutions; in order, each once),
//                  hints ("module01_kinematics/hints.md", or null), has_reference (bool),
//                  student_library, reference_library (the stage's libraries, absolute; the
//                  reference's null without one)
//   graded       one per graded program:
//                  id ("M01"), kind ("catch": a Catch program speaking the grade driver's
//                  list/token protocol), module (int), program (absolute), target ("m01_student"),
//                  reference_program, reference_target (or null: no reference), vet_target
//                  ("m01_vet", or null: nothing of the student's compiled in), points ("listed": the program lists its tests and their points),
//                  tags (["code"])
//   demos        {name, target, program} per lecture demo
//   benchmarks   {name, target, program} per benchmark program
// graded, demos and benchmarks are empty where the build has none. Fields this reader does not
// know are ignored.

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace fmbd::frontend {

struct Module {
  int number = 0;
  std::string id;      // "M01"
  std::string folder;  // "module01_kinematics"
  std::vector<std::string> exercises;
  std::vector<std::string> inputs;  // the student's other files: the answers of the problems
  std::vector<std::string> given;
  std::vector<std::string> solutions;
  std::vector<std::string> tasks;
  std::optional<std::string> hints;
  bool has_reference = false;
  std::string student_library;                   // the stage's library (absolute)
  std::optional<std::string> reference_library;  // nullopt: no reference variant
};

struct GradedItem {
  std::string id;  // "M01"
  std::string kind;
  int module = 0;
  std::string program;
  std::string target;
  std::optional<std::string> reference_program;
  std::optional<std::string> reference_target;
  std::optional<std::string> vet_target;  // nullopt: nothing of the student's is compiled in
  std::string points;
  std::vector<std::string> tags;
};

// A lecture demo or a benchmark program.
struct Program {
  std::string name;
  std::string target;
  std::string program;
};
using Demo = Program;
using Benchmark = Program;

struct Manifest {
  int schema = 0;
  std::string source_dir;
  std::string build_dir;
  std::string grade_driver;  // fmbd-grade (absolute); empty where the build has none
  std::vector<Module> modules;
  std::vector<GradedItem> graded;
  std::vector<Demo> demos;
  std::vector<Benchmark> benchmarks;

  // The module numbered `number`, or nullptr.
  const Module* module(int number) const;
};

// A manifest that cannot be read: what() is "FILE: where: what", where is a JSON position
// ("line 3, column 7") or a field ("modules[2].tasks[0]").
class ManifestError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

constexpr int kManifestSchema = 1;

// The manifest in `text`; `origin` names it in errors (its file). Throws ManifestError.
Manifest parse_manifest(std::string_view text, const std::string& origin);

// The manifest in the file `path`. Throws ManifestError (also when the file cannot be read).
Manifest read_manifest(const std::string& path);

}  // namespace fmbd::frontend
