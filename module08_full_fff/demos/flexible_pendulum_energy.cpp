// Module 8 demo: a flexible pendulum released horizontally. Its true mechanical energy (the FE
// kinetic energy of the nodes, module 8's M(q), plus gravity and strain energy) over time, with the
// intuitive equations (module 7) and the full FFRF (module 8), lumped and consistent mass, as a
// fraction of the energy the fall releases (the largest drop of V). With consistent mass the nodal
// form of module 8 is not exactly Lagrangian (README section 2): the figure names that.
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>
#include <gnuplot-iostream.h>

#include "demo.hpp"
#include "fmbd/energy.hpp"
#include "fmbd/ffrf.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/simulation.hpp"

namespace {

using namespace fmbd;

// The true energy of a state: module 8's kinetic energy and the potential energy.
double true_energy(const FlexibleExample& ex, const VecX& q, const VecX& qd) {
  const BodyId b = ex.flexible;
  const VecX q_b = ex.model.body_state(q, b), qd_b = ex.model.body_state(qd, b);
  return 0.5 * qd_b.dot(ffrf_mass_matrix(*ex.data, q_b) * qd_b) + potential_energy(ex.model, q);
}

const std::vector<demo::Parameter> parameters{
    {"young-modulus", "0.5", "GPa", "E of the beam (steel: 210)"},
    {"modes", "4", "", "elastic modes of the beam"},
    {"basis", "free-free", "",
     "its modes: free-free, or Craig-Bampton on the hinge node made M-orthogonal (module 7 refuses a frame clamped "
     "at the hinge)",
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
  p.modes = options.integer("modes");
  p.basis = basis_of(options.text("basis"));
  demo::Table table{{"t [s]", "module7_lumped [J]", "module8_lumped [J]", "module8_consistent [J]",
                     "module7_lumped_per_released [-]", "module8_lumped_per_released [-]",
                     "module8_consistent_per_released [-]"},
                    {}};
  std::vector<std::vector<double>> columns;
  std::vector<double> t, worst(3, 0.0);
  double released = 0;
  struct Run {
    const char* name;
    BodyFactory make;
    MassMatrixType mass;
  };
  const Run runs[3] = {{"module 7, lumped", make_intuitive_body, MassMatrixType::lumped},
                       {"module 8, lumped", make_ffrf_body, MassMatrixType::lumped},
                       {"module 8, consistent", make_ffrf_body, MassMatrixType::consistent}};
  for (const Run& r : runs) {
    p.mass_type = r.mass;
    const FlexibleExample ex = flexible_pendulum(p, r.make);
    SimulationOptions o;
    o.integrator = Integrator::dormand_prince;
    o.rtol = options.number("rtol");
    o.atol = 1e-12;
    o.max_step = 1e-3;
    o.stabilisation = Stabilisation::projection;
    o.output_interval = 0.01;
    const Trajectory run = simulate(ex.model, ex.q0, ex.qd0, 0.0, options.number("end-time"), o);
    for (const VecX& q : run.q)  // the same fall in each run, to within a fraction of a mm
      released = std::max(released, potential_energy(ex.model, run.q[0]) - potential_energy(ex.model, q));
    std::vector<double> e;
    for (std::size_t i = 0; i < run.t.size(); ++i)
      e.push_back(std::max(std::abs(true_energy(ex, run.q[i], run.qd[i]) - true_energy(ex, run.q[0], run.qd[0])), 1e-16));
    double& largest = worst[columns.size()];
    for (double x : e) largest = std::max(largest, std::abs(x));
    std::printf("%-22s %6d steps, largest change of the true energy %.3e J\n", r.name, run.steps, largest);
    columns.push_back(e);
    t = run.t;
  }
  if (released <= 0) throw std::runtime_error("the pendulum released no energy: nothing to compare with");
  std::printf("the fall releases %.3f J; largest changes per energy released: %.1e, %.1e, %.1e\n", released,
              worst[0] / released, worst[1] / released, worst[2] / released);
  for (std::size_t i = 0; i < t.size(); ++i) {
    std::vector<double> row{t[i]};
    for (const auto& c : columns) row.push_back(i < c.size() ? c[i] : std::nan(""));
    for (const auto& c : columns) row.push_back(i < c.size() ? c[i] / released : std::nan(""));
    table.add(row);
  }
  demo::write_csv(options, "pendulum_energy", table);

  demo::Figure figure(options, "pendulum_energy", 1000, 560);
  if (!figure.active()) return;
  char title[200], numbers[400], keys[3][160];
  std::snprintf(title, sizeof title,
                "Flexible pendulum (1 m, 20 mm square, E = %g GPa, %d %s modes) released horizontally: change of the true energy",
                options.number("young-modulus"), p.modes, options.text("basis").c_str());
  std::snprintf(numbers, sizeof numbers,
                "the fall releases %.2f J; the largest change of the true energy per energy released:\\n"
                "module 7: %.1e (%.1f {/Symbol m}J);   module 8, lumped: %.1e;   module 8, consistent: %.1e (%.1f {/Symbol m}J)",
                released, worst[0] / released, 1e6 * worst[0], worst[1] / released, worst[2] / released,
                1e6 * worst[2]);
  std::snprintf(keys[0], sizeof keys[0], "module 7 (intuitive), lumped mass: constant mass matrix, no Q_v");
  std::snprintf(keys[1], sizeof keys[1], "module 8 (FFRF), lumped mass: conserved to the tolerance");
  std::snprintf(keys[2], sizeof keys[2],
                "module 8 (FFRF), consistent mass: its inertia is not exactly Lagrangian (README sec. 2)");
  figure.gp() << "set title '" << title << "'\n"
              << "set xlabel 't [s]'\nset ylabel '|E(t) - E(0)| / energy released'\nset logscale y\nset format y '10^{%T}'\n"
              << "set yrange [1e-20:1e-1]\nset grid\nset key bottom right opaque box width -14\nset style textbox opaque\n"
              << "set label 1 \"" << numbers << "\" at graph 0.02, graph 0.95 front boxed\n"
              << "plot '-' w l lw 2 lc rgb '#1f77b4' title '" << keys[0] << "' noenhanced, "
              << "'-' w l lw 2 lc rgb '#d62728' title '" << keys[1] << "' noenhanced, "
              << "'-' w l lw 2 dt 2 lc rgb '#2ca02c' title '" << keys[2] << "' noenhanced\n";
  for (int c = 4; c <= 6; ++c) figure.send(table, {0, c});
}

}  // namespace

int main(int argc, char** argv) { return demo::run(argc, argv, "flexible_pendulum_energy", parameters, energy); }
