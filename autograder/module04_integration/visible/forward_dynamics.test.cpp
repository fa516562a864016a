// Module 4, task T1: forward dynamics from the augmented system, eq. (3) (visible tests).
// The oracles: the two rows of eq. (3) with M written out and C_q, gamma, Q_a from modules 1-3,
// closed forms of a free body and of a rod pendulum, and inverse dynamics (module 3).
#include <cmath>
#include <string>

#include "fmbd/applied_forces.hpp"
#include "fmbd/constraints.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/forward_dynamics.hpp"
#include "fmbd/gamma.hpp"
#include "fmbd/inverse_dynamics.hpp"
#include "fmbd/reactions.hpp"
#include "grading.hpp"
#include "integration_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m04;

namespace {

// The undriven four-bar of examples.hpp with gravity, a spring-damper from the ground to the
// coupler, a harmonic torque on the crank and a follower force on the rocker.
Model loaded_four_bar(const examples::FourBarParameters& p) {
  Model model = examples::four_bar(p);
  model.set_gravity(Vec2(0.0, -kG));
  const PointId anchor = model.add_point(ground, Vec2(0.12, 0.45), "spring anchor");
  const PointId coupler_mid = model.add_point(model.find_body("coupler"), Vec2(0.02, 0.01), "coupler spring end");
  model.add_tsda("coupler spring", anchor, coupler_mid, 150.0, 0.15, 2.5);
  model.add_torque("motor", model.find_body("crank"), DriveFunction::harmonic(0.4, 0.3, 2.0, 0.5));
  const PointId tip = model.add_point(model.find_body("rocker"), Vec2(0.05, 0.02), "rocker tip");
  model.add_point_force("follower", tip, Vec2(1.5, -0.7), Frame::body);
  return model;
}

}  // namespace

// ---- T1 -------------------------------------------------------------------------------------

GRADED_TEST("forward_dynamics loaded four-bar satisfies both rows of the augmented system", "[M04][T1][points=2]") {
  Random rnd(4101);
  const auto p = four_bar_parameters(0.1, 0.3, 0.25, 0.3);
  const Model model = loaded_four_bar(p);
  for (int k = 0; k < 4; ++k) {
    const double theta = rnd.uniform(-kPi, kPi), t = rnd.uniform(0.0, 3.0);
    const VecX q = four_bar_q(p, theta);
    // Velocities tangent to the constraints, so the state is consistent.
    const MatX N = null_space(constraint_jacobian(model, q, t));
    const VecX qd = N * rnd.vector(N.cols(), 2.0, 6.0);
    CAPTURE(theta, t);
    check_augmented_rows(model, q, qd, t);
  }
}

GRADED_TEST("forward_dynamics free bodies fall with g and do not rotate", "[M04][T1][points=1]") {
  Random rnd(4102);
  Model model;
  const Vec2 g(0.8, -kG);
  model.set_gravity(g);
  model.add_body("light", 0.4, 0.02);
  model.add_body("heavy", 7.5, 1.3);
  const VecX q = rnd.vector(6, -1, 1), qd = rnd.vector(6, -3, 3);
  const Accelerations a = forward_dynamics(model, q, qd, 0.7);
  CHECK(a.lambda.size() == 0);
  const VecX expected = vec({g.x(), g.y(), 0.0, g.x(), g.y(), 0.0});
  CHECK_CLOSE_NAMED("your q_ddot", a.qdd, expected, (Tolerance{1e-12, 1e-12}),
                    diagnose(a.qdd, expected,
                             {{"your q_ddot is Q_a itself: solve with M = mass_matrix(model, q) (solve_augmented)",
                               vec({0.4 * g.x(), 0.4 * g.y(), 0, 7.5 * g.x(), 7.5 * g.y(), 0})}},
                             "your free bodies do not fall with g: a body without joints falls with gravity's "
                             "acceleration and does not turn, whatever its mass (with no constraints C_q is 0 x n "
                             "and lambda is empty)",
                             Tolerance{1e-9, 1e-9}));
}

