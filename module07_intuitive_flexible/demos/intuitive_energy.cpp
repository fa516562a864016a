// Module 7 demo: what the intuitive equations miss. A soft flexible pendulum released
// horizontally (lumped mass), simulated with module 7's equations. Two energies over time:
//   the model's own energy  1/2 q_dot^T M_bar q_dot + V, which its equations conserve, and
//   the true energy         1/2 v^T M_FE v + V, with v the absolute velocities of the FE nodes
//                           (module 7's node markers: v_k = G_k q_dot).
// Both use the same V (gravity and strain). The gap between them is the kinetic energy that the
// constant M_bar leaves out once the beam deforms and turns: the deformation-dependent mass
// matrix and the quadratic velocity forces of module 8.
#include <cmath>
#include <cstdio>
#include <gnuplot-iostream.h>

#include "demo.hpp"
#include "fmbd/energy.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/simulation.hpp"

namespace {

using namespace fmbd;

// 1/2 v^T M_FE v over the nodes. A lumped M_FE has the same mass in x and y at every node, so
// it holds for velocities in the global frame as well as in the body frame.
double nodal_kinetic_energy(const FlexibleExample& ex, const VecX& q, const VecX& qd) {
  const Body& body = ex.model.body(ex.flexible);
  const VecX q_b = ex.model.body_state(q, ex.flexible), qd_b = ex.model.body_state(qd, ex.flexible);
  const int nodes = body.deformable->num_nodes();
  VecX v(3 * nodes);
  for (int k = 0; k < nodes; ++k) v.segment<3>(3 * k) = body.deformable->node_marker(k, q_b, qd_b).velocity;
  return 0.5 * v.dot(ex.data->matrices.M * v);
}

void energy(const demo::Options& options) {
  FlexiblePendulumParameters p;
  p.E = 5e8;  // a soft (polymer-like) beam, so that it bends visibly
  p.rho = 1200.0;
  p.side = 0.02;
  p.mass_type = MassMatrixType::lumped;
  const FlexibleExample ex = flexible_pendulum(p, make_intuitive_body);
  SimulationOptions o;
  o.integrator = Integrator::dormand_prince;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  o.max_step = 1e-3;
  o.stabilisation = Stabilisation::projection;
  o.output_interval = 0.01;
  const Trajectory run = simulate(ex.model, ex.q0, ex.qd0, 0.0, 4.0, o);

  const auto model_energy = [&](std::size_t i) {
    return kinetic_energy(ex.model, run.q[i], run.qd[i]) + potential_energy(ex.model, run.q[i]);
  };
  const auto true_energy = [&](std::size_t i) {
    return nodal_kinetic_energy(ex, run.q[i], run.qd[i]) + potential_energy(ex.model, run.q[i]);
  };
  demo::Table table{{"t [s]", "model_energy_change [J]", "true_energy_change [J]", "kinetic_energy_gap [J]"}, {}};
  double worst_model = 0, worst_true = 0;
  for (std::size_t i = 0; i < run.t.size(); ++i) {
    const double dm = model_energy(i) - model_energy(0), dt = true_energy(i) - true_energy(0);
    worst_model = std::max(worst_model, std::abs(dm));
    worst_true = std::max(worst_true, std::abs(dt));
    table.add({run.t[i], dm, dt, true_energy(i) - model_energy(i)});
  }
  std::printf("%d steps; largest change of the model's energy %.3e J, of the true energy %.3e J\n", run.steps,
              worst_model, worst_true);
  demo::write_csv(options, "intuitive_energy", table);

  demo::Figure figure(options, "intuitive_energy", 1000, 520);
  if (!figure.active()) return;
  figure.gp() << "set title 'Flexible pendulum (1 m, 20 mm square, E = 0.5 GPa, lumped mass) with the intuitive "
                 "equations of module 7'\n"
              << "set xlabel 't [s]'\nset ylabel 'E(t) - E(0) [J]'\nset grid\nset key top left opaque box\n"
              << "plot '-' w l lw 2 lc rgb '#1f77b4' title 'the model''s energy, with its constant mass matrix (conserved)', "
              << "'-' w l lw 2 lc rgb '#d62728' title 'the true energy, from the velocities of the FE nodes'\n";
  figure.send(table, {0, 1});
  figure.send(table, {0, 2});
}

}  // namespace

int main(int argc, char** argv) { return demo::run(argc, argv, "intuitive_energy", energy); }
