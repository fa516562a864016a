// The front end's library, continued from frontend.test.cpp: the job count, hint ladders, the
// course manifest (also as this build wrote it, checked against the tree), releases and the
// inspection of the tree.

#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "commands.hpp"
#include "csv.hpp"
#include "demo.hpp"
#include "exit_status.hpp"
#include "build.hpp"
#include "grade.hpp"
#include "grade_plan.hpp"
#include "grading.hpp"
#include "grading_protocol.hpp"
#include "hints.hpp"
#include "ids.hpp"
#include "inspect.hpp"
#include "jobs.hpp"
#include "layout.hpp"
#include "json.hpp"
#include "manifest.hpp"
#include "maintainer.hpp"
#include "markdown.hpp"
#include "classroom.hpp"
#include "release.hpp"
#include "options.hpp"
#include "tables.hpp"
#include "task_id.hpp"
#include "frontend_support.hpp"

namespace fs = std::filesystem;
using namespace fmbd::frontend;
namespace json = fmbd::json;
namespace csv = fmbd::csv;

using namespace fmbd::frontend_testing;

TEST_CASE("Jobs: cores, CPU quota and memory limit, with the reason", "[frontend][jobs]") {
  Scratch scratch("jobs");
  const fs::path root = scratch.path / "cgroup";
  const std::string meminfo = (scratch.path / "meminfo").string();
  write_file(meminfo, "MemTotal:       16000000 kB\nMemFree: 1 kB\n");

  fs::create_directories(root);
  Jobs jobs = available_jobs(4, root.string(), meminfo);  // no cgroup files
  CHECK(jobs.count == 4);
  CHECK(jobs.reason == "4 cores");

  write_file(root / "cpu.max", "150000 100000\n");
  jobs = available_jobs(4, root.string(), meminfo);
  CHECK(jobs.count == 1);
  CHECK(jobs.reason == "4 cores, a CPU quota of 1");

  write_file(root / "cpu.max", "max 100000\n");
  CHECK(available_jobs(4, root.string(), meminfo).reason == "4 cores");

  write_file(root / "cpu.max", "800000 100000\n");  // a quota above the cores keeps the cores
  jobs = available_jobs(4, root.string(), meminfo);
  CHECK(jobs.count == 4);
  CHECK(jobs.reason == "4 cores, a CPU quota of 8");

  fs::remove(root / "cpu.max");  // cgroup v1
  write_file(root / "cpu/cpu.cfs_quota_us", "200000\n");
  write_file(root / "cpu/cpu.cfs_period_us", "100000\n");
  jobs = available_jobs(4, root.string(), meminfo);
  CHECK(jobs.count == 2);
  CHECK(jobs.reason == "4 cores, a CPU quota of 2");
  write_file(root / "cpu/cpu.cfs_quota_us", "-1\n");
  CHECK(available_jobs(4, root.string(), meminfo).count == 4);

  write_file(root / "memory.max", "2147483648\n");  // 2 GiB: two jobs of 700 MB
  jobs = available_jobs(4, root.string(), meminfo);
  CHECK(jobs.count == 2);
  CHECK(jobs.reason == "4 cores, 2048 MB of memory");
  write_file(root / "memory.max", "max\n");
  CHECK(available_jobs(4, root.string(), meminfo).count == 4);
  write_file(root / "memory.max", "100000000\n");  // below 700 MB: still one job
  CHECK(available_jobs(4, root.string(), meminfo).count == 1);

  fs::remove(root / "memory.max");  // cgroup v1: its "no limit" is a number above the machine's memory
  write_file(root / "memory/memory.limit_in_bytes", "9223372036854771712\n");
  CHECK(available_jobs(4, root.string(), meminfo).reason == "4 cores");
  write_file(root / "memory/memory.limit_in_bytes", "1073741824\n");
  CHECK(available_jobs(4, root.string(), meminfo).reason == "4 cores, 1024 MB of memory");
}

namespace {

constexpr const char* kLadders = R"(# Module 1 hints

Open them one level at a time.

## M01T1

### Level 1
Where the theory is.


Second paragraph.

### Level 2
The shape.

### Level 3
The formula `x = y`.

## M01T2

### Level 1
Only one level here.
)";

}  // namespace

