// Module 2, tasks T2 and T5: velocities and accelerations on other mechanisms (hidden tests).
#include <cmath>

#include "fmbd/constraints.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/kinematic_analysis.hpp"
#include "grading.hpp"
#include "kinematic_checks.hpp"
#include "kinematic_hidden_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m02;

namespace {

ArmCollar hidden_arm_collar() {
  return arm_collar(0.25, DriveFunction::harmonic(0.22, 0.12, 1.7, 0.2),
                    DriveFunction::harmonic(0.3, 0.1, 2.3, 1.1));
}

}  // namespace

GRADED_TEST("solve_velocities arm and collar matches the closed form", "[M02][T2][points=1]") {
  const ArmCollar ac = hidden_arm_collar();
  auto exact = [&](double s) { return ac.exact(s); };
  for (double t : {0.1, 0.9, 2.2, 3.0}) {
    const VecX q = exact(t);
    const VecX qd = solve_velocities(ac.model, q, t);
    const VecX expected = path_rate(exact, t);
    CAPTURE(t);
    CHECK_CLOSE_NAMED("your q_dot", qd, expected, (Tolerance{1e-7, 1e-7}), velocity_hint(qd, expected));
  }
}

GRADED_TEST("solve_accelerations arm and collar with harmonic drivers matches the closed form", "[M02][T5][points=1]") {
  const ArmCollar ac = hidden_arm_collar();
  auto exact = [&](double s) { return ac.exact(s); };
  for (double t : {0.1, 0.9, 2.2, 3.0}) {
    const VecX q = exact(t), qd = path_rate(exact, t);
    const VecX qdd = solve_accelerations(ac.model, q, qd, t);
    const VecX expected = path_acceleration(exact, t);
    CAPTURE(t);
    CHECK_CLOSE_NAMED("your q_ddot", qdd, expected, (Tolerance{1e-5, 1e-5}),
                      acceleration_hint(ac.model, q, qd, t, qdd, expected) +
                          "; this model has a translational joint on a turning body (Coriolis term), a "
                          "point-coordinate and a distance driver (two drive terms in its gamma)");
  }
}

GRADED_TEST("solve_accelerations four-bar with other lengths matches differences of velocities",
            "[M02][T5][points=1]") {
  const auto p = four_bar_parameters(0.12, 0.35, 0.3, 0.38, 2.2, -1.7);
  const Model model = examples::four_bar(p);
  auto exact = [&](double s) { return four_bar_configuration(p, p.theta0 + p.omega * s); };
  for (double t : {0.2, 1.3, 2.9}) {
    const VecX q = exact(t), qd = path_rate(exact, t);
    const VecX qdd = solve_accelerations(model, q, qd, t);
    const VecX expected = path_acceleration(exact, t);
    CAPTURE(t);
    const std::string hint = acceleration_hint(model, q, qd, t, qdd, expected);
    CHECK_CLOSE_NAMED("your q_ddot", qdd, expected, (Tolerance{1e-5, 1e-5}), hint);
    // Consistency with the velocity solution: q_ddot = d/dt q_dot(q(t), t).
    const double h = 1e-5;
    const VecX rate = (solve_velocities(model, exact(t + h), t + h) - solve_velocities(model, exact(t - h), t - h)) / (2 * h);
    CHECK_CLOSE_NAMED("your q_ddot", qdd, rate, (Tolerance{1e-5, 1e-5}), hint);
  }
}
