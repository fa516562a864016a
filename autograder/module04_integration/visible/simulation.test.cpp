// Module 4, tasks T1-T4 through simulate() (given code): convergence order on a pendulum,
// energy conservation, the period of a large swing, and constraint drift (visible tests).
// The oracles: the pendulum's minimal-coordinate ODE integrated by the test itself, the
// elliptic-integral period, the energy T + V written out, and |C| from module 1.
#include <cmath>
#include <limits>
#include <string>

#include "fmbd/constraints.hpp"
#include "fmbd/simulation.hpp"
#include "grading.hpp"
#include "integration_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m04;

namespace {

SimulationOptions fixed_step(Integrator integrator, double h, Stabilisation stabilisation = Stabilisation::none) {
  SimulationOptions o;
  o.integrator = integrator;
  o.step = h;
  o.stabilisation = stabilisation;
  o.drift_limit = std::numeric_limits<double>::infinity();  // these tests measure the drift themselves
  return o;
}

// Largest |E(t) - E(0)| along a run, with the energy written out.
double energy_error(const Model& model, const Trajectory& s) {
  if (s.q.empty()) return 0.0;
  const double E0 = gravity_energy_of(model, s.q.front(), s.qd.front());
  double worst = 0;
  for (std::size_t i = 0; i < s.q.size(); ++i)
    worst = std::max(worst, std::abs(gravity_energy_of(model, s.q[i], s.qd[i]) - E0));
  return worst;
}

// Largest |C(q(t))| over the points with t in [from, to], from module 1's C.
double drift(const Model& model, const Trajectory& s, double from, double to) {
  double worst = 0;
  for (std::size_t i = 0; i < s.t.size(); ++i)
    if (s.t[i] >= from && s.t[i] <= to) worst = std::max(worst, constraints(model, s.q[i], s.t[i]).norm());
  return worst;
}

}  // namespace

// ---- T2 -------------------------------------------------------------------------------------

GRADED_TEST("simulate euler and rk4 rod pendulum angle converges with order 1 and 4", "[M04][T2][points=1]") {
  const Pendulum p = rod_pendulum(1.0, 1.0, 0.5);
  const double phi0 = 0.4, w0 = 1.0, t_end = 2.0;
  const VecX q0 = p.q(phi0), qd0 = p.qd(phi0, w0);
  const double exact = pendulum_reference(p, phi0, w0, t_end)(0);
  auto error = [&](Integrator integrator, double h) {
    const Trajectory s = simulate(p.model, q0, qd0, 0.0, t_end, fixed_step(integrator, h));
    return std::abs(s.q.back()(2) - exact);
  };
  const double e1 = error(Integrator::euler, 1e-3), e2 = error(Integrator::euler, 5e-4);
  CAPTURE(e1, e2, ratio(e1, e2));
  CHECK_NEAR_NAMED(
      "your Euler error of phi(t_end) with h = 1e-3 s over that with 5e-4 s", ratio(e1, e2), 2.0, (Tolerance{0.3, 0}),
      "Euler on the pendulum: halving h must halve the error of phi(t_end) (order 1); if the T1 tests fail, "
      "fix forward_dynamics first");
  const double r1 = error(Integrator::rk4, 0.02), r2 = error(Integrator::rk4, 0.01);
  CAPTURE(r1, r2, ratio(r1, r2));
  CHECK_NEAR_NAMED("your RK4 error of phi(t_end) with h = 0.02 s over that with 0.01 s", ratio(r1, r2), 16.0,
                   (Tolerance{4.0, 0}),
                   "RK4 on the pendulum: halving h must divide the error of phi(t_end) by about 16 (order 4)");
  CHECK_NEAR_NAMED("your RK4 error of phi(t_end) with h = 0.01 s", r2, 0.0, (Tolerance{1e-6, 0}),
                   "RK4 with h = 0.01 s must follow the pendulum to about 1e-7 rad");
}