TEST_CASE("Hints: ladders are listed, rendered and trimmed as the workbook does", "[frontend][hints]") {
  const auto ladders = hints::list_ladders({kLadders, "## M02T1\n### Level 1\n### Level 2\n"});
  REQUIRE(ladders.size() == 3);
  CHECK(ladders[0].task == "M01T1");
  CHECK(ladders[0].levels == 3);
  CHECK(ladders[1].levels == 1);
  CHECK(ladders[2].task == "M02T1");
  CHECK(ladders[2].levels == 2);
  CHECK(hints::levels_of(kLadders, "M01T1") == 3);
  CHECK(hints::levels_of(kLadders, "M01T9") == 0);
  CHECK(hints::task_headings(kLadders) == std::vector<std::string>{"M01T1", "M01T2"});

  CHECK(hints::render(kLadders, "M01T1", 1) == "-- M01T1, level 1 --\nWhere the theory is.\n\nSecond paragraph.\n");
  CHECK(hints::render(kLadders, "M01T1", 2) ==
        "-- M01T1, level 1 --\nWhere the theory is.\n\nSecond paragraph.\n\n-- M01T1, level 2 --\nThe shape.\n");
  CHECK(hints::render(kLadders, "M01T2", 1) == "-- M01T2, level 1 --\nOnly one level here.\n");

  CHECK_FALSE(hints::ceiling(kLadders));
  const std::string trimmed = hints::apply_ceiling(kLadders, 1);
  CHECK(trimmed.find("### Level 2") == std::string::npos);
  CHECK(trimmed.find("The formula") == std::string::npos);
  CHECK(trimmed.find("Only one level here.") != std::string::npos);
  CHECK(trimmed.rfind("# Module 1 hints\n\n<!-- hint-ceiling: 1 -->\n\nOpen them", 0) == 0);
  CHECK(trimmed.find("\n\n\n") == std::string::npos);  // empty lines squeezed
  CHECK(hints::ceiling(trimmed) == 1);
  CHECK(hints::levels_of(trimmed, "M01T1") == 1);

  const std::string opened = hints::with_opened("M01T2 1\nM01T1 1\n", "M01T1", 2);
  CHECK(opened == "M01T2 1\nM01T1 2\n");
  CHECK(hints::opened_level(opened, "M01T1") == 2);
  CHECK(hints::opened_level(opened, "M01T3") == 0);
  CHECK(hints::with_opened(opened, "M01T1", 0) == "M01T2 1\n");
}

namespace {

constexpr const char* kManifest = R"({
  "schema": 3, "source_dir": "/src", "build_dir": "/src/build/student", "grade_driver": "/b/fmbd-grade",
  "instructor": true, "release_policy": "autograder/release_policy.txt",
  "modules": [
    {"number": 1, "id": "M01", "folder": "module01_kinematics",
     "exercises": ["module01_kinematics/src/planar.cpp"], "hints": null,
     "student_library": "/b/libstage01_student.a", "reference_library": null}
  ],
  "graded": [
    {"id": "M01", "kind": "catch", "module": 1, "program": "/b/m01_student", "target": "m01_student",
     "reference_program": null, "reference_target": null, "vet_target": "m01_vet",
     "vet_report": "/b/vet/m01.txt",
     "inputs": [], "needs_identity": false, "links_student_code": true, "classroom": true, "without_reference": "all"},
    {"id": "M01P", "kind": "problems", "module": 1, "program": "/b/m01_problems", "target": "m01_problems",
     "reference_program": null, "reference_target": null, "vet_target": null, "vet_report": null,
     "inputs": ["module01_kinematics/answers.txt"], "needs_identity": true, "links_student_code": true,
     "classroom": false, "without_reference": "format"}
  ],
  "demos": [], "benchmarks": [{"name": "simulate", "target": "fmbd-bench-simulate", "program": "/b/s"}]
})";

