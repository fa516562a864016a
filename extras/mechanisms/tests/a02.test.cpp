// The N-four-bar mechanism (IFToMM benchmark A02) through its flat positions, where C_q loses N
// ranks for an instant, against the exact one-degree-of-freedom motion (four_bar_chain_theta).
#include <cmath>
#include <exception>
#include <vector>

#include "fmbd/kinematic_errors.hpp"
#include "fmbd/mechanisms.hpp"
#include "fmbd/simulation.hpp"
#include "grading.hpp"

using namespace fmbd;

namespace {

// Flat positions the exact motion passes in the recorded span: sign changes of sin(theta).
int flat_positions(const std::vector<double>& theta) {
  int count = 0;
  for (std::size_t i = 1; i < theta.size(); ++i) count += std::sin(theta[i - 1]) * std::sin(theta[i]) < 0;
  return count;
}

SimulationOptions dormand_prince(double rtol, double dt, double max_step = SimulationOptions{}.max_step) {
  SimulationOptions o;
  o.max_step = max_step;
  o.integrator = Integrator::dormand_prince;
  o.rtol = rtol;
  o.atol = 1e-3 * rtol;
  o.stabilisation = Stabilisation::projection;
  o.output_interval = dt;
  return o;
}

// Dormand-Prince at `rtol` on the chain of `windows` over T s, against the exact motion.
mechanisms::FourBarChainError dormand_prince_error(int windows, double T, double rtol, double dt) {
  const mechanisms::FourBarChain chain = mechanisms::four_bar_chain(windows);
  const std::vector<double> theta = mechanisms::four_bar_chain_theta(windows, dt, T);
  const Trajectory run = simulate(chain.model, chain.q0, chain.qd0, 0.0, T, dormand_prince(rtol, dt));
  const mechanisms::FourBarChainError e = mechanisms::four_bar_chain_error(run, theta);
  CAPTURE(windows, rtol, e.position, e.energy, run.steps, run.rejected_steps);
  return e;
}

SimulationOptions rk4_projected(double h, double dt) {
  SimulationOptions o;
  o.step = h;
  o.stabilisation = Stabilisation::projection;
  o.output_interval = dt;
  return o;
}

// The chain's first flat instant (theta = 0), from the exact motion (four_bar_chain_theta) at
// 1e-5 s and its energy: J theta'^2 / 2 + G sin(theta) = J / 2 + G (theta(0) = pi/2, theta'(0) = -1),
// the last sample's distance to the root by the Taylor series of second order (error ~1e-15 s).
double first_flat_instant(int windows) {
  const double N = windows, J = (N + 1) / 3 + N, G = 9.81 * ((N + 1) / 2 + N), dt = 1e-5;
  const std::vector<double> theta = mechanisms::four_bar_chain_theta(windows, dt, 2.0);
  std::size_t k = 0;
  while (k + 1 < theta.size() && theta[k + 1] > 0) ++k;
  REQUIRE(k + 1 < theta.size());
  const double th = theta[k], w = -std::sqrt(1 + 2 * G / J * (1 - std::sin(th))), a = -G / J * std::cos(th);
  // th + w s + a s^2 / 2 = 0, the root near -th / w
  const double s = (-w - std::sqrt(w * w - 2 * a * th)) / a;
  return static_cast<double>(k) * dt + s;
}

// The run seen from the chain's own frame: every body's x and y less `origin`.
Trajectory from_origin(Trajectory run, const Model& model, const Vec2& origin) {
  for (VecX& q : run.q)
    for (int b = 0; b < model.num_bodies(); ++b) q.segment<2>(model.offset(BodyId{b})) -= origin;
  return run;
}

}  // namespace

TEST_CASE("A02 N-four-bar: Dormand-Prince with projection passes every flat position of 4 and 10 windows",
          "[mechanisms][singular]") {
  // It stopped at the first or second flat position ("the adaptive step fell below min_step", or
  // no acceleration at a stage). Over 10 s (10 flat positions), with the default max_step of
  // 0.02 s: within 1e-5 m at rtol 1e-6 (3.7e-8 and 3.3e-8 m measured; 2.4e-5 and 1.4e-5 m with
  // steps of up to 0.05 s) and at rtol 1e-9 (3.2e-7 m on both chains). The energy at the output
  // points, between the ends of the steps (the step's own continuous extension), within 5e-5 J
  // (9.1e-6 J at most measured; the cubic Hermite output missed it by 1.6e-2 and 4.0e-2 J).
  const double T = 10.0, dt = 0.05;
  for (int windows : {4, 10}) {
    const mechanisms::FourBarChain chain = mechanisms::four_bar_chain(windows);
    const std::vector<double> theta = mechanisms::four_bar_chain_theta(windows, dt, T);
    REQUIRE(flat_positions(theta) >= 8);
    for (const double rtol : {1e-6, 1e-9}) {
      CAPTURE(windows, rtol);
      const Trajectory run = simulate(chain.model, chain.q0, chain.qd0, 0.0, T, dormand_prince(rtol, dt));
      const mechanisms::FourBarChainError e = mechanisms::four_bar_chain_error(run, theta);
      CAPTURE(e.position, e.energy, run.steps, run.rejected_steps);
      CHECK(e.position <= 1e-5);
      CHECK(e.energy <= 5e-5);
    }
  }
}

