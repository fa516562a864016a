// Benchmark: a flexible body from a large imported FE model (sparse_body.hpp, module 8): a
// free-free steel frame lattice (frame_lattice of module 5, 0.1 m cells, 20 mm square members,
// consistent mass) held as the SparseFeModel that load_sparse_fe_model would return for its files
// (the files themselves: fmbd-bench-modal, group import), reduced by sparse Craig-Bampton on its
// four corner nodes (12 interface DOFs) with 10 fixed-interface modes, made FFRF-ready
// (sparse_ffrf_basis: n_f = 19) and turned into a ModalFfrfBody, then hinged at a corner node to
// the ground under gravity and stepped by module 4's simulate.
//
// Prints CSV rows "group,case,quantity,value,unit" (no header), case "n=N" for N DOFs:
//   reduction   seconds of sparse_craig_bampton, of sparse_ffrf_basis and of
//               make_sparse_modal_ffrf_body; n_f; the first elastic frequency of the body; the
//               highest frequency omega_max of the reduced body;
//   step        the marginal cost of one step, per integrator (rk4 at h = 1 / omega_max,
//               generalized_alpha at h = 1e-3 s with its defaults): two runs of s0 = 3 and s steps,
//               (time(s) - time(s0)) / (s - s0), so that the set-up of simulate drops out, with s
//               such that a run takes about 0.3 s (a few thousand steps at most: a few ms of
//               simulated time); the best of three such pairs.
// The per-step cost does not depend on n (the body works on n_f-sized invariants): compare the
// cases. Times are wall-clock: on a busy machine the reduction times grow. Sizes n = 2883,
// 30 603 and 101 568 (about 30 s in all); --quick: n = 2883 only, runs of about 0.02 s.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "fmbd/generalized_alpha.hpp"
#include "fmbd/matrix_market.hpp"
#include "fmbd/simulation.hpp"
#include "fmbd/sparse_body.hpp"
#include "fmbd/sparse_modal.hpp"
#include "fmbd/sparse_reduction.hpp"
#include "bench.hpp"

using namespace fmbd;
using fmbd::bench::row;
using fmbd::bench::seconds;

namespace {

constexpr double kTwoPi = 2.0 * 3.14159265358979323846;

// The lattice as an imported model: its node table numbers node k's DOFs 3k, 3k + 1, 3k + 2.
SparseFeModel imported_lattice(int cells) {
  const FeModel fe = frame_lattice(cells, cells, 0.1, 0.1, square_section(2.1e11, 7850.0, 0.02));
  const SparseFeMatrices sparse = sparse_fe_matrices(fe, MassMatrixType::consistent);
  SparseFeModel model;
  model.M = sparse.M;
  model.K = sparse.K;
  for (int k = 0; k < fe.num_nodes(); ++k) {
    model.table.nodes.push_back(fe.nodes()[k]);
    model.table.dofs.push_back({3 * k, 3 * k + 1, 3 * k + 2});
  }
  return model;
}

// An integrator with a fixed step: the run from 0 to t_end, output only at the ends.
struct Stepper {
  double step = 0.0;
  std::function<Trajectory(double t_end)> run;
};

// Wall time of `steps` steps.
double run(const Stepper& stepper, int steps) {
  double elapsed = 0.0;
  Trajectory tr;
  elapsed = seconds([&] { tr = stepper.run(steps * stepper.step); });
  if (tr.steps != steps)
    throw std::logic_error("expected " + std::to_string(steps) + " steps, simulate took " + std::to_string(tr.steps));
  return elapsed;
}

// The marginal cost of a step: runs of s0 and s steps, s sized so that a run takes about
// `budget` seconds, (time(s) - time(s0)) / (s - s0); the best of three pairs, as other processes
// only ever add time.
double cost_per_step(const Stepper& o, double budget) {
  const int s0 = 3;
  run(o, s0);  // warm-up
  const double probe = run(o, 4 * s0) / (4 * s0);
  const int s = std::clamp(static_cast<int>(budget / probe), s0 + 10, 100000);
  double best = 1e300;
  for (int repeat = 0; repeat < 3; ++repeat) {
    const double t0 = run(o, s0), t1 = run(o, s);
    best = std::min(best, (t1 - t0) / (s - s0));
  }
  return std::max(best, 1e-12);
}

void bench_case(int cells, bool quick) {
  const double budget = quick ? 0.02 : 0.3;  // [s] per timed run
  const SparseFeModel model = imported_lattice(cells);
  const std::string name = "n=" + std::to_string(model.num_dofs());
  std::vector<int> interface;
  for (int k : {0, cells, cells * (cells + 1), cells * (cells + 1) + cells})
    for (NodeDof d : {NodeDof::ux, NodeDof::uy, NodeDof::psi}) interface.push_back(model.dof(k, d));

  ReducedBasis cb, basis;
  std::shared_ptr<const ModalFfrfBody> body;
  const double t_cb = seconds([&] { cb = sparse_craig_bampton(model.K, model.M, interface, 10); });
  const double t_ffrf = seconds([&] { basis = sparse_ffrf_basis(model, cb); });
  const double t_body = seconds([&] { body = make_sparse_modal_ffrf_body(model, basis); });
  const VecX lambda = basis.K_bar.diagonal();
  const double omega_max = std::sqrt(lambda.maxCoeff());
  row("reduction", name, "sparse_craig_bampton seconds", t_cb, "s");
  row("reduction", name, "sparse_ffrf_basis seconds", t_ffrf, "s");
  row("reduction", name, "make_sparse_modal_ffrf_body seconds", t_body, "s");
  row("reduction", name, "n_f", body->num_modes(), "1");
  row("reduction", name, "first elastic frequency", std::sqrt(lambda(3)) / kTwoPi, "Hz");
  row("reduction", name, "omega_max", omega_max, "rad/s");

  Model m;
  m.set_gravity(Vec2(0.0, -9.81));
  const BodyId b = m.add_flexible_body("lattice", body, frame_for_placement(model, Vec2::Zero(), 0.0));
  m.add_revolute("hinge", m.add_point(ground, Vec2::Zero(), "O"), m.add_node_point(b, 0, "corner"));
  const VecX q0 = m.initial_guess(), qd0 = VecX::Zero(m.num_coordinates());

  SimulationOptions rk4;
  rk4.integrator = Integrator::rk4;
  rk4.step = 1.0 / omega_max;
  rk4.output_interval = 1e9;
  const Stepper explicit_rk4{rk4.step, [&](double t_end) { return simulate(m, q0, qd0, 0.0, t_end, rk4); }};
  row("step", name, "rk4 cost_per_step", 1e6 * cost_per_step(explicit_rk4, budget), "us");
  const Stepper alpha{1e-3, [&](double t_end) { return generalized_alpha(m, q0, qd0, 0.0, t_end, 1e-3, {}, 1e9); }};
  row("step", name, "generalized_alpha cost_per_step", 1e6 * cost_per_step(alpha, budget), "us");
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  try {
    // n = 2883, 30 603, 101 568.
    const std::vector<int> cells = quick ? std::vector<int>{30} : std::vector<int>{30, 100, 183};
    for (int c : cells) bench_case(c, quick);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fmbd-bench-sparse_body: %s\n", e.what());
    return 1;
  }
  return 0;
}
