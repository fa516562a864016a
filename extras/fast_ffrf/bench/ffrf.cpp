// Benchmark: simulation cost of the full FFRF body, nodal form (FfrfBody) against the fast form
// with inertia invariants (ModalFfrfBody), on module 7's flexible slider-crank with the default
// rod (consistent mass, Craig-Bampton on both end nodes), stepped by module 4's simulate with
// classical Runge-Kutta at one fixed step for every case.
//
// Two sweeps: the number of fixed-interface modes (2 .. 40; n_f = 3 + modes) at 50 elements, and
// the number of elements (10 .. 400) at 5 modes. Per case and form it prints, as CSV rows
// "group,case,quantity,value,unit" without a header:
//
//   steps_per_second, cost_per_step   the marginal cost of a step: two runs of s0 and s steps,
//                                     (time(s) - time(s0)) / (s - s0), so that the set-up of
//                                     simulate (consistency check, first record) drops out; the
//                                     best of three such pairs, as other processes only add time;
//   share_mass_matrix, share_body_forces, share_rest
//                                     from one more run through a forwarding body that times every
//                                     call of mass_matrix and body_forces (the rest: constraints,
//                                     the augmented solve, the integrator, the Model's assembly);
//   mass_matrix_calls_per_step        evaluations of M(q) per step (RK4: 4 stages; the work of
//                                     the drivers is integrated with them);
//   flops_per_step, gflops            an estimate from the formulas (leading terms, multiply-add
//                                     = 2 flops), n = 3 (elements + 1), z = the entries of the
//                                     sparse M_FE that are not zero, N = n_q + m of the
//                                     augmented system:
//                                       nodal M(q)      2 z (3 + n_f) + 2 n (3 + n_f)^2
//                                       nodal forces    4 z + 4 n (3 + n_f) + 2 n_f^2
//                                       fast M(q)       4 n_f^2,   fast forces  10 n_f^2
//                                       augmented LU    2/3 N^3 + 2 N^2 per evaluation
//                                     times the calls per step; gflops = flops_per_step / cost;
//   allocations_per_step              heap allocations per step (malloc, calloc and realloc are
//                                     wrapped by counting ones), marginal like the cost;
//   setup_invariants                  (fast form) the time to make the invariants, once;
//   speedup                           (fast form) the nodal cost per step over the fast one.
//
// A third row per case steps the fast body with WorkspaceRk4 (bench/workspace), the allocation-free
// loop: its cost per step (the best of three runs), allocations per step, the speed-up over the
// nodal form, and from one more run with its profiling on the shares of M(q), the body forces
// (Q_v, gravity, elastic), the constraint rows (markers, C_q, gamma), the solve of the augmented
// system, and the rest (the RK4 stages).
//
// First, the two cases of the engine's speed targets (group "targets": 50 elements and 5 modes in
// the nodal form, target 60 us per step; 16 elements and 4 modes in the fast form, target 15 us):
// cost_per_step without the work monitor (SimulationOptions::integrate_work = false), target,
// ratio_to_target (<= 1: met), allocations_per_step, the shares above, and
// cost_per_step_with_work, the cost with the monitor on (simulate's default).
//
// Options: --quick (two small cases, short runs: a smoke test), --budget SECONDS (the target
// duration of each timed run, default 1).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "fmbd/ffrf.hpp"
#include "fmbd/ffrf_invariants.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/simulation.hpp"
#include "fmbd/workspace_rk4.hpp"
#include "bench.hpp"

using namespace fmbd;

using fmbd::bench::allocations;
using fmbd::bench::row;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// RK4 is stable below h omega_max = 2.78; the stiffest case (40 modes) has omega_max = 1.9e6 rad/s.
constexpr double kStep = 1e-6;

enum class Form { nodal, fast };

// A DeformableBody that holds both forms of one body, forwards every call to the selected one and
// can time the calls of add_mass and add_forces.
class BenchBody : public DeformableBody {
 public:
  BenchBody(std::shared_ptr<const DeformableBody> nodal, std::shared_ptr<const DeformableBody> fast)
      : nodal_(std::move(nodal)), fast_(std::move(fast)) {}

  void use(Form form) { active_ = form == Form::nodal ? nodal_.get() : fast_.get(); }
  void time_calls(bool on) { timing_ = on; }
  void reset() const {
    mass_seconds_ = forces_seconds_ = 0.0;
    mass_calls_ = forces_calls_ = 0;
  }
  double mass_seconds() const { return mass_seconds_; }
  double forces_seconds() const { return forces_seconds_; }
  long mass_calls() const { return mass_calls_; }
  long forces_calls() const { return forces_calls_; }

