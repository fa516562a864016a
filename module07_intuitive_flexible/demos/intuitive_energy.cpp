// Module 7 demo: what the intuitive equations miss. A soft flexible pendulum released
// horizontally (lumped mass), simulated with module 7's equations. Two energies over time:
//   the model's own energy  1/2 q_dot^T M_bar q_dot + V, which its equations conserve, and
//   the true energy         1/2 v^T M_FE v + V, with v the absolute velocities of the FE nodes
//                           (module 7's node markers: v_k = G_k q_dot).
// Both use the same V (gravity and strain). The gap between them is the kinetic energy that the
// constant M_bar leaves out once the beam deforms and turns: the deformation-dependent mass
// matrix and the quadratic velocity forces of module 8. Both changes are shown as fractions of
// the energy the fall releases (the largest drop of V), so that a class sees their size.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>
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

// M_bar and K_bar of the beam's basis, as module 7 README section 3 shows their blocks: the frame
// block of M_bar is the rigid body's diag(m, m, J) and K_bar has no frame rows or columns. Entries
// below 1e-9 of the matrix's largest (round-off of the products with M_FE and K_FE) print as 0.
MatX without_round_off(const MatX& X) {
  const double threshold = 1e-9 * X.cwiseAbs().maxCoeff();
  return X.unaryExpr([threshold](double x) { return std::abs(x) < threshold ? 0.0 : x; });
}

void print_reduced_matrices(const FlexibleBodyData& d) {
  const Eigen::IOFormat format(4, 0, "  ", "\n", "    [", "]");
  std::printf("The beam's basis: %d free-free modes; m = %.4g kg, J = %.4g kg m^2 about the centroid\n"
              "(entries below 1e-9 of the largest print as 0: round-off).\n",
              d.num_modes(), d.mass, d.inertia);
  std::printf("M_bar = Phi^T M_FE Phi, in (R_x, R_y, theta, q_f) = diag(m, m, J, I):\n");
  std::cout << without_round_off(d.basis.M_bar).format(format) << "\n";
  std::printf("K_bar = Phi^T K_FE Phi = diag(0, 0, 0, omega_i^2) [1/s^2]:\n");
  std::cout << without_round_off(d.basis.K_bar).format(format) << "\n";
  std::printf("omega_i = ");
  for (int i = 0; i < d.num_modes(); ++i) std::printf("%s%.4g", i ? ", " : "", std::sqrt(d.basis.K_bar(3 + i, 3 + i)));
  std::printf(" rad/s\n\n");
}

const std::vector<demo::Parameter> parameters{
    {"young-modulus", "0.5", "GPa", "E of the beam (steel: 210)"},
    {"modes", "4", "", "elastic modes of the beam"},
    {"basis", "free-free", "",
     "its modes: free-free, or Craig-Bampton on the hinge node made M-orthogonal (a frame clamped at the hinge is "
     "module 8's: the intuitive form refuses it)",
     {"free-free", "craig-bampton"}},
    {"end-time", "4", "s", "simulated time"},
    {"rtol", "1e-10", "-", "relative tolerance of Dormand-Prince"},
};

BodyBasis basis_of(const std::string& word) {
  return word == "craig-bampton" ? BodyBasis::craig_bampton : BodyBasis::free_free_modes;
}

