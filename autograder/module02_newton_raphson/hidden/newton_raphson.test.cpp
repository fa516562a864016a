// Module 2, task T1: Newton-Raphson on other geometry (hidden tests).
#include <cmath>

#include "fmbd/constraints.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/newton_raphson.hpp"
#include "grading.hpp"
#include "kinematic_checks.hpp"
#include "kinematic_hidden_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m02;

GRADED_TEST("newton_raphson slider-crank with other dimensions matches the closed form", "[M02][T1][points=1]") {
  const auto p = slider_crank_parameters(0.25, 0.6, 2.0, -1.5);
  const Model model = examples::slider_crank(p);
  Random rnd(1201);
  for (double t : {0.15, 1.4, 3.3}) {
    const double A = p.A0 + p.omega * t;
    const VecX exact = slider_crank_exact(p, A);
    const VecX guess = exact + rnd.vector(9, -0.04, 0.04);
    const auto result = newton_or_fail(model, guess, t);
    if (!result) continue;
    CAPTURE(t, A);
    CHECK_CLOSE_NAMED("C at your q", constraints(model, result->q, t), VecX::Zero(9), (Tolerance{1e-9, 0}),
                      "your q does not satisfy C(q, t) = 0");
    CHECK_CLOSE_NAMED("your q", result->q, align_angles(exact, result->q), (Tolerance{1e-8, 1e-8}),
                      with_formula("your q is not the assembled slider-crank", "C_q dq = -C, then q += dq"));
    INFO("hint: result.residuals holds |C| before each step and at the end: iterations + 1 entries");
    CHECK(result->residuals.size() == static_cast<std::size_t>(result->iterations) + 1);
  }
}

GRADED_TEST("newton_raphson four-bar with other lengths closes the loop", "[M02][T1][points=1]") {
  const auto p = four_bar_parameters(0.15, 0.4, 0.35, 0.45, 1.2, 0.8);
  const Model model = examples::four_bar(p);
  Random rnd(1202);
  for (double t : {0.0, 2.0, 5.5}) {
    const double theta = p.theta0 + p.omega * t;
    const VecX exact = four_bar_configuration(p, theta);
    const VecX guess = exact + rnd.vector(9, -0.03, 0.03);
    const auto result = newton_or_fail(model, guess, t);
    if (!result) continue;
    const VecX& q = result->q;
    CAPTURE(t, theta);
    const std::string hint = with_formula("your q does not satisfy C(q, t) = 0: iterate Newton steps", "C_q dq = -C, then q += dq");
    CHECK_CLOSE_NAMED("the four-bar's loop closure at your q", four_bar_closure(p, q), VecX::Zero(8),
                      (Tolerance{1e-9, 0}), hint);
    CHECK_NEAR_NAMED("your crank angle minus the driven angle", std::remainder(q(2) - theta, 2 * kPi), 0.0,
                     (Tolerance{1e-9, 0}), hint);
    CHECK_CLOSE_NAMED("your q", q, align_angles(exact, q), (Tolerance{1e-8, 1e-8}), hint);
  }
}

GRADED_TEST("newton_raphson arm and collar with distance and point-coordinate drivers", "[M02][T1][points=1]") {
  const ArmCollar ac = arm_collar(0.2, DriveFunction::harmonic(0.2, 0.1, 1.5, 0.4),
                                  DriveFunction::harmonic(0.25, 0.08, 2.0, 0.3));
  Random rnd(1203);
  for (double t : {0.3, 1.7, 2.9}) {
    const VecX exact = ac.exact(t);
    const VecX guess = exact + rnd.vector(6, -0.03, 0.03);
    const auto result = newton_or_fail(ac.model, guess, t);
    if (!result) continue;
    CAPTURE(t);
    CHECK_CLOSE_NAMED("C at your q", constraints(ac.model, result->q, t), VecX::Zero(6), (Tolerance{1e-9, 0}),
                      "your q does not satisfy C(q, t) = 0 for every joint and driver");
    CHECK_CLOSE_NAMED("your q", result->q, align_angles(exact, result->q), (Tolerance{1e-8, 1e-8}),
                      with_formula("your q is not the assembled arm and collar", "C_q dq = -C, then q += dq"));
  }
}