GRADED_TEST("forward_dynamics rod pendulum angular acceleration matches the closed form", "[M04][T1][points=1]") {
  Random rnd(4103);
  for (const Pendulum& p : {rod_pendulum(1.0, 1.0, 0.5), rod_pendulum(2.3, 0.8, 0.25), rod_pendulum(0.6, 1.4, 0.55)}) {
    for (int k = 0; k < 3; ++k) {
      const double phi = rnd.uniform(-kPi, kPi), w = rnd.uniform(-3, 3), t = rnd.uniform(0, 2);
      const VecX q = p.q(phi), qd = p.qd(phi, w);
      const Accelerations a = forward_dynamics(p.model, q, qd, t);
      CAPTURE(p.mass, p.length, p.hinge, phi, w);
      REQUIRE(a.qdd.size() == 3);
      const double expected = p.angular_acceleration(phi);
      CHECK_NEAR_NAMED("phi_ddot of your q_ddot", a.qdd(2), expected, (Tolerance{1e-10, 1e-10}),
                       with_formula("your rod pendulum's phi_ddot differs from its closed form: solve (3) with M = "
                                    "mass_matrix, Q_a = applied_forces and gamma = constraint_gamma",
                                    "phi_ddot = -m g d cos(phi) / (J + m d^2)"));
      CHECK_CLOSE_NAMED("the centroid's acceleration in your q_ddot", Vec2(a.qdd.head<2>()),
                        p.centroid_acceleration(phi, w), (Tolerance{1e-10, 1e-10}),
                        with_formula("your rod's centroid does not move on a circle about the hinge: a missing "
                                     "centripetal part means gamma is missing from the bottom row",
                                     "a = d (phi_ddot I~ u - phi_dot^2 u)"));
    }
  }
}

GRADED_TEST("forward_dynamics pendulum with a motor torque round trip through inverse dynamics",
            "[M04][T1][points=1]") {
  Random rnd(4104);
  for (int k = 0; k < 3; ++k) {
    const double T = rnd.uniform(-6, 6), phi = rnd.uniform(-kPi, kPi), w = rnd.uniform(-2, 2), t = rnd.uniform(0, 1);
    const Pendulum motor = rod_pendulum(1.7, 0.9, 0.45, T);
    const VecX q = motor.q(phi), qd = motor.qd(phi, w);
    CAPTURE(T, phi, w);
    const Accelerations a = forward_dynamics(motor.model, q, qd, t);
    REQUIRE(a.qdd.size() == 3);
    CHECK_NEAR_NAMED("phi_ddot of your q_ddot", a.qdd(2), motor.angular_acceleration(phi), (Tolerance{1e-10, 1e-10}),
                     with_formula("your pendulum ignores the motor torque T: it enters Q_a",
                                  "I_O phi_ddot = T - m g d cos(phi)"));
    // The same motion prescribed by a driver: inverse dynamics must need exactly the torque T.
    Pendulum driven = rod_pendulum(1.7, 0.9, 0.45);
    const double phi_ddot = a.qdd(2);
    const int driver = driven.model.add_absolute_angle_driver(
        "rod angle", driven.model.find_body("rod"),
        DriveFunction::custom([=](double) { return DriveValue{phi, w, phi_ddot}; }, "the forward-dynamics motion"));
    const VecX lambda = lagrange_multipliers(driven.model, q, qd, a.qdd, t);
    CHECK_NEAR_NAMED(
        "the driver torque of your lambda", driver_effort(driven.model, driver, q, lambda), T, (Tolerance{1e-9, 1e-9}),
        "your q_ddot does not give back the motor torque through inverse dynamics: it must solve both rows "
        "of (3)");
  }
}

