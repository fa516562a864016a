// The front end's library, continued from frontend.test.cpp: the grade plan and the driver's
// invocation, bench tables, the build's layout, task ids and the grading protocol.

#include <unistd.h>

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

namespace {

// A course of two modules: module 1 with its reference (its code's tests listed by the reference
// build; its problems their own lister, built without the student's code), module 2 without
// (its problems check only the format). Each module has a problems item with an answers file.
// A graded item whose programs are /b/TARGET.
GradedItem graded(const std::string& id, int module, const std::string& target,
                  const std::optional<std::string>& reference_target, const std::optional<std::string>& vet_target) {
  GradedItem item;
  item.id = id;
  item.kind = id.back() == 'P' ? "problems" : "catch";
  item.module = module;
  item.target = target;
  item.program = "/b/" + target;
  item.reference_target = reference_target;
  if (reference_target) item.reference_program = "/b/" + *reference_target;
  item.vet_target = vet_target;
  if (vet_target) item.vet_report = "/b/vet/" + *vet_target + ".txt";
  return item;
}

Manifest planned_course() {
  Manifest manifest;
  manifest.schema = kManifestSchema;
  manifest.grade_driver = "/b/fmbd-grade";
  manifest.modules = {{1, "M01", "module01_kinematics", {"module01_kinematics/src/planar.cpp"}, std::nullopt,
                       "/b/libstage01_student.a", "/b/libstage01_reference.a"},
                      {2, "M02", "module02_newton_raphson", {"module02_newton_raphson/src/newton.cpp"}, std::nullopt,
                       "/b/libstage02_student.a", std::nullopt}};
  GradedItem code = graded("M01", 1, "m01_student", "m01_reference", "m01_vet");
  code.links_student_code = true;
  GradedItem problems = graded("M01P", 1, "m01_problems", "m01_problems", std::nullopt);
  problems.inputs = {"module01_kinematics/answers.txt"};
  problems.needs_identity = true;
  GradedItem code2 = graded("M02", 2, "m02_student", std::nullopt, "m02_vet");
  code2.links_student_code = true;
  GradedItem problems2 = graded("M02P", 2, "m02_problems", std::nullopt, std::nullopt);
  problems2.inputs = {"module02_newton_raphson/answers.txt"};
  problems2.needs_identity = true;
  problems2.links_student_code = true;
  problems2.without_reference = WithoutReference::format;
  manifest.graded = {code, problems, code2, problems2};
  return manifest;
}

// The planned tree, module 2's answers file in it, 3 tests at once.
TreeFacts planned_tree(bool submission) {
  TreeFacts facts = fmbd::frontend_testing::planned_tree(submission, 3);
  facts.existing_inputs = {"module02_newton_raphson/answers.txt"};
  return facts;
}

std::vector<std::string> ids_of(const GradingPlan& plan) {
  std::vector<std::string> ids;
  for (const PlannedItem& item : plan.items) ids.push_back(item.item.id);
  return ids;
}

}  // namespace

