// Module 4, tasks T2-T4 through simulate(): other geometries, amplitudes and a rough start
// (hidden tests).
#include <cmath>
#include <string>

#include "fmbd/constraints.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/projection.hpp"
#include "fmbd/simulation.hpp"
#include "grading.hpp"
#include "integration_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m04;

namespace {

double energy_error(const Model& model, const Trajectory& s) {
  if (s.q.empty()) return 0.0;
  const double E0 = gravity_energy_of(model, s.q.front(), s.qd.front());
  double worst = 0;
  for (std::size_t i = 0; i < s.q.size(); ++i)
    worst = std::max(worst, std::abs(gravity_energy_of(model, s.q[i], s.qd[i]) - E0));
  return worst;
}

}  // namespace

GRADED_TEST("simulate rk4 double pendulum with other rods conserves energy with order 4", "[M04][T2][points=1]") {
  const DoublePendulum dp = double_pendulum(2.0, 0.6, 1.0, 0.9);
  const VecX q0 = dp.q(-2.0, -1.2), qd0 = dp.qd(-2.0, -1.2, 0.5, -0.8);
  auto run = [&](double h) {
    SimulationOptions o;
    o.integrator = Integrator::rk4;
    o.step = h;
    return energy_error(dp.model, simulate(dp.model, q0, qd0, 0.0, 2.5, o));
  };
  const double e1 = run(0.02), e2 = run(0.01), e3 = run(0.005);
  CAPTURE(e1, e2, e3, ratio(e1, e2), ratio(e2, e3));
  const char* hint =
      "RK4 conserves the energy up to O(h^4): halving h divides |E(t) - E(0)| by about 16 (if the T1 tests fail, fix "
      "forward_dynamics first)";
  CHECK_NEAR_NAMED("your RK4 energy error with h = 0.01 s over that with 0.005 s", ratio(e2, e3), 16.0,
                   (Tolerance{5.0, 0}), hint);
  CHECK_NEAR_NAMED("your RK4 energy error with h = 0.005 s", e3, 0.0, (Tolerance{2e-5, 0}), hint);
}

GRADED_TEST("simulate dormand_prince rod hinged off its end released 60 degrees from hanging has the elliptic period",
            "[M04][T3][points=1]") {
  const Pendulum p = rod_pendulum(2.0, 1.2, 0.3);
  const double amplitude = kPi / 3, phi0 = -kPi / 2 + amplitude;
  const double period = pendulum_period(p, amplitude), tolerance = 1e-6 * period;
  CHECK(std::abs(period - small_angle_period(p)) > 1e3 * tolerance);
  SimulationOptions o;
  o.integrator = Integrator::dormand_prince;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  o.max_step = 0.02;
  const Trajectory s = simulate(p.model, p.q(phi0), p.qd(phi0, 0.0), 0.0, 1.3 * period, o);
  const std::vector<double> bottom = crossing_times(s, 2, -kPi / 2);
  CAPTURE(period, small_angle_period(p), s.steps, bottom.size());
  const std::string hint =
      with_formula("your simulated rod does not swing with its exact period: check dormand_prince_step (and "
                   "forward_dynamics if the T1 tests fail)", "T = 4 sqrt(I_O / (m g d)) K(sin(theta0 / 2))");
  {
    INFO("hint: " << hint);
    REQUIRE(bottom.size() >= 3);
  }
  CHECK_NEAR_NAMED("the period of your swing", bottom[2] - bottom[0], period, (Tolerance{tolerance, 0}), hint);
  CHECK_NEAR_NAMED("your half period, bottom to bottom", bottom[1] - bottom[0], period / 2, (Tolerance{tolerance, 0}),
                   hint);
}

GRADED_TEST("simulate projection four-bar from consistent_initial_conditions keeps C and energy",
            "[M04][T4][points=1]") {
  Random rnd(4421);
  const auto p = four_bar_parameters(0.1, 0.3, 0.25, 0.3);
  Model model = examples::four_bar(p);
  model.set_gravity(Vec2(0.0, -kG));
  const VecX guess = four_bar_q(p, 1.1) + rnd.vector(9, -0.02, 0.02);
  const State s0 = consistent_initial_conditions(model, guess, rnd.vector(9, -1, 1), 0.0);
  const ConstraintEvaluation e = evaluate_constraints(model, s0.q, 0.0);
  CHECK_CLOSE_NAMED("C of your projected q", e.C, VecX::Zero(8), (Tolerance{1e-10, 0}),
                    "your project_positions stops before |C| <= 1e-10");
  CHECK_CLOSE_NAMED("C_q q_dot of your projected q_dot", VecX(e.Cq * s0.qd), VecX::Zero(8), (Tolerance{1e-10, 0}),
                    with_formula("your project_velocities must satisfy the velocity equation (the constraints' "
                                 "rate is zero)",
                                 "C_q q_dot + C_t = 0"));
  SimulationOptions o;
  o.integrator = Integrator::rk4;
  o.step = 0.0025;
  o.stabilisation = Stabilisation::projection;
  const Trajectory s = simulate(model, s0.q, s0.qd, 0.0, 3.0, o);
  double drift = 0, velocity_drift = 0;
  for (std::size_t i = 0; i < s.q.size(); ++i) {
    const ConstraintEvaluation ei = evaluate_constraints(model, s.q[i], s.t[i]);
    drift = std::max(drift, ei.C.norm());
    velocity_drift = std::max(velocity_drift, (ei.Cq * s.qd[i] + ei.Ct).norm());
  }
  CAPTURE(drift, velocity_drift, energy_error(model, s), s0.qd.transpose());
  CHECK_NEAR_NAMED("your largest |C| after a projected step", drift, 0.0, (Tolerance{1e-9, 0}),
                   "your project_positions after every step must keep |C| at its tolerance");
  CHECK_NEAR_NAMED("your largest velocity-equation residual after a projected step", velocity_drift, 0.0,
                   (Tolerance{1e-9, 0}), "your project_velocities after every step must keep C_dot at 0");
  const double T0 = 0.5 * s0.qd.dot(mass_matrix_of(model) * s0.qd);
  CAPTURE(T0);
  CHECK_NEAR_NAMED(
      "your largest energy error, relative to T0", energy_error(model, s) / T0, 0.0, (Tolerance{1e-4, 0}),
      "RK4 with projection must conserve the four-bar's energy: the projections are minimum M-norm corrections");
}
