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
// The scaling rows (group "scaling"): the cost of a step of the same simulate() on a chain of N
// parallelogram windows under gravity (N + 1 cranks on the ground, N couplers joining their heads;
// 2N + 1 bodies, 6N + 3 coordinates, one degree of freedom), N = 4, 10, 20, 40, over one period
// of its swing (four flat positions; the marginal cost as above, once without the set-up):
//
//   cost_per_step, cost_per_coordinate   per step, and per step and coordinate;
//   ratio_40_to_4, target, ratio_to_target   the cost per coordinate of 40 windows over that of 4,
//                                        the target 3 (a cost linear in the bodies gives 1), and
//                                        their ratio (<= 1: met), which ./workbook bench lists.
//
// The scaling rows measure the engine, not the C library's allocator: through the exercises'
// dense interface every call of mass_matrix() and evaluate_constraints() allocates M and C_q
// (470 KB each at 40 windows), and glibc by default gives such blocks back to the kernel when
// they are freed and faults them in again at the next call, which can cost ten times the
// arithmetic (README, "Large models"). Before them the bench keeps freed memory in the process
// (mallopt: mmap and trim thresholds of 64 and 128 MB), as a program with large models should.
//
// Options: --quick (short runs: a smoke test), --budget SECONDS (per timed run, default 1).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>
#ifdef __GLIBC__
#include <malloc.h>
#endif

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

// A chain of `windows` parallelogram windows: cranks of length a at x = k d on the ground, couplers
// of length d between their heads, every crank at angle theta (at rest).
struct Windows {
  Model model;
  VecX q0, qd0;
};

Windows parallelogram_windows(int windows, double theta) {
  const double a = 0.3, d = 0.5;
  Windows w;
  w.model.set_gravity(Vec2(0, -9.81));
  const Vec2 e(std::cos(theta), std::sin(theta));
  std::vector<BodyId> cranks;
  std::vector<double> q;
  for (int k = 0; k <= windows; ++k) {
    const std::string name = "crank " + std::to_string(k);
    cranks.push_back(w.model.add_body(name, 1.0, a * a / 12));
    w.model.add_revolute("pivot of " + name, w.model.add_point(ground, Vec2(k * d, 0), "ground " + std::to_string(k)),
                         w.model.add_point(cranks.back(), Vec2(-a / 2, 0), "foot of " + name));
    const Vec2 centre = Vec2(k * d, 0) + 0.5 * a * e;
    q.insert(q.end(), {centre.x(), centre.y(), theta});
  }
  for (int k = 0; k < windows; ++k) {
    const std::string name = "coupler " + std::to_string(k);
    const BodyId coupler = w.model.add_body(name, 1.0, d * d / 12);
    for (int side : {0, 1}) {
      const std::string crank = "crank " + std::to_string(k + side);
      w.model.add_revolute(name + " at " + crank,
                           w.model.add_point(cranks[k + side], Vec2(a / 2, 0), "head of " + crank + " for " + name),
                           w.model.add_point(coupler, Vec2(side ? d / 2 : -d / 2, 0), name + " end " + std::to_string(side)));
    }
    const Vec2 centre = Vec2(k * d + d / 2, 0) + a * e;
    q.insert(q.end(), {centre.x(), centre.y(), 0.0});
  }
  w.q0 = Eigen::Map<const VecX>(q.data(), static_cast<Eigen::Index>(q.size()));
  w.qd0 = VecX::Zero(w.q0.size());
  return w;
}

// Freed blocks stay in the process (glibc): no page faults for the dense M and C_q of each call.
void keep_freed_memory() {
#ifdef __GLIBC__
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TRIM_THRESHOLD, 128 << 20);
#endif
}

// The chain, released at rest with its cranks at 1 rad, swings with a period of 1.77 s (the same
// for N = 4 ... 40 to 1 %) through four flat positions, where C_q loses N ranks for an instant and
// the solve takes its rank-revealing path on the steps around it. The timed steps span one period
// from t = 0.1 s, so that the cost per step averages those steps as a long run does (and does not
// depend on whether a short timed span happens to hold one); a budget below 1 s (--quick) times
// a few steps near the start instead.
constexpr double kSwingPeriod = 1.77;
constexpr double kTarget40 = 1e-3;  // a step of the 40-window chain [s]

