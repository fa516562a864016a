// Module 3, task T4: Lagrange multipliers of driven motions: power balance, closed forms,
// static equilibrium and the refusal of models without a unique answer (visible tests).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "dynamics_checks.hpp"
#include "fmbd/inverse_dynamics.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m03;

GRADED_TEST("lagrange_multipliers slider-crank with gravity and a spring keeps the power balance",
            "[M03][T4][points=2]") {
  // Driver power lambda^T C_t (+ damper power) = d(T + V)/dt along the driven motion, with T and V
  // computed here from q and q_dot and their rate by central differences in time.
  const auto p = slider_crank_parameters(0.1, 0.3, 0.3, 2.0);
  const Model model = sprung_slider_crank(p, 150.0);
  for (double t : {0.2, 0.9, 1.7, 2.6}) {
    check_power_balance(model, slider_crank_at(p, t - 1e-4), t);
  }
  const auto p2 = slider_crank_parameters(0.15, 0.4, -1.0, -3.0);
  const Model damped = sprung_slider_crank(p2, 80.0, 2.5);
  for (double t : {0.1, 0.8}) {
    check_power_balance(damped, slider_crank_at(p2, t - 1e-4), t);
  }
}

GRADED_TEST("lagrange_multipliers driven pendulum pin reaction and motor torque match the closed form",
            "[M03][T4][points=1]") {
  // Uniform rod (m, L) turning about its end at constant w under gravity g. On the rod, the pin
  // force is F = m a_c - m g = -m w^2 L/2 e_r + (0, m g), the motor torque m g L/2 cos(theta).
  struct Case {
    double m, L, g, theta0, w;
  };
  for (const Case& c : {Case{2.0, 0.8, 9.81, 0.3, 1.5}, Case{0.7, 1.3, 9.81, -2.0, -2.5}, Case{5.0, 0.4, 3.7, 1.0, 4.0}}) {
    const Pendulum pen = pendulum(c.m, c.L, c.g, c.theta0, c.w);
    for (double t : {0.0, 0.4, 1.1}) {
      const double theta = pen.theta(t);
      const Vec2 e_r(std::cos(theta), std::sin(theta));
      const VecX q = pen.q(t), qd = pen.qd(t), qdd = pen.qdd(t);
      const VecX lambda = lagrange_multipliers(pen.model, q, qd, qdd, t);
      const std::string hint = lambda_hint(pen.model, q, qd, qdd, t, lambda);
      CAPTURE(c.m, c.L, c.w, t);
      {
        INFO("hint: lambda has one entry per constraint equation (m = 3)");
        REQUIRE(lambda.size() == 3);
      }
      const Vec2 F = -c.m * c.w * c.w * c.L / 2 * e_r + Vec2(0.0, c.m * c.g);
      const double torque = c.m * c.g * c.L / 2 * std::cos(theta);
      // The constraint forces on the rod, Q_c = -C_q^T lambda: pin force through the centroid,
      // moment of the pin force (arm -L/2 e_r) plus the motor torque.
      const VecX Qc = -constraint_jacobian(pen.model, q, t).transpose() * lambda;
      CHECK_CLOSE_NAMED("the pin force -C_q^T lambda of your lambda", Qc.head(2), F, (Tolerance{1e-9, 1e-9}), hint);
      CHECK_NEAR_NAMED("the constraint moment -C_q^T lambda on the rod, of your lambda", Qc(2),
                       torque + cross(-c.L / 2 * e_r, F), (Tolerance{1e-9, 1e-9}), hint);
      // The motor is an absolute-angle driver C = phi - f(t): its torque on the rod is -lambda.
      CHECK_NEAR_NAMED("the motor torque -lambda of your lambda", -lambda(2), torque, (Tolerance{1e-9, 1e-9}), hint);
    }
  }
}

