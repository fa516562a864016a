// Module 4, task T1: forward dynamics on other mechanisms, drivers and seeds (hidden tests).
#include <cmath>

#include "fmbd/constraints.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/forward_dynamics.hpp"
#include "fmbd/gamma.hpp"
#include "grading.hpp"
#include "integration_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m04;

GRADED_TEST("forward_dynamics loaded slider-crank satisfies both rows of the augmented system", "[M04][T1][points=1]") {
  Random rnd(4111);
  examples::SliderCrankParameters p;
  p.r = 0.12;
  p.l = 0.35;
  p.driven = false;
  Model model = examples::slider_crank(p);
  model.set_gravity(Vec2(0.0, -kG));
  const PointId wall = model.add_point(ground, Vec2(0.7, 0.0), "wall");
  const PointId slider = model.add_point(model.find_body("slider"), Vec2::Zero(), "slider spring end");
  model.add_tsda("slider spring", wall, slider, 300.0, 0.25, 4.0, DriveFunction::harmonic(0.0, 5.0, 3.0));
  model.add_torque("motor", model.find_body("crank"), DriveFunction::linear(0.5, 0.2));
  const PointId rod_mid = model.add_point(model.find_body("rod"), Vec2(0.05, 0.01), "rod load point");
  model.add_point_force("load", rod_mid, Vec2(-2.0, 1.0), Frame::body);
  model.add_rsda("crank bearing", ground, model.find_body("crank"), 3.0, 0.2, 0.05);
  for (int k = 0; k < 4; ++k) {
    const double A = rnd.uniform(-kPi, kPi), t = rnd.uniform(0, 2);
    const VecX q = examples::slider_crank_configuration(p, A);
    const MatX N = null_space(constraint_jacobian(model, q, t));
    const VecX qd = N * rnd.vector(N.cols(), -8.0, 8.0);
    CAPTURE(A, t);
    check_augmented_rows(model, q, qd, t);
  }
  // A pendulum hinged off its end, with a motor: the closed form once more.
  for (int k = 0; k < 3; ++k) {
    const Pendulum pend = rod_pendulum(rnd.uniform(0.5, 3), rnd.uniform(0.5, 1.5), rnd.uniform(0.1, 0.4),
                                       rnd.uniform(-4, 4));
    const double phi = rnd.uniform(-kPi, kPi), w = rnd.uniform(-3, 3);
    const Accelerations a = forward_dynamics(pend.model, pend.q(phi), pend.qd(phi, w), 0.3);
    REQUIRE(a.qdd.size() == 3);
    CHECK_NEAR_NAMED("phi_ddot of your q_ddot", a.qdd(2), pend.angular_acceleration(phi), (Tolerance{1e-10, 1e-10}),
                     with_formula("your pendulum with a motor torque differs from its closed form",
                                  "phi_ddot = (T - m g d cos(phi)) / (J + m d^2)"));
  }
}

GRADED_TEST("forward_dynamics Baumgarte on a driven four-bar with other seeds", "[M04][T1][points=1]") {
  Random rnd(4112);
  const auto p = four_bar_parameters(0.12, 0.32, 0.27, 0.33);
  Model model = examples::four_bar(p);
  model.set_gravity(Vec2(0.0, -kG));
  model.add_absolute_angle_driver("crank drive", model.find_body("crank"), DriveFunction::harmonic(0.6, 0.8, 1.7, 0.2));
  for (const Baumgarte b : {Baumgarte{0.0, 0.0}, Baumgarte{7.0, 7.0}, Baumgarte{3.0, 8.0}}) {
    for (int k = 0; k < 2; ++k) {
      const double t = rnd.uniform(0, 2);
      const VecX q = four_bar_q(p, rnd.uniform(-kPi, kPi)) + rnd.vector(9, -0.02, 0.02);
      const VecX qd = rnd.vector(9, -1, 1);
      CAPTURE(b.alpha, b.beta, t);
      const Accelerations a = forward_dynamics(model, q, qd, t, b);
      REQUIRE(a.qdd.size() == 9);
      const ConstraintEvaluation e = evaluate_constraints(model, q, t);
      const VecX expected =
          constraint_gamma(model, q, qd, t) - 2 * b.alpha * (e.Cq * qd + e.Ct) - b.beta * b.beta * e.C;
      CHECK_CLOSE_NAMED("C_q q_ddot of your q_ddot", VecX(e.Cq * a.qdd), expected, (Tolerance{1e-8, 1e-8}),
                        with_formula("your q_ddot does not solve the bottom row with Baumgarte stabilisation: check "
                                     "the signs, beta squared and C_t in C_dot",
                                     "C_q q_ddot = gamma - 2 alpha C_dot - beta^2 C, C_dot = C_q q_dot + C_t"));
    }
  }
}
