// The hint gate's inputs: the opened levels as the front end writes them and the test programs
// read them (grading_protocol.hpp), the variable the front end hands the tests when it grades, and
// the task of a test from its tags (hint_gate.hpp). The gate on a failing check itself is
// m01.hint_gate.below and m01.hint_gate.last (autograder/CMakeLists.txt).

#include <string>

#include "grade.hpp"
#include "grading.hpp"
#include "grading_protocol.hpp"
#include "hints.hpp"
#include "layout.hpp"

using namespace fmbd;

TEST_CASE("hint gate: the test programs read the levels that ./workbook hint writes", "[hint_gate]") {
  std::string opened;
  opened = frontend::hints::with_opened(opened, "M01T2", 3);
  opened = frontend::hints::with_opened(opened, "M03T1", 1);
  opened = frontend::hints::with_opened(opened, "M01T2", 2);
  CHECK(protocol::opened_hint_level(opened, "M01T2") == 2);
  CHECK(protocol::opened_hint_level(opened, "M03T1") == 1);
  CHECK(protocol::opened_hint_level(opened, "M01T3") == 0);
  CHECK(protocol::opened_hint_level(opened, "M01T") == 0);
  // The last line of a task wins; blanks around the fields and a line without a level.
  CHECK(protocol::opened_hint_level("M02T4 1\n  M02T4\t3  \nM02T4\n", "M02T4") == 0);
  CHECK(protocol::opened_hint_level("M02T4 1\n  M02T4\t3  \n", "M02T4") == 3);
  CHECK(protocol::opened_hint_level("", "M02T4") == 0);
}

TEST_CASE("hint gate: grading a student's tree hands over its levels, a submission none", "[hint_gate]") {
  const auto own = frontend::hint_levels_environment("/course", "");
  CHECK(own.first == protocol::kHintsOpenedVariable);
  CHECK(own.second == frontend::hints_opened_path("/course"));
  CHECK(own.second == "/course/build/hints.opened");
  const auto submission = frontend::hint_levels_environment("/course", "/submissions/ada");
  CHECK(submission.first == protocol::kHintsOpenedVariable);
  CHECK(submission.second.empty());
}

TEST_CASE("hint gate: the task of a test is named by its tags", "[hint_gate]") {
  CHECK(testing::task_of_tags("[M01][T2][points=2]") == "M01T2");
  CHECK(testing::task_of_tags("[M08][points=1][T6][hidden]") == "M08T6");
  CHECK(testing::task_of_tags("[M03][points=1]") == "");
  CHECK(testing::task_of_tags("[T2]") == "");
  CHECK(testing::task_of_tags("[Mx][M04][TODO][T10]") == "M04T10");
}

TEST_CASE("a compared field of a test's local result is named as the header names it", "[hint_gate]") {
  CHECK(testing::quantity_label("a.qdd(2)") == "your qdd(2)");
  CHECK(testing::quantity_label("rb.centroid") == "your centroid");
  CHECK(testing::quantity_label("res->q") == "your q");
  CHECK(testing::quantity_label("qdd") == "qdd");
  CHECK(testing::quantity_label("lambda.size()") == "lambda.size()");
  CHECK(testing::quantity_label("MatX(b.Phi)") == "MatX(b.Phi)");
  CHECK(testing::quantity_label("e.") == "e.");
}