TEST_CASE("Grade plan: one's own tree skips an item not started, a submission grades it", "[frontend][grade][plan]") {
  const Manifest course = planned_course();
  GradeOptions o;
  o.driver.timeout = "10";
  const GradingPlan own = plan_grading(course, o, planned_tree(false));
  CHECK(ids_of(own) == std::vector<std::string>{"M01", "M02", "M02P"});
  REQUIRE(own.not_started.size() == 1);
  CHECK(own.not_started[0].id == "M01P");
  CHECK(own.not_started[0].input == "module01_kinematics/answers.txt");
  CHECK(not_started_message(own) ==
        "workbook: not started (no file of its answers yet), so not graded here: M01P "
        "(module01_kinematics/answers.txt); ./workbook problems MNN prints the problems\n");
  // What is built: the driver, each item's program and its lister; nothing of the item not started.
  CHECK(own.targets == std::vector<std::string>{"fmbd-grade", "m01_student", "m01_reference", "m02_student",
                                                "m02_problems"});
  const PlannedItem& m01 = own.items[0];
  CHECK(m01.program == "/b/m01_student");
  CHECK(m01.lister == std::optional<std::string>("/b/m01_reference"));
  CHECK(m01.vet_target == std::optional<std::string>("m01_vet"));
  CHECK(m01.log == "/t/build/ci/m01_student.build.log");
  CHECK(m01.errors_file == "/t/build/ci/compile/m01.txt");
  CHECK(m01.name == "module01_kinematics");
  CHECK_FALSE(own.items[1].lister);  // module 2 has no reference: its program lists its tests
  CHECK(own.watched.front().message == "the grade driver is ready");
  CHECK(own.exercises == std::vector<std::string>{"/t/module01_kinematics/src/planar.cpp",
                                                  "/t/module02_newton_raphson/src/newton.cpp"});
  CHECK(own.options.timeout == "10");
  CHECK(own.jobs == std::optional<int>(3));
  CHECK_FALSE(own.timings);

  const GradingPlan submission = plan_grading(course, o, planned_tree(true));
  CHECK(ids_of(submission) == std::vector<std::string>{"M01", "M01P", "M02", "M02P"});
  CHECK(submission.not_started.empty());
  CHECK(not_started_message(submission).empty());
  const PlannedItem& m01p = submission.items[1];
  CHECK_FALSE(m01p.student_code);  // built without the student's code: its failure is not theirs
  CHECK(m01p.lister == std::optional<std::string>("/b/m01_problems"));
  CHECK(submission.items[0].student_code);
}

TEST_CASE("Grade plan: --solutions grades the items with a reference, and refuses a module without", "[frontend][grade][plan]") {
  Manifest course = planned_course();
  GradeOptions o;
  o.solutions = true;
  TreeFacts facts = planned_tree(false);
  facts.identity = "reference";
  const GradingPlan plan = plan_grading(course, o, facts);
  CHECK(ids_of(plan) == std::vector<std::string>{"M01", "M01P"});  // M01P's answers: the model answers
  CHECK(plan.items[0].program == "/b/m01_reference");
  CHECK(plan.items[0].target == "m01_reference");
  CHECK_FALSE(plan.items[0].lister);
  CHECK_FALSE(plan.items[0].vet_target);
  CHECK(plan.targets == std::vector<std::string>{"fmbd-grade", "m01_reference", "m01_problems"});
  CHECK(identity_message(plan.identity) == "workbook: M01P graded with the numbers of \"reference\"\n");

  // An item of the module without its own reference is not graded: there is nothing to run.
  Manifest unlisted = course;
  unlisted.graded[1].reference_program = unlisted.graded[1].reference_target = std::nullopt;
  CHECK(ids_of(plan_grading(unlisted, o, facts)) == std::vector<std::string>{"M01"});

  o.modules = {2};
  CHECK(usage_error([&] { plan_grading(course, o, facts); })
            .find("--solutions: module 2 (module02_newton_raphson) has no reference solution here; this copy "
                  "carries those of modules 1") == 0);
  o.modules = {7};
  CHECK(usage_error([&] { plan_grading(course, o, facts); })
            .find("--solutions: module 7 (not in this copy) has no reference solution here") == 0);
  for (GradedItem& item : course.graded) item.reference_program = item.reference_target = std::nullopt;
  o.modules.clear();
  CHECK(usage_error([&] { plan_grading(course, o, facts); }) ==
        "--solutions: this copy carries the reference solution of no module (solutions/)");
}

