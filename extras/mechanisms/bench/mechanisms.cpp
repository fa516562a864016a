// Benchmark: the cost of a step of module 4's simulate() on the seven-body closed loop
// (21 coordinates, 20 constraints, a spring-damper and a motor torque), with classical
// Runge-Kutta and coordinate projection at a fixed step of 1 ms: the path a user runs. Prints CSV
// rows "group,case,quantity,value,unit" without a header:
//
//   cost_per_step          the marginal cost of a step without the work monitor
//                          (SimulationOptions::integrate_work = false): two runs of s0 and s
//                          steps, (time(s) - time(s0)) / (s - s0), so that the set-up drops out;
//                          the best of three such pairs, as other processes only add time;
//   target, ratio_to_target   the target cost (35 us) and cost / target (<= 1: met);
//   allocations_per_step   heap allocations per step, marginal like the cost;
//   cost_per_step_with_work   the same with the work monitor on (simulate's default);
//   share_*                the parts of a step, from their cost in isolated calls near the initial
//                          state times their calls per step: in each of the 4 RK4 stages M(q),
//                          Q_a, the constraints (C, C_q, C_t and gamma) and the augmented solve;
//                          the projection of positions and velocities, once; and the rest (the
//                          integrator, the output).
//
// Options: --quick (short runs: a smoke test), --budget SECONDS (per timed run, default 1).
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

#include "fmbd/applied_forces.hpp"
#include "fmbd/constraints.hpp"
#include "fmbd/forward_dynamics.hpp"
#include "fmbd/gamma.hpp"
#include "fmbd/mass_matrix.hpp"
#include "fmbd/mechanisms.hpp"
#include "fmbd/projection.hpp"
#include "fmbd/simulation.hpp"
#include "bench.hpp"

using namespace fmbd;
using fmbd::bench::allocations;
using fmbd::bench::row;
using fmbd::bench::seconds;

namespace {

constexpr double kStep = 1e-3, kTarget = 35e-6;
const char* const kGroup = "mechanisms";
const char* const kCase = "seven-body loop RK4 + projection h=1ms (simulate)";

SimulationOptions options() {
  SimulationOptions o;
  o.integrator = Integrator::rk4;
  o.step = kStep;
  o.stabilisation = Stabilisation::projection;
  o.output_interval = 1e9;  // only the first and the last point
  o.integrate_work = false;
  return o;
}

// Seconds per call of f, from as many calls as fit in about `budget` seconds.
template <typename F>
double per_call(F&& f, double budget) {
  int calls = 1;
  double t = seconds(f);
  while (t < budget) {
    calls *= 4;
    t = seconds([&] {
      for (int k = 0; k < calls; ++k) f();
    });
  }
  return t / calls;
}

}  // namespace

int main(int argc, char** argv) {
  double budget = 1.0;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) {
      budget = 0.02;
    } else if (std::strcmp(argv[i], "--budget") == 0 && i + 1 < argc) {
      budget = std::stod(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: %s [--quick] [--budget SECONDS]\n", argv[0]);
      return 2;
    }
  }
  try {
    const mechanisms::SevenBodyLoop loop = mechanisms::seven_body_loop();
    const Model& m = loop.model;
    const SimulationOptions o = options();
    // The marginal cost and allocations of a step of simulate with options `so`.
    auto marginal = [&](const SimulationOptions& so) {
      auto run = [&](int steps) { return simulate(m, loop.q0, loop.qd0, 0.0, steps * kStep, so); };
      // Steps per timed run: about `budget` seconds.
      const double rough = seconds([&] { run(50); }) / 50;
      const int steps = std::max(40, static_cast<int>(budget / std::max(rough, 1e-7))), s0 = steps / 4;
      double cost = 1e30, allocated = 0;
      for (int k = 0; k < 3; ++k) {
        const long a0 = allocations.load();
        const double t0 = seconds([&] { run(s0); });
        const long a1 = allocations.load();
        const double t1 = seconds([&] { run(steps); });
        const long a2 = allocations.load();
        const double c = (t1 - t0) / (steps - s0);
        if (c < cost) {
          cost = c;
          allocated = static_cast<double>((a2 - a1) - (a1 - a0)) / (steps - s0);
        }
      }
      return std::pair{cost, allocated};
    };
    const auto [cost, allocated] = marginal(o);
    row(kGroup, kCase, "cost_per_step", 1e6 * cost, "us");
    row(kGroup, kCase, "target", 1e6 * kTarget, "us");
    row(kGroup, kCase, "ratio_to_target", cost / kTarget, "x");
    row(kGroup, kCase, "allocations_per_step", allocated, "1");
    SimulationOptions with_work = o;
    with_work.integrate_work = true;
    row(kGroup, kCase, "cost_per_step_with_work", 1e6 * marginal(with_work).first, "us");

    // The parts, at the initial state, in isolated calls.
    const VecX& q = loop.q0;
    const VecX qd = VecX::Constant(q.size(), 0.1);
    const double part = budget / 8;
    const double t_mass = per_call([&] { mass_matrix(m, q); }, part);
    const double t_forces = per_call([&] { applied_forces(m, q, qd, 0.0); }, part);
    const double t_constraints = per_call(
        [&] {
          evaluate_constraints(m, q, 0.0);
          constraint_gamma(m, q, qd, 0.0);
        },
        part);
    const MatX M = mass_matrix(m, q), Cq = evaluate_constraints(m, q, 0.0).Cq;
    const VecX top = applied_forces(m, q, qd, 0.0), bottom = VecX::Ones(Cq.rows());
    const double t_solve = per_call([&] { solve_augmented(m, M, Cq, top, bottom, "bench"); }, part);
    // The general path of the solve (LU with full pivoting of the equilibrated matrix), on the same
    // system with the first body a point mass (its rotation is held by its two joints).
    MatX M_point = M;
    M_point(2, 2) = 0;
    const double t_general = per_call([&] { solve_augmented(m, M_point, Cq, top, bottom, "bench"); }, part);
    row(kGroup, kCase, "solve_structured", 1e6 * t_solve, "us");
    row(kGroup, kCase, "solve_general", 1e6 * t_general, "us");
    // The projection of one step: from the state after one unprojected step.
    SimulationOptions free = o;
    free.stabilisation = Stabilisation::none;
    const Trajectory one = simulate(m, loop.q0, loop.qd0, 0.0, kStep, free);
    const double t_projection = per_call(
        [&] {
          const VecX p = project_positions(m, one.q.back(), kStep, o.projection);
          project_velocities(m, p, one.qd.back(), kStep);
        },
        part);
    // Per step: 4 RK4 stages, each with M, Q_a, the constraints and a solve; one projection.
    const double shares[] = {4 * t_mass, 4 * t_forces, 4 * t_constraints, 4 * t_solve, t_projection};
    const char* const names[] = {"share_mass_matrix", "share_applied_forces", "share_constraints", "share_solve",
                                 "share_projection"};
    double rest = cost;
    for (int k = 0; k < 5; ++k) {
      row(kGroup, kCase, names[k], std::min(1.0, shares[k] / cost), "1");
      rest -= shares[k];
    }
    row(kGroup, kCase, "share_rest", std::max(0.0, rest / cost), "1");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fmbd-bench-mechanisms: %s\n", e.what());
    return 1;
  }
  return 0;
}
