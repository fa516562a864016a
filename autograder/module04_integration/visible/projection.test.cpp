// Module 4, task T4: coordinate projection of positions and velocities (visible tests).
// The oracles: C and C_q of module 1, M written out, the null space of C_q by SVD, and other
// feasible points found by the test's own Gauss-Newton iterations.
#include <cmath>
#include <string>

#include "fmbd/examples.hpp"
#include "fmbd/projection.hpp"
#include "grading.hpp"
#include "integration_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m04;

GRADED_TEST("project_positions restores C = 0 with the minimum mass-weighted correction", "[M04][T4][points=2]") {
  Random rnd(4401);
  const auto p = four_bar_parameters(0.1, 0.3, 0.25, 0.3);
  const Model four_bar = examples::four_bar(p);
  for (int k = 0; k < 3; ++k) {
    const double theta = rnd.uniform(-kPi, kPi);
    CAPTURE(theta);
    check_position_projection(four_bar, four_bar_q(p, theta), 0.0, rnd);
  }
  const DoublePendulum dp = double_pendulum(2.0, 0.9, 0.4, 0.5);
  for (int k = 0; k < 2; ++k) {
    const double phi1 = rnd.uniform(-kPi, kPi), phi2 = rnd.uniform(-kPi, kPi);
    CAPTURE(phi1, phi2);
    check_position_projection(dp.model, dp.q(phi1, phi2), 0.0, rnd);
  }
  // A large offset needs several Newton iterations.
  const VecX q_far = four_bar_q(p, 0.8) + rnd.vector(9, -0.03, 0.03);
  const VecX q_proj = project_positions(four_bar, q_far, 0.0);
  CHECK_CLOSE_NAMED("C at your projected q", constraints(four_bar, q_proj, 0.0), VecX::Zero(8), (Tolerance{1e-9, 0}),
                    "project_positions must iterate until |C| <= options.tolerance, re-evaluating C and C_q each time");
}

GRADED_TEST("project_velocities satisfies the velocity equation with the minimum mass-weighted correction",
            "[M04][T4][points=1]") {
  Random rnd(4402);
  DoublePendulum dp = double_pendulum(1.5, 0.9, 0.4, 0.5);
  // A relative-angle driver: C_t is not zero and one degree of freedom remains.
  const DriveFunction f = DriveFunction::harmonic(0.4, 0.5, 1.5, 0.3);
  dp.model.add_relative_angle_driver("elbow drive", dp.model.find_body("upper rod"), dp.model.find_body("lower rod"),
                                     f);
  for (int k = 0; k < 3; ++k) {
    const double t = rnd.uniform(0, 3), phi1 = rnd.uniform(-kPi, kPi);
    const VecX q = dp.q(phi1, phi1 + f(t).f);
    const VecX qd = rnd.vector(6, -2, 2);
    CAPTURE(t, phi1);
    check_velocity_projection(dp.model, q, qd, t);
  }
}
