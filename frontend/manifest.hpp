#pragma once
// The course manifest, <build>/course.json, which CMake writes at every configure
// (cmake/FmbdManifest.cmake): what this build has, for the front end. This is the one description
// of its schema.
//
// Schema 3 (every field required unless it says "or null"; fields this reader does not know are
// ignored; a manifest of another schema is refused with OlderManifest or ManifestError):
//   schema       3
//   source_dir   the folder CMake configured (absolute)
//   build_dir    the build folder (absolute)
//   grade_driver fmbd-grade (absolute), or null where the build has none (BUILD_TESTING=OFF)
//   instructor   (bool) the instructor's copy: it has the reference solutions (solutions/) and
//                the mistake catalogue (autograder/mistakes/), which no release has; the
//                maintainers' commands (test, release, gradescope, bench, studentify) need it
//   release_policy the release policy file, relative to source_dir
//                ("autograder/release_policy.txt"), or null where the copy has none
//   modules      one per module folder of the build, in order:
//                  number (int), id ("M01"), folder ("module01_kinematics"),
//                  exercises (the student's exercise files, relative to source_dir),
//                  hints ("module01_kinematics/hints.md", or null),
//                  student_library, reference_library (the stage's libraries, absolute; the
//                  reference's null without one)
//   graded       one per graded program (fmbd_add_graded_item()):
//                  id ("M01", "M01P"), kind ("catch", "problems": a name for people, which no
//                  code tests), module (int), program (absolute), target ("m01_student"),
//                  reference_program, reference_target (a trusted build that lists the tests, or
//                  null: none), vet_target ("m01_vet", or null: no source check), vet_report (the
//                  file it writes, absolute: what it refused; null with vet_target null),
//                and its capabilities, which decide what the front end and the driver do with it:
//                  inputs             the student's files it grades besides the code, relative to
//                                     source_dir (["module01_kinematics/answers.txt"]; [] for
//                                     none): handed in, taken from a submission, handed to the
//                                     program under FMBD_ANSWERS_ROOT (the environment of the
//                                     programs' protocol, autograder/driver/grade.cpp); in one's
//                                     own tree an item none of whose inputs exists yet is not
//                                     started, so not built or graded
//                  needs_identity     (bool) it grades with the numbers of the student's name,
//                                     which the grader trusts (FMBD_STUDENT: --student, the
//                                     submission's folder, Gradescope's metadata, the remembered
//                                     name); with inputs, ./workbook problems prints its problems
//                  links_student_code (bool) its program is built from the student's exercise
//                                     files: their build failing fails it
//                  classroom          (bool) a step of the GitHub Classroom workflow
//                  without_reference  what it checks where reference_program is null: "all"
//                                     (every test, listed by the student's build) or "format"
//                                     (only the format of its inputs; the values need the
//                                     reference, so the instructor's grader grades them)
//   demos        {name, target, program} per lecture demo
//   benchmarks   {name, target, program} per benchmark program
// graded, demos and benchmarks are empty where the build has none.
//
// Schema 2 (before): no instructor, release_policy or vet_report; the front end decided the first
// from the folders, and kept the paths of the other two itself.
// Schema 1 (before that): inputs belonged to the modules, items had no capabilities, and the fields
// given, solutions, tasks, has_reference (modules), points and tags (items) were written but
// never read.

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
  std::optional<std::string> hints;
  std::string student_library;                   // the stage's library (absolute)
  std::optional<std::string> reference_library;  // nullopt: no reference variant
};

// What a graded item checks where its reference is absent (without_reference).
enum class WithoutReference { all, format };

struct GradedItem {
  std::string id;    // "M01"
  std::string kind;  // for people: no code tests it
  int module = 0;
  std::string program;
  std::string target;
  std::optional<std::string> reference_program;
  std::optional<std::string> reference_target;
  std::optional<std::string> vet_target;  // nullopt: no source check
  std::optional<std::string> vet_report;  // its report (absolute); with vet_target
  // Its capabilities (the schema above says what each one does).
  std::vector<std::string> inputs;
  bool needs_identity = false;
  bool links_student_code = false;
  bool classroom = false;
  WithoutReference without_reference = WithoutReference::all;

  // Whether ./workbook problems serves it: it grades inputs with the numbers of the student's
  // name, and its program prints them (--print, --worked, --template: docs/instructors.md, "Adding a kind").
  bool has_personal_problems() const { return needs_identity && !inputs.empty(); }
};

// Whether `item` has the yes-or-no capability named as the manifest names its field:
// "links_student_code", "needs_identity", "classroom", or "inputs" (it has some). Nothing for
// another name (kCapabilityNames lists these).
std::optional<bool> has_capability(const GradedItem& item, std::string_view name);
constexpr const char* kCapabilityNames = "inputs, needs_identity, links_student_code, classroom";

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
  bool instructor = false;   // the instructor's copy
  std::optional<std::string> release_policy;  // relative to source_dir; nullopt: none
  std::vector<Module> modules;
  std::vector<GradedItem> graded;
  std::vector<Demo> demos;
  std::vector<Benchmark> benchmarks;

  // The module numbered `number`, or nullptr.
  const Module* module(int number) const;
};

// A manifest that cannot be read: what() is "FILE: where: what", where is a JSON position
// ("line 3, column 7") or a field ("modules[2].exercises[0]").
class ManifestError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A manifest of an older schema than this reader's, written by a build configured before the tree
// changed: configuring the build again writes the current one.
class OlderManifest : public ManifestError {
 public:
  OlderManifest(const std::string& what, int schema) : ManifestError(what), schema_(schema) {}
  int schema() const { return schema_; }

 private:
  int schema_;
};

constexpr int kManifestSchema = 3;

// The manifest in `text`; `origin` names it in errors (its file). Throws ManifestError, and
// OlderManifest for a manifest of an older schema.
Manifest parse_manifest(std::string_view text, const std::string& origin);

// The manifest in the file `path`. Throws as parse_manifest, and ManifestError when the file
// cannot be read.
Manifest read_manifest(const std::string& path);

}  // namespace fmbd::frontend
