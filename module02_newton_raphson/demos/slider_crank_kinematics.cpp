// Module 2 demo: slider position, velocity and acceleration over one crank turn, from the
// kinematic analysis (tasks M02T1-T6) against the closed form
//   x = r cos A + sqrt(l^2 - r^2 sin^2 A),  x_dot = x'(A) omega,  x_ddot = x''(A) omega^2.
#include <cmath>
#include <cstdio>
#include <gnuplot-iostream.h>

#include "demo.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/kinematic_analysis.hpp"

int main(int argc, char** argv) {
  using namespace fmbd;
  return demo::run(argc, argv, "slider_crank_kinematics", [](const demo::Options& options) {
    examples::SliderCrankParameters p;  // r = 0.1 m, l = 0.3 m, omega = 2 rad/s
    const Model model = examples::slider_crank(p);
    const int steps = 72;
    const double period = 2 * M_PI / p.omega;
    std::vector<double> times;
    for (int k = 0; k <= steps; ++k) times.push_back(period * k / steps);
    const KinematicSolution sol = kinematic_analysis(model, model.initial_guess(), times);

    demo::Table table{{"crank_angle [deg]", "x_numeric [m]", "x_closed_form [m]", "v_numeric [m/s]", "v_closed_form [m/s]",
                       "a_numeric [m/s^2]", "a_closed_form [m/s^2]"},
                      {}};
    double worst = 0;
    for (std::size_t k = 0; k < times.size(); ++k) {
      const double A = p.A0 + p.omega * times[k];
      const auto cf = examples::slider_crank_closed_form(p.r, p.l, A);
      const double x = sol.q[k](6), v = sol.qd[k](6), a = sol.qdd[k](6);
      table.add({A * 180 / M_PI, x, cf.x, v, cf.dx_dA * p.omega, a, cf.d2x_dA2 * p.omega * p.omega});
      worst = std::max({worst, std::abs(x - cf.x), std::abs(v - cf.dx_dA * p.omega),
                        std::abs(a - cf.d2x_dA2 * p.omega * p.omega)});
    }
    std::printf("slider-crank over one turn: largest deviation from the closed form %.2e\n", worst);
    demo::write_csv(options, "slider_crank_kinematics", table);

    demo::Figure figure(options, "slider_crank_kinematics", 1000, 900);
    if (!figure.active()) return;
    Gnuplot& gp = figure.gp();
    gp << "set multiplot layout 3,1 title 'Slider-crank (r = 0.1 m, l = 0.3 m, omega = 2 rad/s): "
          "kinematic analysis vs closed form'\n"
       << "set xrange [0:360]\nset xtics 45\nset key outside top center horizontal\n";
    const char* labels[] = {"x [m]", "dx/dt [m/s]", "d^2x/dt^2 [m/s^2]"};
    for (int panel = 0; panel < 3; ++panel) {
      gp << "set ylabel '" << labels[panel] << "'\n" << (panel > 0 ? "unset key\n" : "")
         << (panel == 2 ? "set xlabel 'crank angle A [deg]'\n" : "unset xlabel\n")
         << "plot '-' with lines lw 2 lc rgb '#1f77b4' title 'closed form', "
            "'-' with points pt 7 ps 0.7 lc rgb '#d62728' title 'Newton-Raphson + eq. (2)'\n";
      figure.send(table, {0, 2 + 2 * panel});
      figure.send(table, {0, 1 + 2 * panel});
    }
    gp << "unset multiplot\n";
  });
}