TEST_CASE("A02 N-four-bar: Dormand-Prince's error control does not depend on where the chain stands",
          "[mechanisms][singular]") {
  // The weights of the error are the bodies' sizes, not the coordinates' distances from the
  // origin: the 4-window chain moved 100 m out takes the same steps as at the origin and makes
  // the same error. max_step is the run's length, so that the estimate alone sets every step
  // (measured: 161 steps and 6.20e-5 m at all three places; with the distance's weights the
  // positions 100 m out were controlled 200 times more loosely).
  const double T = 10.0, dt = 0.05;
  const std::vector<double> theta = mechanisms::four_bar_chain_theta(4, dt, T);
  const mechanisms::FourBarChain here = mechanisms::four_bar_chain(4);
  const Trajectory near = simulate(here.model, here.q0, here.qd0, 0.0, T, dormand_prince(1e-6, dt, T));
  const double error_near = mechanisms::four_bar_chain_error(near, theta).position;
  for (const Vec2& origin : {Vec2(100, 0), Vec2(-60, 80)}) {
    const mechanisms::FourBarChain there = mechanisms::four_bar_chain(4, origin);
    const Trajectory far = simulate(there.model, there.q0, there.qd0, 0.0, T, dormand_prince(1e-6, dt, T));
    const double error_far = mechanisms::four_bar_chain_error(from_origin(far, there.model, origin), theta).position;
    CAPTURE(origin.transpose(), error_near, error_far, near.steps, far.steps);
    CHECK(std::abs(far.steps - near.steps) <= 2);
    CHECK(error_far <= 1.1 * error_near);
  }
}

TEST_CASE("A02 N-four-bar: Dormand-Prince at rtol 1e-6 on the benchmark's 40 windows over 20 s",
          "[mechanisms][singular]") {
  // With the default max_step of 0.02 s: 1.7e-7 m measured (2.9e-5 m with steps of up to 0.05 s,
  // 1.7e-4 m with the estimate's steps alone).
  CHECK(dormand_prince_error(40, 20.0, 1e-6, 0.05).position <= 1e-5);
}

TEST_CASE("A02 N-four-bar: Dormand-Prince at rtol 1e-9 on the benchmark's 40 windows over 20 s",
          "[mechanisms][singular]") {
  // Within 1e-5 m (1.4e-6 m measured, 1279 steps; about 4 s).
  CHECK(dormand_prince_error(40, 20.0, 1e-9, 0.05).position <= 1e-5);
}

TEST_CASE("A02 N-four-bar: RK4 with projection, a smaller step is never worse", "[mechanisms][singular]") {
  // A stage or a projection that fell within a small fraction of a step of a flat instant turned
  // the stages' drift, amplified across the branch by 1/sigma_min, into a jump of phase and energy,
  // at random as the grid fell (6.4e-11, 1.4e-8, 8.2e-8 m and 2.9e-9, 2.4e-8, 2.4e-7 J at these
  // steps; 3.3e-5 m and 5.5e-5 J at a step of 1.00001e-4 s). The steps now span each flat instant
  // (fmbd/singular_instant.hpp): 6.4e-11, 8.3e-13, 6.3e-12 m and 2.9e-9, 5.5e-11, 3.1e-12 J measured.
  // Each smaller step ends no further from the exact motion, and drifts no more in energy, or
  // stays within round-off: one rounding (eps) per step of the chain's length (10 m) or energy.
  const int windows = 10;
  const double T = 5.0, dt = 0.05, eps = 2.2e-16;
  const mechanisms::FourBarChain chain = mechanisms::four_bar_chain(windows);
  const std::vector<double> theta = mechanisms::four_bar_chain_theta(windows, dt, T);
  REQUIRE(flat_positions(theta) >= 5);
  mechanisms::FourBarChainError previous{HUGE_VAL, HUGE_VAL};
  for (double h : {1e-3, 3e-4, 1e-4}) {
    const Trajectory run = simulate(chain.model, chain.q0, chain.qd0, 0.0, T, rk4_projected(h, dt));
    const mechanisms::FourBarChainError e = mechanisms::four_bar_chain_error(run, theta);
    const double steps = T / h, round_off = steps * eps * windows, energy_round_off = steps * eps * std::abs(run.energy.front());
    CAPTURE(h, e.position, e.energy, previous.position, previous.energy, round_off, energy_round_off, run.rejected_steps);
    CHECK(e.position <= std::max(previous.position, round_off));
    CHECK(e.energy <= std::max(previous.energy, energy_round_off));
    CHECK(static_cast<int>(run.stepped_over.size()) == flat_positions(theta));  // each flat instant, once
    previous = e;
  }
}

