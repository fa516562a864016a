// Module 3 demo: inverse dynamics of a driven slider-crank with gravity and a spring on the
// slider. Driver torque and the magnitude of every joint's reaction force over one crank turn
// (tasks M03T1-T5), and the power balance driver power = dE/dt as a check.
#include <cmath>
#include <cstdio>
#include <gnuplot-iostream.h>

#include "demo.hpp"
#include "fmbd/energy.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/inverse_dynamics.hpp"
#include "fmbd/reactions.hpp"

int main(int argc, char** argv) {
  using namespace fmbd;
  return demo::run(argc, argv, "slider_crank_reactions", [](const demo::Options& options) {
    examples::SliderCrankParameters p;  // r = 0.1 m, l = 0.3 m
    p.omega = 4.0;
    Model model = examples::slider_crank(p);
    model.set_gravity(Vec2(0.0, -9.81));
    model.add_tsda("return spring", model.find_point("O"), model.find_point("slider C"), 400.0, 0.25, 0.0);

    const int steps = 144;
    std::vector<double> times;
    for (int k = 0; k <= steps; ++k) times.push_back(2 * M_PI / p.omega * k / steps);
    const InverseDynamicsSolution sol = inverse_dynamics(model, model.initial_guess(), times);

    demo::Table table{{"crank_angle [deg]", "driver_torque [N m]", "F_O [N]", "F_B [N]", "F_C [N]", "F_guide [N]",
                       "driver_power [W]", "dE_dt [W]"},
                      {}};
    double worst = 0;
    for (std::size_t k = 0; k < times.size(); ++k) {
      const VecX& q = sol.kinematics.q[k];
      const VecX& lambda = sol.lambda[k];
      std::vector<double> row{(p.A0 + p.omega * times[k]) * 180 / M_PI, driver_effort(model, 4, q, lambda)};
      for (int joint = 0; joint < 4; ++joint) row.push_back(joint_reaction(model, joint, q, lambda).on_j.force.norm());
      // Power balance by central differences of E = T + V between neighbouring samples.
      double dE_dt = NAN;
      if (k > 0 && k + 1 < times.size()) {
        auto E = [&](std::size_t i) {
          return kinetic_energy(model, sol.kinematics.qd[i]) + potential_energy(model, sol.kinematics.q[i]);
        };
        dE_dt = (E(k + 1) - E(k - 1)) / (times[k + 1] - times[k - 1]);
      }
      row.push_back(row[1] * p.omega);
      row.push_back(dE_dt);
      if (std::isfinite(dE_dt)) worst = std::max(worst, std::abs(row[6] - dE_dt));
      table.add(row);
    }
    std::printf("largest |driver power - dE/dt| (central differences, dt = %.3g s): %.3g W\n",
                times[1] - times[0], worst);
    demo::write_csv(options, "slider_crank_reactions", table);

    demo::Figure figure(options, "slider_crank_reactions", 1000, 1000);
    if (!figure.active()) return;
    Gnuplot& gp = figure.gp();
    gp << "set multiplot layout 3,1 title 'Driven slider-crank (omega = 4 rad/s, gravity, spring k = 400 N/m): "
          "inverse dynamics'\n"
       << "set xrange [0:360]\nset xtics 45\nset key outside right top vertical\nset lmargin 12\nset rmargin 22\n"
       << "set ylabel 'driver torque [N m]'\nunset xlabel\n"
       << "plot '-' with lines lw 2 lc rgb '#1f77b4' title 'driver torque'\n";
    figure.send(table, {0, 1});
    gp << "set ylabel '|reaction force| [N]'\n"
       << "plot '-' with lines lw 2 title 'joint O', '-' with lines lw 2 title 'joint B', "
          "'-' with lines lw 2 title 'joint C', '-' with lines lw 2 dt 2 title 'slider guide'\n";
    for (int c = 2; c <= 5; ++c) figure.send(table, {0, c});
    gp << "set ylabel 'power [W]'\nset xlabel 'crank angle [deg]'\n"
       << "plot '-' with lines lw 2 lc rgb '#1f77b4' title 'driver power', "
          "'-' with points pt 7 ps 0.5 lc rgb '#d62728' title 'dE/dt'\n";
    figure.send(table, {0, 6});
    demo::Table balance{table.columns, {}};
    for (const auto& row : table.rows)
      if (std::isfinite(row[7])) balance.add(row);
    figure.send(balance, {0, 7});
    gp << "unset multiplot\n";
  });
}
