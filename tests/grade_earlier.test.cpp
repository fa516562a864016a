// The grade's word on the earlier modules: whose code the graded modules run on (always said), and
// the advice the driver prints where an earlier module's task is not implemented yet
// (--reference-earlier where that module's reference is released). The driver's line itself is
// tested with its fixture (driver.messages.*).
#include <algorithm>
#include <string>
#include <vector>

#include "grading.hpp"

#include "frontend_support.hpp"
#include "grade_plan.hpp"
#include "manifest.hpp"

using namespace fmbd::frontend;
using fmbd::frontend_testing::planned_tree;

namespace {

// Modules 1-3, the reference of modules 1 and 2 released; a code item per module.
Manifest three_modules() {
  Manifest manifest;
  manifest.schema = kManifestSchema;
  manifest.grade_driver = "/b/fmbd-grade";
  for (int n = 1; n <= 3; ++n) {
    const std::string id = "M0" + std::to_string(n);
    manifest.modules.push_back({n, id, "module0" + std::to_string(n), {}, std::nullopt,
                                "/b/libstage0" + std::to_string(n) + "_student.a",
                                n <= 2 ? std::optional<std::string>("/b/libstage0" + std::to_string(n) + "_reference.a")
                                       : std::nullopt});
    GradedItem item;
    item.id = id;
    item.kind = "catch";
    item.module = n;
    item.target = "m0" + std::to_string(n) + "_student";
    item.program = "/b/" + item.target;
    if (n <= 2) {
      item.reference_target = "m0" + std::to_string(n) + "_reference";
      item.reference_program = "/b/" + *item.reference_target;
    }
    item.links_student_code = true;
    manifest.graded.push_back(item);
  }
  return manifest;
}

}  // namespace

TEST_CASE("Grade: it says whose earlier modules it ran on, and suggests --reference-earlier", "[frontend][grade][plan]") {
  Manifest course = three_modules();
  GradeOptions o;
  o.modules = {3};
  const GradingPlan own = plan_grading(course, o, planned_tree(false, 1));
  CHECK(own.earlier ==
        "workbook: module 3 runs on your own code of modules 1-2 (--reference-earlier: on the released reference "
        "of modules 1-2)\n");
  CHECK(own.options.earlier_note ==
        "Finish them, or grade on the released reference of modules 1-2: ./workbook grade --reference-earlier "
        "--module 3");
  // The advice reaches the driver, which prints it under its line naming the earlier stubs.
  const std::vector<ItemOutcome> built(own.items.size(), ItemOutcome{BuildState::built, true, ""});
  const std::vector<std::string> argv = driver_argv(driver_invocation(own, built));
  CHECK(std::find(argv.begin(), argv.end(), "--earlier-note") != argv.end());

  o.reference_earlier = true;
  const GradingPlan reference = plan_grading(course, o, planned_tree(false, 1));
  CHECK(reference.earlier == "workbook: module 3 runs on the released reference (solutions/) of modules 1-2\n");
  CHECK(reference.options.earlier_note == "Their reference is not released here (solutions/): finish them first.");

  // Only module 1's reference released: module 2 is the student's own under --reference-earlier too.
  course.modules[1].reference_library = std::nullopt;
  CHECK(plan_grading(course, o, planned_tree(false, 1)).earlier ==
        "workbook: module 3 runs on the released reference (solutions/) of module 1 and your own code of module 2 "
        "(no reference of it released)\n");
  // None released: no --reference-earlier to suggest.
  course.modules[0].reference_library = std::nullopt;
  o.reference_earlier = false;
  const GradingPlan none = plan_grading(course, o, planned_tree(false, 1));
  CHECK(none.earlier == "workbook: module 3 runs on your own code of modules 1-2\n");
  CHECK(none.options.earlier_note == "No earlier module's reference is released here (solutions/): finish them first.");
}

TEST_CASE("Grade: a submission and the solutions say whose earlier modules too; module 1 has none", "[frontend][grade][plan]") {
  const Manifest course = three_modules();
  GradeOptions o;
  const GradingPlan submission = plan_grading(course, o, planned_tree(true, 1));
  CHECK(submission.earlier ==
        "workbook: modules 2-3 run on the reference of modules 1-2 (--own-earlier: on the submission's own)\n");
  CHECK(submission.options.earlier_note.empty());
  o.own_earlier = true;
  CHECK(plan_grading(course, o, planned_tree(true, 1)).earlier ==
        "workbook: modules 2-3 run on the submission's own code of modules 1-2 (--own-earlier)\n");
  o = GradeOptions{};
  o.solutions = true;
  CHECK(plan_grading(course, o, planned_tree(false, 1)).earlier == "workbook: module 2 runs on the reference solutions of module 1\n");
  o = GradeOptions{};
  o.modules = {1};
  CHECK(plan_grading(course, o, planned_tree(false, 1)).earlier.empty());
}