TEST_CASE("A02 N-four-bar: RK4 steps whose grid falls on a flat instant", "[mechanisms][singular]") {
  // The worst grids: the first flat instant t_c (the exact motion's, to 1e-12 s) at the end of a
  // step, or at its middle stages. There a step of 1e-3 s changed the energy by up to 26 J, and
  // one of 1e-4 s by 0.16 J or locked the linkage (SingularJacobianError). Spanned, the run stays
  // within 1e-9 m and 1e-8 J of the exact motion.
  const int windows = 10;
  const double T = 0.8, dt = 0.01;
  const mechanisms::FourBarChain chain = mechanisms::four_bar_chain(windows);
  const std::vector<double> theta = mechanisms::four_bar_chain_theta(windows, dt, T);
  const double t_c = first_flat_instant(windows);
  for (double h : {1e-3, 1e-4})
    for (double at : {0.0, 0.5}) {  // t_c at a step's end, at its middle stages
      const double step = t_c / (std::round(t_c / h) + at);
      const Trajectory run = simulate(chain.model, chain.q0, chain.qd0, 0.0, T, rk4_projected(step, dt));
      const mechanisms::FourBarChainError e = mechanisms::four_bar_chain_error(run, theta);
      CAPTURE(h, at, step, t_c, e.position, e.energy, run.stepped_over);
      CHECK(e.position <= 1e-9);
      CHECK(e.energy <= 1e-8);
      REQUIRE(run.stepped_over.size() == 1);
      CHECK(std::abs(run.stepped_over[0] - t_c) <= 0.1 * step);  // where the margins foretold it
    }
}

TEST_CASE("A02 N-four-bar: the exact motion's oracle", "[mechanisms]") {
  // theta from four_bar_chain_theta keeps the first integral J theta'^2 / 2 + G sin(theta) of its
  // equation: theta' from finite differences of a fine grid.
  const int N = 10;
  const double J = (N + 1) / 3.0 + N, G = 9.81 * ((N + 1) / 2.0 + N), dt = 1e-3;
  const std::vector<double> theta = mechanisms::four_bar_chain_theta(N, dt, 2.0);
  const double E0 = 0.5 * J + G;  // theta = pi/2, theta' = -1
  for (std::size_t i = 1; i + 1 < theta.size(); i += 97) {
    const double rate = (theta[i + 1] - theta[i - 1]) / (2 * dt);
    CHECK(0.5 * J * rate * rate + G * std::sin(theta[i]) == Approx(E0).epsilon(1e-5));
  }
}

TEST_CASE("simulate_keeping: a run that fails keeps its trajectory up to the failure", "[mechanisms]") {
  // Without stabilisation the 4-window chain drifts past 1e-9 L at its third flat position
  // (t = 2.67 s): simulate() throws DriftError there and its 267 recorded points were lost.
  const mechanisms::FourBarChain chain = mechanisms::four_bar_chain(4);
  const double T = 3.0;
  SimulationOptions o;
  o.output_interval = 0.01;
  o.drift_limit = HUGE_VAL;
  const Trajectory full = simulate(chain.model, chain.q0, chain.qd0, 0.0, T, o);
  o.drift_limit = 1e-9;
  const SimulationOutcome run = simulate_keeping(chain.model, chain.q0, chain.qd0, 0.0, T, o);
  REQUIRE_FALSE(run.completed());
  CHECK_THROWS_AS(std::rethrow_exception(run.error), DriftError);
  const Trajectory& kept = run.trajectory;
  REQUIRE(kept.t.size() >= 250);
  REQUIRE(kept.t.size() < full.t.size());
  CHECK(kept.steps > 0);
  for (std::size_t i = 0; i < kept.t.size(); ++i) {  // the same points as the run without a limit
    CHECK(kept.t[i] == full.t[i]);
    CHECK((kept.q[i] - full.q[i]).norm() == 0.0);
  }
  CHECK_THROWS_AS(simulate(chain.model, chain.q0, chain.qd0, 0.0, T, o), DriftError);  // simulate() still throws
  // A failure that is not an IntegrationError (the exercise's projection) keeps its points too.
  SimulationOptions p;
  p.stabilisation = Stabilisation::projection;
  p.projection.tolerance = 1e-30;
  p.projection.max_iterations = 1;
  const SimulationOutcome stuck = simulate_keeping(chain.model, chain.q0, chain.qd0, 0.0, T, p);
  CHECK_THROWS_AS(std::rethrow_exception(stuck.error), ConvergenceError);
  CHECK(stuck.trajectory.t.size() == 1);
  o.drift_limit = HUGE_VAL;
  CHECK(simulate_keeping(chain.model, chain.q0, chain.qd0, 0.0, T, o).trajectory.t.size() == full.t.size());
}