  int num_modes() const override { return active_->num_modes(); }
  int num_nodes() const override { return active_->num_nodes(); }
  Vec2 node_position(int node) const override { return active_->node_position(node); }
  double mass() const override { return active_->mass(); }
  double inertia() const override { return active_->inertia(); }
  NodeMarker node_marker(int node, const VecX& q, const VecX& qd) const override {
    return active_->node_marker(node, q, qd);
  }
  void write_node_marker(int node, const VecX& q, const VecX& qd, NodeMarker& out) const override {
    active_->write_node_marker(node, q, qd, out);
  }
  void add_node_columns(const NodeMarker& node, const RowBlock& B, int first_row, int at, MatX& Cq) const override {
    active_->add_node_columns(node, B, first_row, at, Cq);
  }
  RowVector node_gamma_term(const NodeMarker& node, const RowBlock& B) const override {
    return active_->node_gamma_term(node, B);
  }
  void add_node_force(const NodeMarker& node, const Vec3& Q, int at, VecX& Q_a) const override {
    active_->add_node_force(node, Q, at, Q_a);
  }
  void add_mass(const VecX& q, int at, MatX& M) const override {
    ++mass_calls_;
    if (!timing_) return active_->add_mass(q, at, M);
    const Clock::time_point start = Clock::now();
    active_->add_mass(q, at, M);
    mass_seconds_ += seconds_since(start);
  }
  void add_forces(const VecX& q, const VecX& qd, const Vec2& g, int at, VecX& Q_a) const override {
    ++forces_calls_;
    if (!timing_) return active_->add_forces(q, qd, g, at, Q_a);
    const Clock::time_point start = Clock::now();
    active_->add_forces(q, qd, g, at, Q_a);
    forces_seconds_ += seconds_since(start);
  }
  double kinetic_energy(const VecX& q, const VecX& qd) const override { return active_->kinetic_energy(q, qd); }
  double potential_energy(const VecX& q, const Vec2& g) const override { return active_->potential_energy(q, g); }

 private:
  std::shared_ptr<const DeformableBody> nodal_, fast_;
  const DeformableBody* active_ = nodal_.get();
  bool timing_ = false;
  mutable double mass_seconds_ = 0.0, forces_seconds_ = 0.0;
  mutable long mass_calls_ = 0, forces_calls_ = 0;
};

struct Options {
  bool quick = false;
  double budget = 1.0;  // [s] per timed run
};

struct Measured {
  double cost = 0.0;  // [s] per step
  double share_mass = 0.0, share_forces = 0.0;
  double mass_calls = 0.0, forces_calls = 0.0;  // per step
  double allocations = 0.0;                     // per step
};

// Wall time of simulate over `steps` steps of kStep (no output but the first and last point),
// with or without the work monitor.
double run(const FlexibleExample& ex, int steps, bool work = true) {
  SimulationOptions o;
  o.integrator = Integrator::rk4;
  o.step = kStep;
  o.output_interval = 1e9;
  o.integrate_work = work;
  const Clock::time_point start = Clock::now();
  const Trajectory tr = simulate(ex.model, ex.q0, ex.qd0, 0.0, steps * kStep, o);
  const double elapsed = seconds_since(start);
  if (tr.steps != steps)
    throw std::logic_error("bench: expected " + std::to_string(steps) + " steps, simulate took " +
                           std::to_string(tr.steps));
  return elapsed;
}

Measured measure(const FlexibleExample& ex, BenchBody& body, Form form, const Options& opt, bool work = true) {
  body.use(form);
  body.time_calls(false);
  run(ex, 2, work);  // warm-up
  // The best of three marginal costs: other processes only ever add time.
  const int s0 = 3;
  const int steps = std::clamp(static_cast<int>(opt.budget / 3 / (run(ex, s0, work) / s0)), s0 + 5, 1000000);
  Measured m;
  m.cost = 1e300;
  for (int repeat = 0; repeat < 3; ++repeat) {
    const double t0 = run(ex, s0, work), t1 = run(ex, steps, work);
    m.cost = std::min(m.cost, std::max((t1 - t0) / (steps - s0), 1e-12));
  }

  const long a0 = allocations.load();
  run(ex, s0, work);
  const long a1 = allocations.load();
  run(ex, steps, work);
  m.allocations = static_cast<double>((allocations.load() - a1) - (a1 - a0)) / (steps - s0);

  body.time_calls(true);
  body.reset();
  const double t2 = run(ex, steps, work);
  m.share_mass = body.mass_seconds() / t2;
  m.share_forces = body.forces_seconds() / t2;
  m.mass_calls = static_cast<double>(body.mass_calls()) / steps;
  m.forces_calls = static_cast<double>(body.forces_calls()) / steps;
  body.time_calls(false);
  return m;
}

