// Module 4 demo: a pendulum integrated with a coarse RK4 step three ways -- no stabilisation,
// Baumgarte, coordinate projection -- with its energy error and constraint drift side by side;
// and an animation of a double pendulum (tasks M04T1-T4).
#include <cmath>
#include <cstdio>
#include <gnuplot-iostream.h>

#include "demo.hpp"
#include "fmbd/simulation.hpp"

namespace {

using namespace fmbd;

// Chain of uniform rods (length L, mass 1 kg) hinged end to end, the first to the ground at
// the origin, all horizontal along +x at the start, under gravity.
Model rod_chain(int rods, double L) {
  Model m;
  m.set_gravity(Vec2(0.0, -9.81));
  PointId previous = m.add_point(ground, Vec2::Zero(), "O");
  for (int k = 0; k < rods; ++k) {
    const std::string name = "rod " + std::to_string(k + 1);
    const BodyId b = m.add_body(name, 1.0, L * L / 12, Vec3((k + 0.5) * L, 0.0, 0.0));
    m.add_revolute("hinge " + std::to_string(k + 1), previous, m.add_point(b, Vec2(-L / 2, 0), name + " start"));
    previous = m.add_point(b, Vec2(L / 2, 0), name + " end");
  }
  return m;
}

void stabilisation_comparison(const demo::Options& options) {
  const Model pendulum = rod_chain(1, 1.0);
  const char* names[] = {"none", "Baumgarte (alpha = beta = 10)", "projection"};
  const Stabilisation kinds[] = {Stabilisation::none, Stabilisation::baumgarte, Stabilisation::projection};
  demo::Table table{{"t [s]", "energy_error_none [J]", "energy_error_baumgarte [J]", "energy_error_projection [J]",
                     "drift_none [m]", "drift_baumgarte [m]", "drift_projection [m]"},
                    {}};
  std::vector<Trajectory> runs;
  for (int k = 0; k < 3; ++k) {
    SimulationOptions o;
    o.integrator = Integrator::rk4;
    o.step = 0.02;
    o.stabilisation = kinds[k];
    runs.push_back(simulate(pendulum, pendulum.initial_guess(), VecX::Zero(3), 0.0, 20.0, o));
    std::printf("%-30s energy error %9.2e J, |C| at the end %9.2e m\n", names[k],
                runs.back().energy.back() - runs.back().energy.front(), runs.back().position_drift.back());
  }
  for (std::size_t i = 0; i < runs[0].t.size(); ++i) {
    std::vector<double> row{runs[0].t[i]};
    for (const Trajectory& r : runs) row.push_back(r.energy[i] - r.energy.front());
    for (const Trajectory& r : runs) row.push_back(std::max(r.position_drift[i], 1e-17));
    table.add(row);
  }
  demo::write_csv(options, "pendulum_stabilisation", table);

  demo::Figure figure(options, "pendulum_stabilisation", 1100, 500);
  if (!figure.active()) return;
  Gnuplot& gp = figure.gp();
  gp << "set multiplot layout 1,2 title 'Pendulum (uniform rod, L = 1 m), RK4 with h = 0.02 s'\n"
     << "set xlabel 't [s]'\nset key top left\n"
     << "set ylabel 'E(t) - E(0) [J]'\nset title 'energy error'\n"
     << "plot '-' w l lw 2 title 'none', '-' w l lw 2 title 'Baumgarte', '-' w l lw 2 title 'projection'\n";
  for (int c = 1; c <= 3; ++c) figure.send(table, {0, c});
  gp << "set logscale y\nset format y '10^{%T}'\nset ylabel '|C(q)| [m]'\nset title 'constraint drift'\n"
     << "set key top left\n"
     << "plot '-' w l lw 2 title 'none', '-' w l lw 2 title 'Baumgarte', '-' w l lw 2 title 'projection'\n";
  for (int c = 4; c <= 6; ++c) figure.send(table, {0, c});
  gp << "unset multiplot\n";
}

void double_pendulum_animation(const demo::Options& options) {
  const Model chain = rod_chain(2, 1.0);
  SimulationOptions o;
  o.integrator = Integrator::rk4;
  o.step = 1e-3;
  o.stabilisation = Stabilisation::projection;
  o.output_interval = 0.01;  // the path at 100 Hz; every 4th point is an animation frame
  const Trajectory run = simulate(chain, chain.initial_guess(), VecX::Zero(6), 0.0, 8.0, o);
  std::printf("double pendulum: %d steps, energy error %.2e J, largest |C| %.2e m\n", run.steps,
              run.energy.back() - run.energy.front(),
              *std::max_element(run.position_drift.begin(), run.position_drift.end()));

  demo::Table tips{{"t [s]", "x_tip [m]", "y_tip [m]"}, {}};
  for (std::size_t i = 0; i < run.t.size(); ++i) {
    const VecX& q = run.q[i];
    const Vec2 tip = q.segment<2>(3) + Vec2(std::cos(q(5)), std::sin(q(5))) * 0.5;
    tips.add({run.t[i], tip.x(), tip.y()});
  }
  demo::write_csv(options, "double_pendulum", tips);

  demo::Figure figure(options, "double_pendulum", 500, 500, demo::Format::gif_animation);
  if (!figure.active()) return;
  Gnuplot& gp = figure.gp();
  gp << "set size ratio -1\nset xrange [-2.2:2.2]\nset yrange [-2.2:1.2]\nunset key\nset grid\n";
  for (std::size_t i = 0; i < run.t.size(); i += 4) {
    const VecX& q = run.q[i];
    const Vec2 elbow = q.segment<2>(0) * 2.0;  // the first rod's centroid is its middle
    const Vec2 tip = tips.rows[i][1] * Vec2::UnitX() + tips.rows[i][2] * Vec2::UnitY();
    gp << "set title sprintf('Double pendulum, t = %.2f s', " << run.t[i] << ")\n"
       << "plot '-' with lines lc rgb '#bbbbbb' lw 1, '-' with linespoints lw 4 pt 7 ps 1.5 lc rgb '#1f77b4'\n";
    for (std::size_t j = 0; j <= i; ++j) gp << tips.rows[j][1] << ' ' << tips.rows[j][2] << '\n';
    gp << "e\n0 0\n" << elbow.x() << ' ' << elbow.y() << '\n' << tip.x() << ' ' << tip.y() << "\ne\n";
    figure.end_frame(0.04);
  }
  // A still of the whole tip path next to the animation.
  demo::Figure still(options, "double_pendulum_path", 600, 600);
  if (!still.active()) return;
  still.gp() << "set size ratio -1\nset title 'Double pendulum (two uniform rods, L = 1 m): path of the tip over 8 s'\n"
             << "set xlabel 'x [m]'\nset ylabel 'y [m]'\nunset key\n"
             << "plot '-' with lines lw 1.5 lc rgb '#1f77b4'\n";
  still.send(tips, {1, 2});
}

}  // namespace

int main(int argc, char** argv) {
  return demo::run(argc, argv, "stabilisation", [](const demo::Options& options) {
    stabilisation_comparison(options);
    double_pendulum_animation(options);
  });
}
