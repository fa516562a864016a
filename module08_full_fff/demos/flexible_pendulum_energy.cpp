// Module 8 demo: a flexible pendulum released horizontally. Its true mechanical energy (the FE
// kinetic energy of the nodes, module 8's M(q), plus gravity and strain energy) over time, with the
// intuitive equations (module 7) and the full FFRF (module 8), lumped and consistent mass.
#include <cmath>
#include <cstdio>
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

void energy(const demo::Options& options) {
  FlexiblePendulumParameters p;
  p.E = 5e8;  // a soft (polymer-like) beam, so that it bends visibly
  p.rho = 1200.0;
  p.side = 0.02;
  demo::Table table{{"t [s]", "module7_lumped [J]", "module8_lumped [J]", "module8_consistent [J]"}, {}};
  std::vector<std::vector<double>> columns;
  std::vector<double> t;
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
    o.rtol = 1e-10;
    o.atol = 1e-12;
    o.max_step = 1e-3;
    o.stabilisation = Stabilisation::projection;
    o.output_interval = 0.01;
    const Trajectory run = simulate(ex.model, ex.q0, ex.qd0, 0.0, 4.0, o);
    std::vector<double> e;
    for (std::size_t i = 0; i < run.t.size(); ++i)
      e.push_back(std::max(std::abs(true_energy(ex, run.q[i], run.qd[i]) - true_energy(ex, run.q[0], run.qd[0])), 1e-16));
    double worst = 0;
    for (double x : e) worst = std::max(worst, std::abs(x));
    std::printf("%-22s %6d steps, largest change of the true energy %.3e J\n", r.name, run.steps, worst);
    columns.push_back(e);
    t = run.t;
  }
  for (std::size_t i = 0; i < t.size(); ++i) {
    std::vector<double> row{t[i]};
    for (const auto& c : columns) row.push_back(i < c.size() ? c[i] : std::nan(""));
    table.add(row);
  }
  demo::write_csv(options, "pendulum_energy", table);

  demo::Figure figure(options, "pendulum_energy", 1000, 520);
  if (!figure.active()) return;
  figure.gp() << "set title 'Flexible pendulum (1 m, 20 mm square, E = 0.5 GPa) released horizontally: change of the true energy'\n"
              << "set xlabel 't [s]'\nset ylabel '|E(t) - E(0)| [J]'\nset logscale y\nset format y '10^{%T}'\n"
              << "set yrange [1e-16:1e-2]\nset grid\nset key top left opaque box\n"
              << "plot '-' w l lw 2 lc rgb '#1f77b4' title 'module 7 (intuitive), lumped mass', "
              << "'-' w l lw 2 lc rgb '#d62728' title 'module 8 (FFRF), lumped mass', "
              << "'-' w l lw 2 dt 2 lc rgb '#2ca02c' title 'module 8 (FFRF), consistent mass'\n";
  for (int c = 1; c <= 3; ++c) figure.send(table, {0, c});
}

}  // namespace

int main(int argc, char** argv) { return demo::run(argc, argv, "flexible_pendulum_energy", energy); }