double flops_per_step(Form form, const FlexibleExample& ex, const Measured& m) {
  const double n = ex.data->fe.num_dofs(), f = ex.data->num_modes(), r = 3 + f;
  const double z = static_cast<double>(ex.data->matrices.M.nonZeros());
  const double N = ex.model.num_coordinates() + ex.model.num_constraints();
  const double mass = form == Form::nodal ? 2 * z * r + 2 * n * r * r : 4 * f * f;
  const double forces = form == Form::nodal ? 4 * z + 4 * n * r + 2 * f * f : 10 * f * f;
  const double solve = 2.0 / 3.0 * N * N * N + 2 * N * N;
  return m.mass_calls * (mass + solve) + m.forces_calls * forces;
}

// The fast body stepped by WorkspaceRk4 (bench/workspace): RK4 with no allocation per step and 4
// evaluations per step (simulate adds a fifth for the work of the drivers).
void bench_workspace(const char* group, const FlexibleSliderCrankParameters& p, const Options& opt,
                     double nodal_cost) {
  const FlexibleExample ex = flexible_slider_crank(p, make_modal_ffrf_body);
  bench::WorkspaceRk4 stepper(ex.model);
  VecX y(2 * ex.q0.size());
  y << ex.q0, ex.qd0;
  double t = 0.0;
  auto run_steps = [&](int steps) {
    const Clock::time_point start = Clock::now();
    for (int s = 0; s < steps; ++s, t += kStep) stepper.step(t, y, kStep);
    return seconds_since(start);
  };
  run_steps(2);  // warm-up
  const int steps = std::clamp(static_cast<int>(opt.budget / 3 / (run_steps(3) / 3)), 8, 1000000);
  double cost = 1e300;
  for (int repeat = 0; repeat < 3; ++repeat) cost = std::min(cost, run_steps(steps) / steps);
  const long a0 = allocations.load();
  run_steps(steps);
  const double per_step = static_cast<double>(allocations.load() - a0) / steps;
  stepper.set_profiling(true);
  const double profiled = run_steps(steps);
  const bench::StepProfile parts = stepper.profile();
  stepper.set_profiling(false);
  const std::string name = "ModalFfrfBody + WorkspaceRk4 (allocation-free loop); " + std::to_string(p.elements) +
                           " elements; " + std::to_string(p.modes) + " modes (n_f " +
                           std::to_string(ex.data->num_modes()) + "); RK4 h 1e-6 s";
  row(group, name, "steps_per_second", 1.0 / cost, "1/s");
  row(group, name, "cost_per_step", 1e6 * cost, "us");
  row(group, name, "allocations_per_step", per_step, "1");
  row(group, name, "share_mass_matrix", 100 * parts.mass_matrix / profiled, "%");
  row(group, name, "share_body_forces", 100 * parts.body_forces / profiled, "%");
  row(group, name, "share_constraints", 100 * parts.constraints / profiled, "%");
  row(group, name, "share_solve", 100 * parts.solve / profiled, "%");
  row(group, name, "share_rest",
      100 * (1 - (parts.mass_matrix + parts.body_forces + parts.constraints + parts.solve) / profiled), "%");
  row(group, name, "speedup", nodal_cost / cost, "x");
  std::fflush(stdout);
}