GRADED_TEST("simulate rk4 double pendulum conserves energy with order 4", "[M04][T2][points=1]") {
  const DoublePendulum dp = double_pendulum(1.0, 1.0, 0.6, 0.7);
  const VecX q0 = dp.q(-0.6, 0.3), qd0 = dp.qd(-0.6, 0.3, 0.0, 0.0);
  auto run = [&](double h) {
    return energy_error(dp.model, simulate(dp.model, q0, qd0, 0.0, 2.0, fixed_step(Integrator::rk4, h)));
  };
  const double e1 = run(0.02), e2 = run(0.01), e3 = run(0.005);
  CAPTURE(e1, e2, e3, ratio(e1, e2), ratio(e2, e3));
  const std::string hint =
      "RK4 must conserve the energy of the double pendulum up to O(h^4): halving h divides |E(t) - E(0)| by about 16 "
      "(if the T1 tests fail, fix forward_dynamics first)";
  CHECK_NEAR_NAMED("your RK4 energy error with h = 0.02 s over that with 0.01 s", ratio(e1, e2), 16.0,
                   (Tolerance{5.0, 0}), hint);
  CHECK_NEAR_NAMED("your RK4 energy error with h = 0.01 s over that with 0.005 s", ratio(e2, e3), 16.0,
                   (Tolerance{5.0, 0}), hint);
  CHECK_NEAR_NAMED("your RK4 energy error with h = 0.005 s", e3, 0.0, (Tolerance{2e-5, 0}), hint);
}

// ---- T3 -------------------------------------------------------------------------------------

GRADED_TEST("simulate dormand_prince rod hinged at one end released from horizontal has the elliptic period",
            "[M04][T3][points=2]") {
  const double L = 1.0;
  const Pendulum p = rod_pendulum(1.0, L, L / 2);
  // Released at rest from phi = 0, it swings through phi = -pi/2 with amplitude pi/2 about it.
  const double period = 4 * std::sqrt(2 * L / (3 * kG)) * elliptic_K(std::sin(kPi / 4));
  const double tolerance = 1e-6 * period;
  CHECK_NEAR(period, pendulum_period(p, kPi / 2), (Tolerance{1e-12, 1e-12}), "test oracle");
  CHECK(std::abs(period - small_angle_period(p)) > 1e4 * tolerance);  // a large swing, not a small one
  SimulationOptions o;
  o.integrator = Integrator::dormand_prince;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  o.step = 1e-3;
  o.max_step = 0.02;
  const Trajectory s = simulate(p.model, p.q(0.0), p.qd(0.0, 0.0), 0.0, 1.3 * period, o);
  const std::vector<double> bottom = crossing_times(s, 2, -kPi / 2);
  CAPTURE(period, small_angle_period(p), s.steps, s.rejected_steps, bottom.size());
  const std::string hint =
      with_formula("your simulated rod, released from horizontal, must pass the bottom at T/4, 3T/4 and 5T/4 of its "
                   "elliptic period T: check dormand_prince_step (and forward_dynamics if the T1 tests fail)",
                   "T = 4 sqrt(2L/(3g)) K(sin(pi/4))");
  {
    INFO("hint: " << hint);
    REQUIRE(bottom.size() >= 3);
  }
  CHECK_NEAR_NAMED("the time your rod first passes the bottom", bottom[0], period / 4, (Tolerance{tolerance, 0}), hint);
  CHECK_NEAR_NAMED("the period of your rod's swing", bottom[2] - bottom[0], period, (Tolerance{tolerance, 0}), hint);
  CHECK_NEAR_NAMED("your rod's angle at t_end", s.q.back()(2), pendulum_reference(p, 0.0, 0.0, s.t.back())(0),
                   (Tolerance{1e-7, 0}), hint);
}

GRADED_TEST("simulate dormand_prince tighter rtol gives a smaller energy error", "[M04][T3][points=1]") {
  const Pendulum p = rod_pendulum(1.0, 1.0, 0.5);
  auto run = [&](double rtol) {
    SimulationOptions o;
    o.integrator = Integrator::dormand_prince;
    o.rtol = rtol;
    o.atol = 1e-3 * rtol;
    o.step = 1e-3;
    o.max_step = 3.0;  // the run's length: the error estimate alone sets every step
    return simulate(p.model, p.q(0.0), p.qd(0.0, 0.0), 0.0, 3.0, o);
  };
  const Trajectory loose = run(1e-4), tight = run(1e-8);
  const double e_loose = energy_error(p.model, loose), e_tight = energy_error(p.model, tight);
  CAPTURE(e_loose, e_tight, loose.steps, tight.steps, loose.rejected_steps, tight.rejected_steps);
  const std::string hint =
      with_formula("your simulation with a tighter rtol must take more, smaller steps and have a smaller energy "
                   "error: the step control needs the error estimate (if the T1 tests fail, fix forward_dynamics "
                   "first)", "error = y5 - y4 = h sum_s (b_s - b_hat_s) k_s");
  CHECK(tight.steps > 2 * loose.steps);
  CHECK_NEAR_NAMED("your energy error at the tight rtol over that at the loose one", e_tight / e_loose, 0.0,
                   (Tolerance{0.02, 0}), hint);
  CHECK_NEAR_NAMED("your energy error at the tight rtol", e_tight, 0.0, (Tolerance{1e-6, 0}), hint);
}