GRADED_TEST("lagrange_multipliers static slider-crank crank torque balances the load", "[M03][T4][points=1]") {
  // Crank held at angle A (drive f constant), a horizontal load P pushing the slider back and
  // gravity. Virtual work: tau dA - P dx - (m_crank + m_rod) g (r/2) cos(A) dA = 0, so the
  // crank torque is tau = P x'(A) + (m_crank + m_rod) g (r/2) cos(A).
  for (double A : {0.4, 1.3, 2.5, 4.0, 5.5}) {
    const auto p = slider_crank_parameters(0.12, 0.35, A, 0.0);
    Model model = examples::slider_crank(p);
    const double g = 9.81, P = 50.0 + 10 * A;
    model.set_gravity(Vec2(0.0, -g));
    model.add_point_force("load", model.find_point("slider C"), Vec2(-P, 0.0));
    const VecX q = slider_crank_at(p, 0.0), zero = VecX::Zero(9);
    const VecX lambda = lagrange_multipliers(model, q, zero, zero, 0.0);
    const std::string hint = lambda_hint(model, q, zero, zero, 0.0, lambda);
    REQUIRE(lambda.size() == 9);
    const double m_crank = model.bodies()[0].mass, m_rod = model.bodies()[1].mass;
    const double tau = P * examples::slider_crank_closed_form(p.r, p.l, A).dx_dA + (m_crank + m_rod) * g * p.r / 2 * std::cos(A);
    const int row = model.constraints()[4].first_row;  // "crank angle": C = phi - f, torque -lambda
    CAPTURE(A, P);
    CHECK_NEAR_NAMED("the crank torque -lambda of your lambda", -lambda(row), tau, (Tolerance{1e-9, 1e-9}), hint);
    CHECK_CLOSE_NAMED("your lambda", lambda, multipliers_of(model, q, zero, zero, 0.0), kSolve, hint);
  }
}

GRADED_TEST("lagrange_multipliers refuses undriven and redundant models", "[M03][T4][points=1]") {
  const std::string hint = with_formula("your lagrange_multipliers must solve with solve_multipliers(model, C_q, rhs): "
                                        "it refuses a model that is not kinematically driven and names redundant rows",
                                        "C_q^T lambda = Q_a - M q_ddot");
  auto p = slider_crank_parameters(0.1, 0.3, 0.5, 2.0);
  p.driven = false;
  const VecX q = slider_crank_at(p, 0.0), zero = VecX::Zero(9);
  // One degree of freedom without a driver: lambda is not determined by the motion.
  const Model undriven = examples::slider_crank(p);
  check_throws_mentioning<std::invalid_argument>([&] { lagrange_multipliers(undriven, q, zero, zero, 0.0); },
                                                 "degree", hint);
  // The slider's angle driven although the guide already fixes it: C_q is square but singular.
  Model redundant = examples::slider_crank(p);
  redundant.add_absolute_angle_driver("slider angle", redundant.find_body("slider"), DriveFunction::constant(0.0));
  bool thrown = false;
  std::vector<int> rows;
  try {
    lagrange_multipliers(redundant, q, zero, zero, 0.0);
  } catch (const SingularJacobianError& e) {
    thrown = true;
    rows = e.rows;
  }
  INFO("hint: " << hint);
  CHECK(thrown);
  if (thrown) {
    // Rows 7 (guide angle) and 8 (slider angle driver) are dependent.
    CHECK(std::find(rows.begin(), rows.end(), 7) != rows.end());
    CHECK(std::find(rows.begin(), rows.end(), 8) != rows.end());
  }
  // Ten equations for nine coordinates.
  auto pd = p;
  pd.driven = true;
  Model over = examples::slider_crank(pd);
  over.add_absolute_angle_driver("slider angle", over.find_body("slider"), DriveFunction::constant(0.0));
  check_throws_mentioning<std::invalid_argument>([&] { lagrange_multipliers(over, q, zero, zero, 0.0); }, "redundant",
                                                 hint);
}