TEST_CASE("Grade plan: --module and --task choose the modules; the identity's message", "[frontend][grade][plan]") {
  const Manifest course = planned_course();
  GradeOptions o;
  o.modules = {2};
  const GradingPlan plan = plan_grading(course, o, planned_tree(true));
  CHECK(ids_of(plan) == std::vector<std::string>{"M02", "M02P"});
  CHECK(plan.targets == std::vector<std::string>{"fmbd-grade", "m02_student", "m02_problems"});
  CHECK(identity_message(plan.identity) ==
        "workbook: the numbers of M02P depend on your name: ./workbook grade --student \"YOUR NAME\" "
        "(or ./workbook problems --student \"YOUR NAME\" once)\n"
        "workbook: M02P without the reference here: only the format of the answers is checked; your "
        "instructor's grader checks the values\n");
  o.modules = {1, 2};  // --module 1 --task M02T1
  CHECK(ids_of(plan_grading(course, o, planned_tree(true))).size() == 4);
  // The preset: a submission on the reference's earlier modules, unless --own-earlier.
  CHECK(grading_preset(o, true, true) == "reference");
  CHECK(grading_preset(o, false, false) == "student");
  o.own_earlier = true;
  CHECK(grading_preset(o, true, true) == "student");
  CHECK(usage_error([&] { grading_preset(o, true, false); }) ==
        "--submission needs the solutions/ folder (an instructor's copy)");
  o.solutions = true;
  CHECK(usage_error([&] { grading_preset(o, true, true); }) == "--solutions and --submission exclude each other");
}

TEST_CASE("Driver invocation: each program with its lister, a broken or rejected module's report", "[frontend][grade][plan]") {
  const Manifest course = planned_course();
  GradeOptions o;
  o.driver.modules = {"1", "2"};
  TreeFacts facts = planned_tree(true);
  facts.has_timings = true;
  const GradingPlan plan = plan_grading(course, o, facts);
  REQUIRE(plan.items.size() == 4);
  const std::vector<ItemOutcome> outcomes = {
      {BuildState::built, true, ""},
      {BuildState::broken, true, "/t/build/ci/compile/m01P.txt"},
      {BuildState::rejected, false, "/t/build/ci/vet/m02.txt"},
      {BuildState::broken, false, "/t/build/ci/compile/m02P.txt"},  // no lister: not graded
  };
  const DriverInvocation invocation = driver_invocation(plan, outcomes);
  REQUIRE(invocation.programs.size() == 3);
  CHECK(invocation.programs[1].build_errors->module == "1");
  CHECK(driver_argv(invocation) ==
        std::vector<std::string>{"/b/fmbd-grade", "--timings", "/t/autograder/timings.txt", "--jobs", "3",
                                 "--module", "1", "--module", "2",
                                 "--build-errors", "1=/t/build/ci/compile/m01P.txt",
                                 "--reject", "02=/t/build/ci/vet/m02.txt",
                                 "/b/m01_student", "--listed-by", "/b/m01_reference",
                                 "/b/m01_problems", "--listed-by", "/b/m01_problems", "--grades-inputs",
                                 "/b/m02_student"});
  // M01P grades the student's inputs (its capabilities), so module 1's build errors leave it alone.
  CHECK(invocation.programs[1].grades_inputs);
  CHECK_FALSE(invocation.programs[0].grades_inputs);
  // A lister that did not build lists nothing: the program lists its own tests.
  std::vector<ItemOutcome> unlisted = outcomes;
  unlisted[0].lister_built = false;
  const std::vector<std::string> unlisted_argv = driver_argv(driver_invocation(plan, unlisted));
  REQUIRE(unlisted_argv.size() == 19);
  CHECK(std::vector<std::string>(unlisted_argv.begin() + 13, unlisted_argv.begin() + 15) ==
        std::vector<std::string>{"/b/m01_student", "/b/m01_problems"});
  // The user's --jobs is the driver's; no timings file, no --timings.
  o.driver = DriverOptions{};
  o.driver.jobs = "1";
  facts.has_timings = false;
  const std::vector<std::string> argv = driver_argv(driver_invocation(plan_grading(course, o, facts), outcomes));
  CHECK(std::vector<std::string>(argv.begin(), argv.begin() + 4) ==
        std::vector<std::string>{"/b/fmbd-grade", "--jobs", "1", "--build-errors"});
  // Nothing built that can be graded: nothing to grade.
  const std::vector<ItemOutcome> skipped(4, ItemOutcome{BuildState::skipped, false, ""});
  CHECK(usage_error([&] { driver_invocation(plan, skipped); }) == "nothing to grade");
  // Every option of the driver, typed, written in one order.
  DriverOptions all;
  all.modules = {"1"};
  all.tasks = {"M01T2"};
  all.json = "/o/results.json";
  all.junit = "/o/junit.xml";
  all.csv = "/o/tasks.csv";
  all.timings_out = "/o/timings.txt";
  all.timeout = "30";
  all.jobs = "2";
  all.hidden_visibility = "hidden";
  all.strict = true;
  const DriverInvocation typed{"/b/fmbd-grade", std::nullopt, std::nullopt, all, {}};
  CHECK(driver_argv(typed) == std::vector<std::string>{"/b/fmbd-grade", "--module", "1", "--task", "M01T2",
                                                       "--json", "/o/results.json", "--junit", "/o/junit.xml",
                                                       "--csv", "/o/tasks.csv", "--timings-out", "/o/timings.txt",
                                                       "--timeout", "30", "--jobs", "2", "--hidden-visibility",
                                                       "hidden", "--strict"});
}