// ---- T4 and T1 (Baumgarte): constraint drift --------------------------------------------------

GRADED_TEST("simulate double pendulum constraint drift grows without stabilisation and vanishes with projection",
            "[M04][T4][points=1]") {
  const DoublePendulum dp = double_pendulum(1.0, 0.8, 0.5, 0.6);
  const VecX q0 = dp.q(-0.3, 0.5), qd0 = dp.qd(-0.3, 0.5, 1.0, -1.0);
  const Trajectory none = simulate(dp.model, q0, qd0, 0.0, 6.0, fixed_step(Integrator::rk4, 0.02));
  const double early = drift(dp.model, none, 0.0, 0.5), late = drift(dp.model, none, 3.0, 6.0);
  CAPTURE(early, late);
  CHECK(late > 1e-6);
  CHECK(late > 5 * early);
  const Trajectory projected =
      simulate(dp.model, q0, qd0, 0.0, 6.0, fixed_step(Integrator::rk4, 0.02, Stabilisation::projection));
  const double projected_drift = drift(dp.model, projected, 0.0, 6.0);
  double velocity_drift = 0;
  for (std::size_t i = 0; i < projected.q.size(); ++i) {
    const ConstraintEvaluation e = evaluate_constraints(dp.model, projected.q[i], projected.t[i]);
    velocity_drift = std::max(velocity_drift, (e.Cq * projected.qd[i] + e.Ct).norm());
  }
  CAPTURE(projected_drift, velocity_drift);
  CHECK_NEAR_NAMED("your largest |C| after a projected step", projected_drift, 0.0, (Tolerance{1e-9, 0}),
                   with_formula("your project_positions must bring |C| below its tolerance after every step (Newton "
                                "iterations until |C| <= tolerance)",
                                "[M C_q^T; C_q 0] (dq; mu) = (0; -C)"));
  CHECK_NEAR_NAMED("your largest velocity-equation residual after a projected step", velocity_drift, 0.0,
                   (Tolerance{1e-9, 0}),
                   with_formula("your project_velocities must satisfy the velocity equation after every step (the "
                                "constraints' rate is zero)",
                                "C_q q_dot + C_t = 0"));
}

GRADED_TEST("simulate Baumgarte keeps the double pendulum constraint drift bounded, far below the drift without stabilisation",
            "[M04][T1][points=1]") {
  const DoublePendulum dp = double_pendulum(1.0, 0.8, 0.5, 0.6);
  const VecX q0 = dp.q(-0.3, 0.5), qd0 = dp.qd(-0.3, 0.5, 1.0, -1.0);
  const Trajectory none = simulate(dp.model, q0, qd0, 0.0, 6.0, fixed_step(Integrator::rk4, 0.01));
  SimulationOptions o = fixed_step(Integrator::rk4, 0.01, Stabilisation::baumgarte);
  o.baumgarte = Baumgarte{10.0, 10.0};
  const Trajectory stabilised = simulate(dp.model, q0, qd0, 0.0, 6.0, o);
  const double d_none = drift(dp.model, none, 0.0, 6.0), d_first = drift(dp.model, stabilised, 0.0, 3.0),
               d_second = drift(dp.model, stabilised, 3.0, 6.0);
  CAPTURE(d_none, d_first, d_second);
  const std::string hint =
      with_formula("your Baumgarte terms do not pull C back to zero (check the minus signs, beta squared and C_t in "
                   "C_dot); this run uses RK4: if the T2 tests fail, fix rk4_step first",
                   "the bottom row is gamma - 2 alpha C_dot - beta^2 C, C_dot = C_q q_dot + C_t");
  CHECK_NEAR_NAMED("your Baumgarte drift over the drift without stabilisation", std::max(d_first, d_second) / d_none,
                   0.0, (Tolerance{0.05, 0}), hint);
  CHECK_NEAR_NAMED("your Baumgarte drift in the second half of the run", d_second, 0.0,
                   (Tolerance{5 * d_first + 1e-12, 0}), hint);
}