void bench_case(const char* group, int elements, int modes, const Options& opt) {
  FlexibleSliderCrankParameters p;
  p.elements = elements;
  p.modes = modes;
  std::shared_ptr<BenchBody> body;
  double setup = 0.0;
  const BodyFactory factory = [&](std::shared_ptr<const FlexibleBodyData> data) {
    const Clock::time_point start = Clock::now();
    std::shared_ptr<const DeformableBody> fast = make_modal_ffrf_body(data);
    setup = seconds_since(start);
    body = std::make_shared<BenchBody>(make_ffrf_body(data), std::move(fast));
    return std::shared_ptr<const DeformableBody>(body);
  };
  const FlexibleExample ex = flexible_slider_crank(p, factory);
  const int n_f = ex.data->num_modes();
  double nodal_cost = 0.0;
  for (Form form : {Form::nodal, Form::fast}) {
    const Measured m = measure(ex, *body, form, opt);
    const std::string name = std::string(form == Form::nodal ? "FfrfBody (nodal)" : "ModalFfrfBody (invariants)") +
                             "; " + std::to_string(elements) + " elements; " + std::to_string(modes) +
                             " modes (n_f " + std::to_string(n_f) + "); RK4 h 1e-6 s";
    const double flops = flops_per_step(form, ex, m);
    row(group, name, "steps_per_second", 1.0 / m.cost, "1/s");
    row(group, name, "cost_per_step", 1e6 * m.cost, "us");
    row(group, name, "share_mass_matrix", 100 * m.share_mass, "%");
    row(group, name, "share_body_forces", 100 * m.share_forces, "%");
    row(group, name, "share_rest", 100 * (1 - m.share_mass - m.share_forces), "%");
    row(group, name, "mass_matrix_calls_per_step", m.mass_calls, "1");
    row(group, name, "allocations_per_step", m.allocations, "1");
    row(group, name, "flops_per_step", flops, "flop");
    row(group, name, "gflops", flops / m.cost * 1e-9, "GFLOP/s");
    if (form == Form::nodal) {
      nodal_cost = m.cost;
    } else {
      row(group, name, "setup_invariants", 1e3 * setup, "ms");
      row(group, name, "speedup", nodal_cost / m.cost, "x");
    }
    std::fflush(stdout);
  }
  bench_workspace(group, p, opt, nodal_cost);
}

// The cases of the engine's speed targets, each in one form through simulate without the work
// monitor: its cost against the target (ratio <= 1: met), allocations, the shares of M(q), the
// body forces and the rest (constraints, the augmented solve, the integrator), and the cost with
// the work monitor on (simulate's default).
void bench_target(int elements, int modes, Form form, double target, const Options& opt) {
  FlexibleSliderCrankParameters p;
  p.elements = elements;
  p.modes = modes;
  std::shared_ptr<BenchBody> body;
  const BodyFactory factory = [&](std::shared_ptr<const FlexibleBodyData> data) {
    body = std::make_shared<BenchBody>(make_ffrf_body(data), make_modal_ffrf_body(data));
    return std::shared_ptr<const DeformableBody>(body);
  };
  const FlexibleExample ex = flexible_slider_crank(p, factory);
  const Measured m = measure(ex, *body, form, opt, false);
  const Measured with_work = measure(ex, *body, form, opt, true);
  const std::string name = std::string(form == Form::nodal ? "FfrfBody (nodal)" : "ModalFfrfBody (invariants)") +
                           "; " + std::to_string(elements) + " elements; " + std::to_string(modes) + " modes; RK4 h 1e-6 s (simulate)";
  row("targets", name, "cost_per_step", 1e6 * m.cost, "us");
  row("targets", name, "target", 1e6 * target, "us");
  row("targets", name, "ratio_to_target", m.cost / target, "x");
  row("targets", name, "allocations_per_step", m.allocations, "1");
  row("targets", name, "share_mass_matrix", 100 * m.share_mass, "%");
  row("targets", name, "share_body_forces", 100 * m.share_forces, "%");
  row("targets", name, "share_rest", 100 * (1 - m.share_mass - m.share_forces), "%");
  row("targets", name, "cost_per_step_with_work", 1e6 * with_work.cost, "us");
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) {
      opt.quick = true;
      opt.budget = 0.02;
    } else if (std::strcmp(argv[i], "--budget") == 0 && i + 1 < argc) {
      opt.budget = std::stod(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: %s [--quick] [--budget SECONDS]\n", argv[0]);
      return 2;
    }
  }
  try {
    bench_target(50, 5, Form::nodal, 60e-6, opt);
    bench_target(16, 4, Form::fast, 15e-6, opt);
    if (opt.quick) {
      bench_case("modes", 10, 2, opt);
      bench_case("elements", 25, 5, opt);
      return 0;
    }
    for (int modes : {2, 5, 10, 20, 40}) bench_case("modes", 50, modes, opt);
    for (int elements : {10, 25, 50, 100, 200, 400}) bench_case("elements", elements, 5, opt);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fmbd-bench-ffrf: %s\n", e.what());
    return 1;
  }
  return 0;
}