void energy(const demo::Options& options) {
  FlexiblePendulumParameters p;
  p.E = 1e9 * options.number("young-modulus");  // default: a soft (polymer-like) beam, so that it bends visibly
  p.rho = 1200.0;
  p.side = 0.02;
  p.mass_type = MassMatrixType::lumped;  // nodal_kinetic_energy needs it
  p.modes = options.integer("modes");
  p.basis = basis_of(options.text("basis"));
  const FlexibleExample ex = flexible_pendulum(p, make_intuitive_body);
  print_reduced_matrices(*ex.data);
  SimulationOptions o;
  o.integrator = Integrator::dormand_prince;
  o.rtol = options.number("rtol");
  o.atol = 1e-12;
  o.max_step = 1e-3;
  o.stabilisation = Stabilisation::projection;
  o.output_interval = 0.01;
  const Trajectory run = simulate(ex.model, ex.q0, ex.qd0, 0.0, options.number("end-time"), o);

  const auto model_energy = [&](std::size_t i) {
    return kinetic_energy(ex.model, run.q[i], run.qd[i]) + potential_energy(ex.model, run.q[i]);
  };
  const auto true_energy = [&](std::size_t i) {
    return nodal_kinetic_energy(ex, run.q[i], run.qd[i]) + potential_energy(ex.model, run.q[i]);
  };
  // The energy the fall releases: the largest drop of the potential energy (gravity and strain).
  double released = 0;
  for (std::size_t i = 0; i < run.t.size(); ++i)
    released = std::max(released, potential_energy(ex.model, run.q[0]) - potential_energy(ex.model, run.q[i]));
  if (released <= 0) throw std::runtime_error("the pendulum released no energy: nothing to compare with");
  demo::Table table{{"t [s]", "model_energy_change [J]", "true_energy_change [J]", "kinetic_energy_gap [J]",
                     "model_energy_change_per_released [-]", "true_energy_change_per_released [-]"},
                    {}};
  double worst_model = 0, worst_true = 0, low = 0, high = 0;
  for (std::size_t i = 0; i < run.t.size(); ++i) {
    const double dm = model_energy(i) - model_energy(0), dt = true_energy(i) - true_energy(0);
    worst_model = std::max(worst_model, std::abs(dm));
    worst_true = std::max(worst_true, std::abs(dt));
    low = std::min({low, dm, dt});
    high = std::max({high, dm, dt});
    table.add({run.t[i], dm, dt, true_energy(i) - model_energy(i), dm / released, dt / released});
  }
  std::printf("%d steps; the fall releases %.3f J; largest change of the model's energy %.3e J (%.1e of it), "
              "of the true energy %.3e J (%.1e of it)\n",
              run.steps, released, worst_model, worst_model / released, worst_true, worst_true / released);
  demo::write_csv(options, "intuitive_energy", table);

  demo::Figure figure(options, "intuitive_energy", 1000, 560);
  if (!figure.active()) return;
  char title[200], numbers[300];
  std::snprintf(title, sizeof title,
                "Flexible pendulum (1 m, 20 mm square, E = %g GPa, lumped mass, %d %s modes) with the intuitive "
                "equations of module 7",
                options.number("young-modulus"), p.modes, options.text("basis").c_str());
  std::snprintf(numbers, sizeof numbers,
                "the fall releases %.2f J\\nthe true energy changes by up to %.1f {/Symbol m}J = %.1f x 10^{-6} of it\\n"
                "the model's own energy by %.0e J",
                released, 1e6 * worst_true, 1e6 * worst_true / released, worst_model);
  figure.gp() << "set title '" << title << "'\n"
              << "set xlabel 't [s]'\nset ylabel '(E(t) - E(0)) / energy released  [10^{-6}]'\nset grid\n"
              << "set key bottom right opaque box\nset style textbox opaque\n"
              << "set label 1 \"" << numbers << "\" at graph 0.02, graph 0.95 front boxed\n"
              << "set yrange [" << 1e6 * (low - 0.2 * (high - low)) / released << ":"
              << 1e6 * (high + 0.6 * (high - low)) / released << "]\n"
              << "plot '-' u 1:($2*1e6) w l lw 2 lc rgb '#1f77b4' title 'the model''s energy, with its constant mass matrix (conserved)', "
              << "'-' u 1:($2*1e6) w l lw 2 lc rgb '#d62728' title 'the true energy, from the velocities of the FE nodes'\n";
  figure.send(table, {0, 4});
  figure.send(table, {0, 5});
}

}  // namespace

int main(int argc, char** argv) { return demo::run(argc, argv, "intuitive_energy", parameters, energy); }