std::string manifest_error(const std::string& text) {
  try {
    parse_manifest(text, "course.json");
  } catch (const ManifestError& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST_CASE("Manifest: a small course.json is read into its structs", "[frontend][manifest]") {
  const Manifest manifest = parse_manifest(kManifest, "course.json");
  CHECK(manifest.schema == 3);
  CHECK(manifest.source_dir == "/src");
  CHECK(manifest.instructor);
  CHECK(manifest.release_policy == std::optional<std::string>("autograder/release_policy.txt"));
  REQUIRE(manifest.modules.size() == 1);
  CHECK(manifest.module(1)->folder == "module01_kinematics");
  CHECK(manifest.module(2) == nullptr);
  CHECK(manifest.modules[0].exercises == std::vector<std::string>{"module01_kinematics/src/planar.cpp"});
  CHECK_FALSE(manifest.modules[0].hints);
  REQUIRE(manifest.graded.size() == 2);
  CHECK(manifest.graded[0].vet_target == std::optional<std::string>("m01_vet"));
  CHECK(manifest.graded[0].vet_report == std::optional<std::string>("/b/vet/m01.txt"));
  CHECK_FALSE(manifest.graded[0].reference_program);
  // The capabilities, as data.
  const GradedItem& code = manifest.graded[0];
  const GradedItem& problems = manifest.graded[1];
  CHECK(code.inputs.empty());
  CHECK((code.links_student_code && code.classroom && !code.needs_identity && !code.has_personal_problems()));
  CHECK(code.without_reference == WithoutReference::all);
  CHECK(problems.inputs == std::vector<std::string>{"module01_kinematics/answers.txt"});
  CHECK((problems.needs_identity && !problems.classroom && problems.has_personal_problems()));
  CHECK(problems.without_reference == WithoutReference::format);
  // ... and by the names of their fields (./workbook inspect tasks --of).
  CHECK(has_capability(code, "links_student_code") == std::optional<bool>(true));
  CHECK(has_capability(code, "inputs") == std::optional<bool>(false));
  CHECK(has_capability(problems, "inputs") == std::optional<bool>(true));
  CHECK(has_capability(problems, "classroom") == std::optional<bool>(false));
  CHECK_FALSE(has_capability(problems, "problems"));  // a kind, not a capability
  CHECK(manifest.demos.empty());
  CHECK(manifest.benchmarks.at(0).target == "fmbd-bench-simulate");

  // Each entry: a piece of the manifest, what replaces it, and the error that names the culprit.
  const struct {
    const char *piece, *replacement, *error;
  } broken[] = {
      {"\"module01_kinematics/answers.txt\"", "2", "course.json: graded[1].inputs[0]: a string is expected, not a number"},
      {"\"format\"", "\"some\"", "course.json: graded[1].without_reference: \"all\" or \"format\" is expected, not \"some\""},
      {"\"needs_identity\": true", "\"needs_identity\": 1",
       "course.json: graded[1].needs_identity: a boolean is expected, not a number"},
      {"\"vet_target\"", "\"vet\"", "course.json: graded[0].vet_target: missing"},
      {"\"vet_report\": \"/b/vet/m01.txt\"", "\"vet_report\": null",
       "course.json: graded[0].vet_report: vet_target and vet_report are both null or both given"},
      {"\"instructor\": true", "\"instructor\": 1", "course.json: instructor: a boolean is expected, not a number"},
  };
  std::string text;
  for (const auto& b : broken) {
    CAPTURE(b.piece);
    text = kManifest;
    const std::size_t at = text.find(b.piece);
    REQUIRE(at != std::string::npos);
    CHECK(manifest_error(text.replace(at, std::strlen(b.piece), b.replacement)) == b.error);
  }
  text = kManifest;
  CHECK(manifest_error(text.replace(text.find("\"schema\": 3"), 11, "\"schema\": 4")).find("course.json: schema: schema 4 is newer") == 0);
  // A manifest of an older schema says so, with its schema, for the one re-configure.
  int older = 0;
  try {
    parse_manifest(R"({"schema": 1, "modules": [{"inputs": []}]})", "course.json");
  } catch (const OlderManifest& error) {
    older = error.schema();
    CHECK(std::string(error.what()).find("course.json: schema: schema 1 is older than the one this front end reads (3)") == 0);
  }
  CHECK(older == 1);
  CHECK(manifest_error("{\n\"schema\": 1,,}").find("course.json: line 2, column 13: ") == 0);
  CHECK(manifest_error("{\"schema\": 1, \"schema\": 1}") == "course.json: duplicate key \"schema\"");
  CHECK(manifest_error("[]") == "course.json: the document: an object is expected, not an array");
}

TEST_CASE("Manifest: this build's course.json describes the tree", "[frontend][manifest]") {
  const Manifest manifest = read_manifest(FMBD_COURSE_JSON);
  CHECK(fs::equivalent(manifest.source_dir, FMBD_SOURCE_DIR));
  REQUIRE_FALSE(manifest.modules.empty());
  std::set<std::string> exercise_files;
  for (const Module& module : manifest.modules) {
    INFO(module.folder);
    CHECK(module.id == module_id(module.number));
    CHECK(module.folder.rfind("module" + module_id(module.number).substr(1) + "_", 0) == 0);  // module08_...
    CHECK_FALSE(module.exercises.empty());
    std::set<std::string> tasks;  // the TODO(MnnTk) markers of its exercise files
    for (const std::string& file : module.exercises) {
      CHECK(fs::is_regular_file(fs::path(FMBD_SOURCE_DIR) / file));
      CHECK(file.rfind(module.folder + "/src/", 0) == 0);
      exercise_files.insert(file);
      const std::string text = read_file(fs::path(FMBD_SOURCE_DIR) / file);
      for (std::size_t at = text.find("TODO(M"); at != std::string::npos; at = text.find("TODO(M", at + 1)) {
        const std::optional<WrittenTask> task = task_id(text.substr(at + 5, text.find(')', at) - at - 5));
        if (task) tasks.insert(task->id);
      }
    }
    CHECK_FALSE(tasks.empty());
    for (const std::string& task : tasks) CHECK(task_id(task)->task.module == module.number);
    if (module.hints) {
      const std::string ladders = read_file(fs::path(FMBD_SOURCE_DIR) / *module.hints);
      REQUIRE_FALSE(ladders.empty());
      for (const std::string& task : tasks) {
        INFO(task);
        CHECK(hints::levels_of(ladders, task) > 0);
      }
    }
  }
  // The graded programs are those of modules the manifest has, with their targets.
  for (const GradedItem& item : manifest.graded) {
    INFO(item.id);
    CHECK(manifest.module(item.module) != nullptr);
    const bool has_reference = manifest.module(item.module)->reference_library.has_value();
    if (item.kind == "problems") {  // the tutorial problems: one program, its own reference
      CHECK(item.id == module_id(item.module) + "P");
      CHECK(item.target == "m" + item.id.substr(1, 2) + "_problems");
      CHECK(item.inputs == std::vector<std::string>{manifest.module(item.module)->folder + "/answers.txt"});
      CHECK((item.needs_identity && !item.classroom && item.without_reference == WithoutReference::format));
      CHECK(item.links_student_code == !has_reference);  // format-only: built on the student's stages
    } else {
      CHECK(item.kind == "catch");
      CHECK(item.target == "m" + item.id.substr(1) + "_student");
      CHECK((item.inputs.empty() && !item.needs_identity && item.links_student_code && item.classroom));
    }
    CHECK(item.program.find(manifest.build_dir) == 0);
    CHECK(item.reference_program.has_value() == has_reference);
  }
  // No exercise file lies outside the manifest: every moduleNN_*/src/*.cpp but the given ones.
  for (const Module& module : manifest.modules) {
    for (const auto& entry : fs::directory_iterator(fs::path(FMBD_SOURCE_DIR) / module.folder / "src")) {
      const std::string name = entry.path().filename().string();
      if (entry.path().extension() != ".cpp" || name.find("_given.cpp") != std::string::npos) continue;
      CHECK(exercise_files.count(module.folder + "/src/" + name) == 1);
    }
  }
}

TEST_CASE("Release: the README filters make a README true of the release", "[frontend][release][markdown]") {
  const std::string readme =
      "# Course\n\nIntro.\n<!-- instructor-only -->\nSecret.\n\n\n<!-- /instructor-only -->\n\n\nEnd.\n";
  CHECK(markdown::strip_marked(readme, {"instructor-only"}) == "# Course\n\nIntro.\n\n\nEnd.\n");
  CHECK(markdown::squeeze_blank_lines(markdown::strip_marked(readme, {"instructor-only"})) == "# Course\n\nIntro.\n\nEnd.\n");
  CHECK(markdown::strip_marked(readme, {"extras"}) == readme);  // another mark: unchanged
  // Nested marks of two kinds, each line exactly the mark.
  CHECK(markdown::strip_marked("a\n<!-- extras -->\nb\n <!-- /extras -->\n<!-- /extras -->\nc", {"extras"}) == "a\nc");

  const auto exists = [](const std::string& target) { return target == "module01/README.md" || target == "img.png"; };
  CHECK(markdown::drop_missing_links("See [one](module01/README.md) and [two](module02/README.md#x).\n", exists) ==
        "See [one](module01/README.md) and two.\n");
  CHECK(markdown::drop_missing_links("| [2](module02/README.md) | two |\n| [1](module01/README.md) | one |\n", exists) ==
        "| [1](module01/README.md) | one |\n");
  CHECK(markdown::drop_missing_links("![plot](gone.png) ![ok](img.png)", exists) == "plot ![ok](img.png)");
  // URLs, anchors and absolute paths stay; a target with a space is no link.
  const std::string kept = "[a](https://x.org/y) [b](#section) [c](/abs/path) [d](no such)";
  CHECK(markdown::drop_missing_links(kept, exists) == kept);
}

TEST_CASE("Release: the policy file and its path patterns", "[frontend][release]") {
  const ReleasePolicy policy = parse_policy(
      "# comment\nomit solutions\nomit autograder/module*/hidden\n\nomit-engine extras\nstrip instructor-only\n"
      "strip-engine extras\ngradescope-omit tests\n",
      "policy.txt");
  CHECK(policy.omit == std::vector<std::string>{"solutions", "autograder/module*/hidden"});
  CHECK(policy.omit_engine == std::vector<std::string>{"extras"});
  CHECK(policy.strip == std::vector<std::string>{"instructor-only"});
  CHECK(policy.strip_engine == std::vector<std::string>{"extras"});
  CHECK(policy.gradescope_omit == std::vector<std::string>{"tests"});
  CHECK(usage_error([] { parse_policy("omit a\nkeep b\n", "policy.txt"); }) ==
        "policy.txt:2: no rule 'keep' (omit, omit-engine, strip, strip-engine, gradescope-omit)");
  CHECK(usage_error([] { parse_policy("omit\n", "policy.txt"); }) == "policy.txt:1: write a rule as RULE ARGUMENT");
  CHECK(policy_rule(policy, "omit") == policy.omit);
  CHECK(policy_rule(policy, "gradescope-omit") == std::vector<std::string>{"tests"});
  CHECK(usage_error([&policy] { policy_rule(policy, "keep"); }) ==
        "no rule 'keep' (omit, omit-engine, strip, strip-engine, gradescope-omit)");

  CHECK(excluded("solutions/module01_kinematics/planar.cpp", policy.omit));
  CHECK(excluded("autograder/module03_lagrange/hidden/x.test.cpp", policy.omit));
  CHECK_FALSE(excluded("autograder/module03_lagrange/visible/x.test.cpp", policy.omit));
  CHECK_FALSE(excluded("solutionsX/a.cpp", policy.omit));  // a name, not a prefix of one
  CHECK_FALSE(excluded("autograder/hidden", policy.omit));
  // The real policy keeps the tests and the solutions out of a release, and the grader in it.
  std::string text = read_file(fs::path(FMBD_SOURCE_DIR) / "autograder/release_policy.txt");
  const ReleasePolicy real = parse_policy(text, "release_policy.txt");
  CHECK(excluded("tests/release_check.sh", real.omit));
  CHECK(excluded("autograder/mistakes/m01.mutant", real.omit));
  CHECK(excluded("docs/instructors.md", real.omit));  // the instructor's guides stay out
  CHECK(excluded("docs/tests.md", real.omit));
  CHECK_FALSE(excluded("docs/students.md", real.omit));  // the students' guide goes with the release
  CHECK_FALSE(excluded("docs/lecturers.md", real.omit));
  CHECK_FALSE(excluded("autograder/driver/grade.cpp", real.omit));
  CHECK_FALSE(excluded("module01_kinematics/src/planar.cpp", real.omit));
}

namespace {

// ./workbook inspect ARGS in the folder `scratch`: its exit status and output, or the message of
// the error that ended it with its exit status.
struct Inspected {
  int status = 0;
  std::string out;
};
Inspected inspect(const Scratch& scratch, const std::vector<std::string>& args, const Manifest& manifest = {}) {
  std::ostringstream out;
  const Context context{scratch.path.string(), manifest, out};
  Inspected result;
  try {
    result.status = run_inspect(args, context);
  } catch (const std::exception& error) {
    result.status = exit_status_of(error);
    out << "workbook: " << error.what() << "\n";
  }
  result.out = out.str();
  return result;
}

}  // namespace

TEST_CASE("Inspect: the workbook's files read for scripts; each check can fail", "[frontend][inspect]") {
  const Scratch scratch("inspect");
  const std::string header = "module,task,score,max_score,status\n";
  const std::string full = (scratch.path / "full.csv").string();
  const std::string partial = (scratch.path / "partial.csv").string();
  write_file(full, header + "M01,T1,4,4,passed\nM01,P1,2,2,passed\n");
  write_file(partial, header + "M01,T1,4,4,passed\nM01,T2,1.5,3,failed\nM01,P1,0,2,failed\n");

  CHECK(inspect(scratch, {"tasks", partial, "--sum", "max_score"}).out == "9\n");
  CHECK(inspect(scratch, {"tasks", partial, "--sum", "score"}).out == "5.5\n");
  CHECK(inspect(scratch, {"tasks", partial, "--count"}).out == "3\n");
  const Inspected passed = inspect(scratch, {"tasks", full, "--full"});
  CHECK((passed.status == 0 && passed.out.empty()));
  const Inspected below = inspect(scratch, {"tasks", partial, "--full"});
  CHECK(below.status == 1);
  CHECK(below.out == "M01 T2: 1.5 of 3, failed\nM01 P1: 0 of 2, failed\n"
                     "workbook: 2 of the 3 tasks in " + partial + " scored below their maximum (above)\n");
  write_file(scratch.path / "empty.csv", header);
  CHECK(inspect(scratch, {"tasks", (scratch.path / "empty.csv").string(), "--full"}).status == 1);
  // --of: the tasks of the items with a capability; an item whose lister is not built cannot say.
  const Manifest manifest = parse_manifest(kManifest, "course.json");
  CHECK(inspect(scratch, {"tasks", full, "--full", "--of", "problems"}, manifest).out ==
        "workbook: --of: no capability 'problems' (inputs, needs_identity, links_student_code, classroom)\n");
  const Inspected unbuilt = inspect(scratch, {"tasks", full, "--full", "--of", "links_student_code"}, manifest);
  CHECK(unbuilt.status == 2);
  CHECK(unbuilt.out.find("workbook: --of: the tasks of M01 cannot be listed: ") == 0);
  // No item of FILE's modules has it: no task, which --full does not take for a pass.
  const Inspected none = inspect(scratch, {"tasks", full, "--full", "--of", "needs_identity"}, Manifest{});
  CHECK(none.status == 1);
  CHECK(none.out.find("no task of the items with needs_identity in ") != std::string::npos);

  // The gradebook: its columns add up, or the submission is named.
  const std::string book = "submission,score,max_score,status,M01,M01T1,M01T2\n";
  write_file(scratch.path / "good.csv", book + "alice,5,7,graded,5,4,1\nbob,0,7,build_error:M01,0,0,0\n");
  write_file(scratch.path / "bad.csv", book + "alice,5,7,graded,5,4,2\n");
  CHECK(inspect(scratch, {"gradebook", (scratch.path / "good.csv").string()}).status == 0);
  const Inspected bad = inspect(scratch, {"gradebook", (scratch.path / "bad.csv").string()});
  CHECK(bad.status == 1);
  CHECK(bad.out.find("alice: the tasks of M01 add up to 6, M01 is 5\n") == 0);
  CHECK(inspect(scratch, {"gradebook", partial}).status == 1);  // not a gradebook

  // The timings: the key of each timed test; a line out of the format fails.
  write_file(scratch.path / "timings.txt", "# comment\nM01\tvisible\t0.02\trotation\nM02\thidden\t1\tgamma\n");
  CHECK(inspect(scratch, {"timings", (scratch.path / "timings.txt").string()}).out == "M01\trotation\nM02\tgamma\n");
  write_file(scratch.path / "timings.txt", "M01 0.02 rotation\n");
  CHECK(inspect(scratch, {"timings", (scratch.path / "timings.txt").string()}).status == 1);

  // The policy: a rule's arguments; a rule that is none, or a file out of the format.
  const std::string policy = (scratch.path / "policy.txt").string();
  write_file(policy, "# comment\nomit tests\ngradescope-omit extras\nomit solutions\n");
  CHECK(inspect(scratch, {"policy", policy, "--rule", "omit"}).out == "tests\nsolutions\n");
  CHECK(inspect(scratch, {"policy", policy, "--rule", "keep"}).status == 2);
  write_file(policy, "keep tests\n");
  CHECK(inspect(scratch, {"policy", policy, "--rule", "omit"}).status == 1);

  // A wrong command line, or a file that is not there: exit status 2.
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"tasks", full},                                // no --sum, --count or --full
           {"tasks", full, "--count", "--full"},           // two
           {"tasks", full, "--sum", "points"},             // no such column
           {"tasks", full, "--rule", "omit", "--count"},   // --rule is policy's
           {"tasks", full, "--count", "--manifest", "c"},  // --manifest goes with --of
           {"policy", policy},                             // no --rule
           {"results", full},                              // no such format
           {"gradebook"},                                  // no file
           {"gradebook", (scratch.path / "missing.csv").string()}}) {
    INFO(args.front());
    CHECK(inspect(scratch, args).status == 2);
  }
}