TEST_CASE("Bench: the table of a CSV text, and the speed targets met or not", "[frontend][bench]") {
  const std::string table = bench_table("group,case,quantity,value,unit\n"
                                        "simulate,pendulum,cost per step,2.5,us\n"
                                        "simulate,pendulum,ratio_to_target,0.8,1\n"
                                        "modal,beam 1000 elements,ratio_to_target,3.2,1\n");
  CHECK(table.rfind("group          case ", 0) == 0);  // the header, in the columns of the rows
  CHECK(table.find("\nsimulate       pendulum ") != std::string::npos);
  CHECK(table.find("Speed targets (cost per step / target):\n") != std::string::npos);
  CHECK(table.find("simulate: pendulum") != std::string::npos);
  CHECK(table.find("met (0.8x)") != std::string::npos);
  CHECK(table.find("not met: 3.2x the target") != std::string::npos);
  CHECK(bench_table("group,case,quantity,value,unit\nsimulate,pendulum,cost per step,2.5,us\n").find("Speed targets") ==
        std::string::npos);
  CHECK_THROWS_AS(bench_table("simulate,pendulum,2.5,us\n"), StepFailed);  // a row of four fields
}

TEST_CASE("Layout: the paths of a build folder and of the timings, each spelled once", "[frontend][layout]") {
  const BuildLayout layout = BuildLayout::of_preset("/t", "ci");
  CHECK(layout.dir == "/t/build/ci");
  CHECK(BuildLayout::of_preset("ci").configure_log() == "build/ci/configure.log");
  CHECK(layout.course_json() == "/t/build/ci/course.json");
  CHECK(layout.configure_log() == "/t/build/ci/configure.log");
  CHECK(layout.errors_file("M01") == "/t/build/ci/compile/m01.txt");
  CHECK(layout.errors_file("M01P") == "/t/build/ci/compile/m01P.txt");
  CHECK(layout.build_log("fmbd-grade") == "/t/build/ci/fmbd-grade.build.log");
  CHECK(timings_path("/t") == "/t/autograder/timings.txt");
  CHECK(preset_build_dir("/t", "ci") == layout.dir);
}

