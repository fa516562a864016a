// Module 8 demo: module 7 against module 8 on the simplest case there is. A free beam (no joints,
// no gravity) starts undeformed, spinning at Omega about its centroid. Its elongation over time:
//   module 7 (constant M_bar, no quadratic velocity forces): no centrifugal force, no stretch;
//   module 8 (M(q), Q_v): the beam stretches and oscillates about the centrifugal stretch.
// The oracle is the static FE solution under the centrifugal load in the rotating frame,
//   K u = Omega^2 M_FE P (X + u)    (P: the translational DOFs, X: the nodal positions),
// solved in the same reduced basis (the fair comparison), on the whole mesh with the frame kept at
// the centroid, and in closed form for a uniform rod spinning about its middle,
//   u(x) = rho Omega^2 / (6 E) x (3 (L/2)^2 - x^2),   elongation rho Omega^2 L^3 / (12 E).
#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <gnuplot-iostream.h>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "demo.hpp"
#include "fmbd/fe_assembly.hpp"
#include "fmbd/ffrf.hpp"
#include "fmbd/flexible_body.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/marker.hpp"
#include "fmbd/simulation.hpp"

namespace {

using namespace fmbd;

// Beam: 1 m, 20 mm square, the soft polymer of the pendulum demos.
constexpr double length = 1.0, side = 0.02, E = 5e8, rho = 1200.0;

const std::vector<demo::Parameter> parameters{
    {"spin-rate", "30", "rad/s", "spin rate Omega at t = 0 (first free-free bending mode: 83 rad/s)"},
    {"axial-modes", "1", "", "free-free axial modes kept (the 1st, 3rd, ... stretch the beam)"},
    {"bending-modes", "2", "", "free-free bending modes kept"},
    {"mass", "consistent", "", "FE mass matrix", {"consistent", "lumped"}},
    {"elements", "10", "", "beam elements"},
    {"end-time", "0.1", "s", "simulated time"},
    {"rtol", "1e-8", "-", "relative tolerance of Dormand-Prince"},
};

// Stacked nodal positions X (psi rows 0) and the projection P on the translational DOFs.
VecX positions(const FeModel& fe) {
  VecX X = VecX::Zero(fe.num_dofs());
  for (int k = 0; k < fe.num_nodes(); ++k) X.segment<2>(dof_index(k, NodeDof::ux)) = fe.nodes()[k];
  return X;
}
MatX translational(int n) {
  MatX P = MatX::Zero(n, n);
  for (int d = 0; d < n; d += 3) P.block<2, 2>(d, d).setIdentity();
  return P;
}

// Elongation of the static displacement u: the end nodes' distance minus the length.
double elongation(const FeModel& fe, const VecX& u) {
  const int last = fe.num_nodes() - 1;
  const Vec2 a = fe.nodes()[0] + u.segment<2>(dof_index(0, NodeDof::ux));
  const Vec2 b = fe.nodes()[last] + u.segment<2>(dof_index(last, NodeDof::ux));
  return (b - a).norm() - length;
}

// The oracles of the elongation [m]: the static FE stretch under the centrifugal load in the
// body's reduced basis, on the whole mesh, and the closed form of a uniform rod.
struct StaticStretch {
  double basis = 0, mesh = 0, closed_form = 0;
};

StaticStretch static_stretch(const FeModel& fe, const FeMatrices& fm, const FlexibleBodyData& data, double Omega) {
  // (The FE model is centred already: its nodes are those of data.fe.)
  StaticStretch out;
  const double W = Omega * Omega;
  const MatX P = translational(fe.num_dofs());
  const VecX load = W * fm.M * P * positions(fe);
  const MatX& Phi_f = data.Phi_f;
  const VecX q_static = (Phi_f.transpose() * (fm.K - W * fm.M * P) * Phi_f).fullPivLu().solve(Phi_f.transpose() * load);
  out.basis = elongation(fe, Phi_f * q_static);
  // The whole mesh, its rigid motions held by multipliers: Phi_r^T M u = 0 keeps the frame at the centroid.
  const int n = fe.num_dofs();
  const MatX Phi_r = data.basis.Phi.leftCols(3);
  MatX A = MatX::Zero(n + 3, n + 3);
  A.topLeftCorner(n, n) = fm.K - W * fm.M * P;
  A.topRightCorner(n, 3) = fm.M * Phi_r;
  A.bottomLeftCorner(3, n) = Phi_r.transpose() * fm.M;
  VecX rhs = VecX::Zero(n + 3);
  rhs.head(n) = load;
  out.mesh = elongation(fe, A.fullPivLu().solve(rhs).head(n));
  out.closed_form = rho * W * std::pow(length, 3) / (12.0 * E);
  return out;
}

// The elongation over time of the beam with module 7's body (stretch[0]) and module 8's
// (stretch[1]), both from the same state: undeformed, spinning at Omega. `t`: the output times.
std::vector<std::vector<double>> simulate_both(const std::shared_ptr<const FlexibleBodyData>& data, int elements,
                                               double Omega, double t_end, double rtol, std::vector<double>& t) {
  SimulationOptions o;
  o.integrator = Integrator::dormand_prince;
  o.rtol = rtol;
  o.atol = 1e-12;
  o.step = 1e-5;
  o.max_step = 1e-3;
  o.output_interval = 1e-4;
  std::vector<std::vector<double>> stretch(2);
  const BodyFactory makes[2] = {make_intuitive_body, make_ffrf_body};
  for (int f = 0; f < 2; ++f) {
    Model model;
    const BodyId beam = model.add_flexible_body("beam", makes[f](data));
    const PointId left = model.add_node_point(beam, 0, "left end");
    const PointId right = model.add_node_point(beam, elements, "right end");
    VecX q0 = VecX::Zero(model.num_coordinates()), qd0 = q0;
    qd0(model.offset(beam) + 2) = Omega;
    const Trajectory run = simulate(model, q0, qd0, 0.0, t_end, o);
    for (const VecX& q : run.q)
      stretch[f].push_back((point_position(model, right, q) - point_position(model, left, q)).norm() - length);
    t = run.t;
    std::printf("module %d: %d steps\n", f == 0 ? 7 : 8, run.steps);
  }
  return stretch;
}

// Module 8's mean over its whole oscillations: from t = 0 (undeformed, a minimum) to its last
// local minimum (the index `end`), by the trapezoidal rule.
struct OscillationMean {
  double mean = 0;
  std::size_t end = 0;
};

OscillationMean mean_over_oscillations(const std::vector<double>& s8, const std::vector<double>& t) {
  std::size_t end = 0;
  for (std::size_t i = 1; i + 1 < s8.size(); ++i)
    if (s8[i] <= s8[i - 1] && s8[i] < s8[i + 1]) end = i;
  if (end == 0) throw std::runtime_error("module 8 did not complete one oscillation: a longer --end-time");
  double area = 0;
  for (std::size_t i = 1; i <= end; ++i) area += 0.5 * (s8[i] + s8[i - 1]) * (t[i] - t[i - 1]);
  return {area / t[end], end};
}

// The figure: both elongations, the static FE stretch in the same basis and module 8's mean, with
// the numbers in a box.
void plot_stretch(const demo::Options& options, const demo::Table& table, double Omega, const StaticStretch& oracle,
                  double mean8, double t_mean, double largest7, double percent) {
  demo::Figure figure(options, "spinning_beam", 1000, 560);
  if (!figure.active()) return;
  char title[200], numbers[400], mean_title[80];
  std::snprintf(title, sizeof title,
                "Free beam spinning at %g rad/s (1 m, 20 mm square, E = 0.5 GPa, %s mass, %d axial + %d bending modes)",
                Omega, options.text("mass").c_str(), options.integer("axial-modes"), options.integer("bending-modes"));
  std::snprintf(numbers, sizeof numbers,
                "module 8: mean stretch %.1f {/Symbol m}m, static FE (same basis): %.1f {/Symbol m}m (%+.2f %%)\\n"
                "module 7: %.0f {/Symbol m}m (no centrifugal force)\\n"
                "static FE, whole mesh: %.1f {/Symbol m}m;  closed form {/Symbol r}{/Symbol W}^2L^3/12E: %.1f {/Symbol m}m",
                1e6 * mean8, 1e6 * oracle.basis, percent, 1e6 * largest7, 1e6 * oracle.mesh, 1e6 * oracle.closed_form);
  std::snprintf(mean_title, sizeof mean_title, "module 8, mean over %.1f ms", 1e3 * t_mean);
  Gnuplot& gp = figure.gp();
  gp << "set title '" << title << "'\nset xlabel 't [s]'\nset ylabel 'elongation [{/Symbol m}m]'\n"
     << "set yrange [" << -0.2e6 * oracle.basis << ":" << 2.8e6 * oracle.basis << "]\n"
     << "set key below\n"
     << "set label 1 \"" << numbers << "\" at graph 0.02, graph 0.95 front boxed\nset style textbox opaque\n"
     << "plot '-' w l lw 1.5 lc rgb '#d62728' title 'module 8: full FFRF', "
     << "'-' w l lw 3 lc rgb '#1f77b4' title 'module 7: intuitive', "
     << "'-' w l lw 2 dt 2 lc rgb '#000000' title 'static FE, same basis', "
     << mean8 * 1e6 << " w l lw 2 dt 3 lc rgb '#ff7f0e' title '" << mean_title << "'\n";
  figure.send(table, {0, 2});
  figure.send(table, {0, 1});
  figure.send(table, {0, 3});
}

void spinning(const demo::Options& options) {
  const double Omega = options.number("spin-rate"), t_end = options.number("end-time");
  const int elements = options.integer("elements");
  const MassMatrixType mass = options.text("mass") == "lumped" ? MassMatrixType::lumped : MassMatrixType::consistent;
  if (Omega <= 0 || t_end <= 0 || elements < 2) throw std::invalid_argument("spin rate, end time > 0, 2 elements at least");
  const FeModel fe = straight_beam(length, elements, square_section(E, rho, side), Vec2(-0.5 * length, 0.0));
  const FeMatrices fm = assemble(fe, mass);
  const auto data = std::make_shared<const FlexibleBodyData>(flexible_body_data(
      fe, mass, modes_by_kind(fe, fm, {options.integer("bending-modes"), options.integer("axial-modes")})));
  const StaticStretch oracle = static_stretch(fe, fm, *data, Omega);

  std::vector<double> t;
  const std::vector<std::vector<double>> stretch =
      simulate_both(data, elements, Omega, t_end, options.number("rtol"), t);
  const std::vector<double>& s8 = stretch[1];
  const OscillationMean m8 = mean_over_oscillations(s8, t);
  double largest7 = 0;
  for (double s : stretch[0]) largest7 = std::max(largest7, std::abs(s));
  const double percent = 100.0 * (m8.mean - oracle.basis) / oracle.basis;
  std::printf("module 8: mean stretch %.2f um over %.4f s; static FE in its basis %.2f um (%+.2f %%); "
              "whole mesh %.2f um; closed form %.2f um; module 7: largest stretch %.1e um\n",
              1e6 * m8.mean, t[m8.end], 1e6 * oracle.basis, percent, 1e6 * oracle.mesh, 1e6 * oracle.closed_form,
              1e6 * largest7);

  demo::Table table{{"t [s]", "module7 [um]", "module8 [um]", "static_fe_basis [um]", "static_fe_mesh [um]",
                     "closed_form [um]"},
                    {}};
  for (std::size_t i = 0; i < t.size(); ++i)
    table.add({t[i], 1e6 * stretch[0][i], 1e6 * s8[i], 1e6 * oracle.basis, 1e6 * oracle.mesh,
               1e6 * oracle.closed_form});
  demo::write_csv(options, "spinning_beam", table);
  plot_stretch(options, table, Omega, oracle, m8.mean, t[m8.end], largest7, percent);
}

}  // namespace

int main(int argc, char** argv) { return demo::run(argc, argv, "spinning_beam", parameters, spinning); }