// The scaling rows: the cost per step and per coordinate of chains of windows.
void scaling_rows(double budget) {
  keep_freed_memory();
  double per_coordinate_4 = 0, per_coordinate_40 = 0;
  for (int windows : {4, 10, 20, 40}) {
    const Windows w = parallelogram_windows(windows, 1.0);
    const SimulationOptions o = options();
    auto run = [&](int steps) { simulate(w.model, w.q0, w.qd0, 0.0, steps * kStep, o); };
    const double rough = budget < 1 ? seconds([&] { run(10); }) / 10 : 0.0;
    const int steps = budget < 1 ? std::max(20, static_cast<int>(budget / 2 / std::max(rough, 1e-7)))
                                 : 100 + static_cast<int>(std::lround(kSwingPeriod / kStep));
    const int s0 = budget < 1 ? steps / 4 : 100;
    double cost = 1e30;
    for (int k = 0; k < 2; ++k) {
      const double t0 = seconds([&] { run(s0); });
      const double t1 = seconds([&] { run(steps); });
      cost = std::min(cost, (t1 - t0) / (steps - s0));
    }
    const int n = static_cast<int>(w.q0.size());
    const std::string name = "chain of " + std::to_string(windows) + " parallelogram windows (" + std::to_string(n) +
                             " coordinates) RK4 + projection h=1ms";
    row("scaling", name.c_str(), "cost_per_step", 1e6 * cost, "us");
    row("scaling", name.c_str(), "cost_per_coordinate", 1e6 * cost / n, "us");
    if (windows == 40) {  // the benchmark's own case (IFToMM A02)
      row("scaling", name.c_str(), "target", 1e6 * kTarget40, "us");
      row("scaling", name.c_str(), "ratio_to_target", cost / kTarget40, "x");
    }
    if (windows == 4) per_coordinate_4 = cost / n;
    if (windows == 40) per_coordinate_40 = cost / n;
  }
  const char* const ratio = "cost per coordinate of 40 parallelogram windows over that of 4";
  const double measured = per_coordinate_40 / per_coordinate_4;
  row("scaling", ratio, "ratio_40_to_4", measured, "x");
  row("scaling", ratio, "target", 3.0, "x");
  row("scaling", ratio, "ratio_to_target", measured / 3.0, "x");
}

// The marginal cost and allocations of a step of simulate on the loop with options `so`: two runs
// of s0 and s steps, (time(s) - time(s0)) / (s - s0), the best of three such pairs.
std::pair<double, double> marginal_step(const mechanisms::SevenBodyLoop& loop, const SimulationOptions& so,
                                        double budget) {
  auto run = [&](int steps) { return simulate(loop.model, loop.q0, loop.qd0, 0.0, steps * kStep, so); };
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
}

// The rows of the marginal cost of a step (without and with the work monitor), its target and
// its allocations; returns the cost without the monitor.
double cost_rows(const mechanisms::SevenBodyLoop& loop, double budget) {
  const SimulationOptions o = options();
  const auto [cost, allocated] = marginal_step(loop, o, budget);
  row(kGroup, kCase, "cost_per_step", 1e6 * cost, "us");
  row(kGroup, kCase, "target", 1e6 * kTarget, "us");
  row(kGroup, kCase, "ratio_to_target", cost / kTarget, "x");
  row(kGroup, kCase, "allocations_per_step", allocated, "1");
  SimulationOptions with_work = o;
  with_work.integrate_work = true;
  row(kGroup, kCase, "cost_per_step_with_work", 1e6 * marginal_step(loop, with_work, budget).first, "us");
  return cost;
}

// The share_* rows: the parts of a step of cost `cost`, from isolated calls at the initial state
// (and the solve_* rows: the structured and the general path of the augmented solve).
void share_rows(const mechanisms::SevenBodyLoop& loop, double cost, double budget) {
  const Model& m = loop.model;
  const SimulationOptions o = options();
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
    const double cost = cost_rows(loop, budget);
    share_rows(loop, cost, budget);
    scaling_rows(budget);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fmbd-bench-mechanisms: %s\n", e.what());
    return 1;
  }
  return 0;
}