TEST_CASE("Task ids: one strict parser and its formatter (common/task_id.hpp)", "[protocol][ids]") {
  using fmbd::protocol::TaskId;
  struct Valid {
    const char* text;
    TaskId task;
    const char* formatted;
  };
  for (const Valid& v : {Valid{"M01T3", {1, 'T', 3}, "M01T3"}, Valid{"M08T12", {8, 'T', 12}, "M08T12"},
                         Valid{"M01P2", {1, 'P', 2}, "M01P2"}, Valid{"M99P99", {99, 'P', 99}, "M99P99"},
                         Valid{"M00T0", {0, 'T', 0}, "M00T0"}, Valid{"M01T03", {1, 'T', 3}, "M01T3"}}) {
    INFO(v.text);
    const std::optional<TaskId> task = fmbd::protocol::parse_task_id(v.text);
    REQUIRE(task);
    CHECK(*task == v.task);
    CHECK(fmbd::protocol::format_task_id(*task) == v.formatted);
  }
  for (const char* text : {"", "M", "M01", "M01T", "M1T3", "m01t3", "M01t3", "M01X3", "M01T123", "M001T3", " M01T3",
                           "M01T3 ", "M01T3x", "MA1T3", "M01T-3", "N01T3", "M01TT3", "M01T+3"}) {
    INFO("'" << text << "'");
    CHECK_FALSE(fmbd::protocol::parse_task_id(text));
  }
  CHECK(fmbd::protocol::format_module_id(7) == "M07");
  CHECK(fmbd::protocol::is_task_kind('T'));
  CHECK(fmbd::protocol::is_task_kind('P'));
  CHECK_FALSE(fmbd::protocol::is_task_kind('t'));
  CHECK_FALSE(fmbd::protocol::is_task_kind('\0'));
  // The code's tasks are reported before those of the inputs, each kind by number.
  CHECK(fmbd::protocol::task_before('T', 9, 'P', 1));
  CHECK_FALSE(fmbd::protocol::task_before('P', 1, 'T', 9));
  CHECK(fmbd::protocol::task_before('P', 1, 'P', 2));
  CHECK_FALSE(fmbd::protocol::task_before('T', 2, 'T', 2));
}

TEST_CASE("Grading protocol: listing lines, task tags and the test-name escaping", "[protocol]") {
  CHECK(fmbd::protocol::listing_line("a test", "[M01][T2]") == "a test\t[M01][T2]\n");
  CHECK(fmbd::protocol::task_tags({1, 'P', 2}, "3") == "[M01][P2][points=3]");
  CHECK(fmbd::protocol::catch_test_spec("a, [b] *c~ \"d\" \\") == "\"a\\, \\[b\\] \\*c\\~ \\\"d\\\" \\\\\"");
  for (const char* name : {"plain", "M01P2: the angle, in degrees", "a, [b] *c~ \"d\" \\", ""}) {
    CHECK(fmbd::protocol::test_name_of_spec(fmbd::protocol::catch_test_spec(name)) == name);
  }
  CHECK(fmbd::protocol::test_name_of_spec("M01P2") == "M01P2");  // a bare name is itself
  CHECK(std::string(fmbd::protocol::kCompletionTokenPrefix) == "fmbd-completion-token: ");
}

TEST_CASE("Ids: M1T3, m01t3 and M01T3 name one task; others are refused", "[frontend][ids]") {
  for (const char* text : {"M1T3", "m01t3", "M01T3", "m1t3"}) {
    const auto task = task_id(text);
    REQUIRE(task);
    CHECK(task->id == "M01T3");
    CHECK(task->task == fmbd::protocol::TaskId{1, 'T', 3});
  }
  CHECK(task_id("M12T10")->id == "M12T10");
  CHECK(task_id("m1p2")->id == "M01P2");  // a tutorial problem
  CHECK(task_id("M01P2")->task.number == 2);
  CHECK(task_id("m1t03")->id == "M01T03");  // as written: it names no ladder's task
  CHECK(module_id(7) == "M07");
  CHECK_FALSE(task_id("M01"));
  CHECK_FALSE(task_id("M123T1"));
  CHECK_FALSE(task_id("M01T123"));
  CHECK_FALSE(task_id("X"));
  CHECK(usage_error([] { parse_task_id("x", "hint"); }) ==
        "hint: 'x' is not a task id; write it like M01T3 (./workbook hint lists them)");
  // The refusal quotes the id as rewritten: upper-cased, the module's zero added.
  CHECK(usage_error([] { parse_task_id("m1t3x", "hint"); }) ==
        "hint: 'M01T3x' is not a task id; write it like M01T3 (./workbook hint lists them)");
}