TEST_CASE("Inspect: a Classroom workflow, a test listing and a benchmark CSV; each check can fail",
          "[frontend][inspect]") {
  const Scratch scratch("inspect-more");
  // A Classroom workflow: its command-grader steps (not the checkout or the reporter).
  const std::string workflow = (scratch.path / "classroom.yml").string();
  const std::string step = "        uses: classroom-resources/autograding-command-grader@v1\n        with:\n";
  write_file(workflow, "    steps:\n      - name: Checkout code\n        uses: actions/checkout@v4\n"
                       "      - name: M01 T1\n        id: m01-t1\n" + step +
                       "          command: ./workbook grade --task M01T1 --strict\n          max-score: 4\n"
                       "      - name: M01 T2\n        id: m01-t2\n" + step +
                       "          command: ./workbook grade --task M01T2 --strict\n          max-score: 1.5\n"
                       "      - name: Autograding Reporter\n        with:\n          runners: m01-t1,m01-t2\n");
  CHECK(inspect(scratch, {"classroom", workflow}).out ==
        "m01-t1\t4\t./workbook grade --task M01T1 --strict\nm01-t2\t1.5\t./workbook grade --task M01T2 --strict\n");
  CHECK(inspect(scratch, {"classroom", workflow, "--count"}).out == "2\n");
  CHECK(inspect(scratch, {"classroom", workflow, "--sum", "max_score"}).out == "5.5\n");
  write_file(workflow, "      - name: M01 T1\n        id: m01-t1\n" + step + "          max-score: 4\n");
  CHECK(inspect(scratch, {"classroom", workflow}).out.find("lacks its id, command or max-score") != std::string::npos);
  write_file(workflow, "      - name: M01 T1\n        id: m01-t1\n" + step + "          command: x\n          max-score: four\n");
  CHECK(inspect(scratch, {"classroom", workflow}).status == 1);

  // A test program's listing, read by the grade driver's reader; a line without tags fails.
  const std::string listing = (scratch.path / "listing.txt").string();
  write_file(listing, "rotation\t[M01][T1]\ngamma [x]\t[M02][T2][points=2][hidden]\nhelper\t[tools]\n");
  CHECK(inspect(scratch, {"listing", listing}).out == "M01\trotation\nM02\tgamma [x]\nother\thelper\n");
  write_file(listing, "rotation [M01][T1]\n");
  const Inspected untagged = inspect(scratch, {"listing", listing});
  CHECK(untagged.status == 1);
  CHECK(untagged.out.find("line 1: expected name<TAB>tags") != std::string::npos);

  // A benchmark CSV: its rows (after the header); a row without five fields or a number fails.
  const std::string bench = (scratch.path / "bench.csv").string();
  write_file(bench, "group,case,quantity,value,unit\nsimulate,pendulum,cost per step,2.5,us\nmodal,n=9,error,1e-12,1\n");
  CHECK(inspect(scratch, {"bench", bench}).out == "2 rows\n");
  for (const char* text : {"simulate,pendulum,2.5,us\n", "simulate,pendulum,cost,fast,us\n",
                                  "simulate,pendulum,cost,nan,us\n", "group,case,quantity,value,unit\n"}) {
    INFO(text);
    write_file(bench, text);
    CHECK(inspect(scratch, {"bench", bench}).status == 1);
  }

  // A wrong command line: exit status 2.
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"classroom", workflow, "--sum", "score"},  // classroom has max_score only
           {"classroom", workflow, "--full"},          // --full is tasks'
           {"bench", bench, "--count"},                // --count is tasks' and classroom's
           {"listing"}}) {                             // no file
    INFO(args.front());
    CHECK(inspect(scratch, args).status == 2);
  }
}