GRADED_TEST("forward_dynamics Baumgarte terms in the bottom row", "[M04][T1][points=1]") {
  Random rnd(4105);
  DoublePendulum dp = double_pendulum(1.2, 0.8, 0.7, 0.6);
  // A relative-angle driver makes C_t non-zero, so C_dot = C_q q_dot + C_t.
  dp.model.add_relative_angle_driver("elbow drive", dp.model.find_body("upper rod"), dp.model.find_body("lower rod"),
                                     DriveFunction::harmonic(0.5, 0.3, 2.0, 0.4));
  const Model& model = dp.model;
  for (const Baumgarte b : {Baumgarte{4.0, 4.0}, Baumgarte{2.5, 6.0}}) {
    for (int k = 0; k < 2; ++k) {
      const double t = rnd.uniform(0, 2);
      // A state that violates C and C_dot.
      const VecX q = dp.q(rnd.uniform(-2, 0), rnd.uniform(-2, 0)) + rnd.vector(6, -0.03, 0.03);
      const VecX qd = rnd.vector(6, -2, 2);
      const Accelerations a = forward_dynamics(model, q, qd, t, b);
      REQUIRE(a.qdd.size() == 6);
      const ConstraintEvaluation e = evaluate_constraints(model, q, t);
      const VecX gamma = constraint_gamma(model, q, qd, t);
      const VecX C_dot = e.Cq * qd + e.Ct, Cq_qd = e.Cq * qd;
      const VecX expected = gamma - 2 * b.alpha * C_dot - b.beta * b.beta * e.C;
      const VecX actual = e.Cq * a.qdd;
      CAPTURE(b.alpha, b.beta, t);
      const Tolerance tol{1e-8, 1e-8};
      const char* row = "C_q q_ddot = gamma - 2 alpha C_dot - beta^2 C, C_dot = C_q q_dot + C_t";
      auto named = [row](const char* words) { return with_formula(words, row); };
      CHECK_CLOSE_NAMED(
          "C_q q_ddot of your q_ddot", actual, expected, tol,
          diagnose(actual, expected,
                   {{named("your bottom row: Baumgarte terms missing"), gamma},
                    {named("your (3) with Baumgarte: the bottom row needs gamma = constraint_gamma()"),
                     VecX(-2 * b.alpha * C_dot - b.beta * b.beta * e.C)},
                    {named("your bottom row: Baumgarte sign of the C_dot term"),
                     gamma + 2 * b.alpha * C_dot - b.beta * b.beta * e.C},
                    {named("your bottom row: Baumgarte sign of the C term"),
                     gamma - 2 * b.alpha * C_dot + b.beta * b.beta * e.C},
                    {named("your bottom row: Baumgarte signs of both terms"),
                     gamma + 2 * b.alpha * C_dot + b.beta * b.beta * e.C},
                    {named("your bottom row: Baumgarte beta is not squared"), gamma - 2 * b.alpha * C_dot - b.beta * e.C},
                    {named("your bottom row: Baumgarte factor 2 of the C_dot term missing"),
                     gamma - b.alpha * C_dot - b.beta * b.beta * e.C},
                    {named("your bottom row: Baumgarte alpha and beta swapped"),
                     gamma - 2 * b.beta * C_dot - b.alpha * b.alpha * e.C},
                    {named("your Baumgarte C_dot leaves out C_t (drivers depend on time)"),
                     gamma - 2 * b.alpha * Cq_qd - b.beta * b.beta * e.C}},
                   named("your q_ddot does not solve the bottom row with Baumgarte stabilisation"), tol));
      // The top row does not change.
      CHECK_CLOSE_NAMED("M q_ddot + C_q^T lambda of your q_ddot and lambda",
                        VecX(mass_matrix_of(model) * a.qdd + e.Cq.transpose() * a.lambda),
                        applied_forces(model, q, qd, t), tol,
                        "your top row changed with Baumgarte: Baumgarte changes only the bottom row");
    }
  }
}
