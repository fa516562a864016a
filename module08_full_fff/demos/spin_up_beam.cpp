// Module 8 demo: the spin-up beam. Tip deflection in the hub frame for a slow and a fast spin-up,
// with the intuitive equations (module 7) and the full FFRF (module 8), and, where this copy has
// extras/geometric_stiffening (FMBD_HAVE_GEOMETRIC_STIFFENING, set by demos/CMakeLists.txt), the
// full FFRF with geometric stiffening; then the full FFRF with the body's frame at its centroid
// and clamped at the hub, above the first cantilever frequency.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>
#include <gnuplot-iostream.h>

#include "demo.hpp"
#include "fmbd/ffrf.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/marker.hpp"
#include "fmbd/simulation.hpp"
#ifdef FMBD_HAVE_GEOMETRIC_STIFFENING
#include "fmbd/geometric_stiffening.hpp"
#endif

namespace {

using namespace fmbd;

constexpr double t_end = 30.0;

const std::vector<demo::Parameter> parameters{
    {"slow-rate", "2", "rad/s", "the slow spin rate of the first figure (first cantilever frequency: 2.9 rad/s)"},
    {"fast-rate", "8", "rad/s", "the fast spin rate of the first figure"},
    {"modes", "3", "", "fixed-interface (cantilever) modes of the beam, in both figures"},
};
int modes = 3;  // --modes

// Tip position across the hub's radial line, in the hub frame.
double tip_deflection(const FlexibleExample& ex, const VecX& q) {
  const Model& m = ex.model;
  const Vec2 tip = point_position(m, m.find_point("beam tip"), q);
  return (rotation(m.body_coordinates(q, m.find_body("hub"))(2)).transpose() * tip).y();
}

// Every run of this demo: Dormand-Prince with projection.
SimulationOptions spin_up_options() {
  SimulationOptions o;
  o.integrator = Integrator::dormand_prince;
  o.rtol = 1e-8;
  o.atol = 1e-10;
  o.max_step = 0.01;
  o.stabilisation = Stabilisation::projection;
  return o;
}

// One curve of a panel: its key title and gnuplot style.
struct Curve {
  std::string title;
  const char* style;
};
constexpr const char* kSolid = "lw 2 lc rgb '#1f77b4'";
constexpr const char* kDashed = "lw 2 dt 2 lc rgb '#d62728'";

// Two panels, one per spin rate, of the tip deflection: panel k plots curves[k][c] from column
// 1 + n k + c of `table` (n curves per panel).
void two_rate_figure(const demo::Options& options, const char* name, const char* title, const char* extra,
                     const double (&rates)[2], const demo::Table& table, const std::vector<Curve> (&curves)[2]) {
  demo::Figure figure(options, name, 1100, 500);
  if (!figure.active()) return;
  Gnuplot& gp = figure.gp();
  gp << "set multiplot layout 1,2 title '" << title << "'\n"
     << "set xlabel 't [s]'\nset ylabel 'tip deflection in the hub frame [m]'\nset grid\nset key below\n" << extra;
  for (int k = 0; k < 2; ++k) {
    char panel[64];
    std::snprintf(panel, sizeof panel, "set title 'spin rate %.0f rad/s'\n", rates[k]);
    gp << panel << "plot ";
    const int n = static_cast<int>(curves[k].size());
    for (int c = 0; c < n; ++c)
      gp << (c ? ", " : "") << "'-' w l " << curves[k][c].style << " title '" << curves[k][c].title << "'";
    gp << "\n";
    for (int c = 0; c < n; ++c) figure.send(table, {0, 1 + n * k + c});
  }
  gp << "unset multiplot\n";
}

// The largest |value| of a run, with its sign.
double peak(const std::vector<double>& d) {
  double p = 0.0;
  for (double v : d)
    if (std::isfinite(v) && std::abs(v) > std::abs(p)) p = v;
  return p;
}

std::vector<double> deflections(double spin_rate, const BodyFactory& make, BodyBasis basis, std::vector<double>& t) {
  SpinUpBeamParameters p;
  p.spin_rate = spin_rate;
  p.modes = modes;
  p.basis = basis;
  const FlexibleExample ex = spin_up_beam(p, make);
  SimulationOptions o = spin_up_options();
  o.output_interval = 0.05;
  const Trajectory run = simulate(ex.model, ex.q0, ex.qd0, 0.0, t_end, o);
  t = run.t;
  std::vector<double> d;
  for (const VecX& q : run.q) d.push_back(tip_deflection(ex, q));
  return d;
}

// The full FFRF with the frame at the centroid (Craig-Bampton made FFRF-ready: M-orthogonal to the
// rigid motions) or clamped at the hub node (its cantilever modes): the same displacement shapes,
// another frame. Runs until t_end, or until the tip leaves the hub's radial line by more than
// `limit` (a linear FFRF that diverges); the missing times stay empty.
std::vector<double> frame_deflections(double spin_rate, BodyBasis basis, const std::vector<double>& t, double limit) {
  SpinUpBeamParameters p;
  p.spin_rate = spin_rate;
  p.basis = basis;
  p.modes = modes;
  const FlexibleExample ex = spin_up_beam(p, make_ffrf_body);
  const SimulationOptions o = spin_up_options();
  VecX q = ex.q0, qd = ex.qd0;
  std::vector<double> d(t.size(), std::nan(""));
  d[0] = tip_deflection(ex, q);
  for (std::size_t i = 1; i < t.size(); ++i) {
    const Trajectory run = simulate(ex.model, q, qd, t[i - 1], t[i], o);
    q = run.q.back();
    qd = run.qd.back();
    d[i] = tip_deflection(ex, q);
    if (std::abs(d[i]) > limit) break;
  }
  return d;
}

void frames(const demo::Options& options) {
  const double rates[2] = {2.0, 4.0};  // below and above the first cantilever frequency, 2.9 rad/s
  std::vector<double> t;
  for (int i = 0; i <= 400; ++i) t.push_back(0.05 * i);
  demo::Table table{{"t [s]", "centroid_2 [m]", "clamped_2 [m]", "centroid_4 [m]", "clamped_4 [m]"}, {}};
  std::vector<std::vector<double>> columns;
  for (double rate : rates)
    for (BodyBasis basis : {BodyBasis::craig_bampton, BodyBasis::clamped_frame}) {
      columns.push_back(frame_deflections(rate, basis, t, 1.0));
      std::size_t last = 0;
      while (last + 1 < t.size() && std::isfinite(columns.back()[last + 1])) ++last;
      std::printf("spin rate %.0f rad/s, frame %s: tip deflection %.4f m at t = %.2f s\n", rate,
                  basis == BodyBasis::clamped_frame ? "clamped at the hub" : "at the centroid", columns.back()[last],
                  t[last]);
    }
  for (std::size_t i = 0; i < t.size(); ++i) {
    std::vector<double> row{t[i]};
    for (const auto& c : columns) row.push_back(c[i]);
    table.add(row);
  }
  demo::write_csv(options, "spin_up_frames", table);

  const std::vector<Curve> curves{{"frame at the centroid", kSolid}, {"frame clamped at the hub", kDashed}};
  two_rate_figure(options, "spin_up_frames",
                  "Full FFRF in two frames (consistent mass: not exactly Lagrangian, README sec. 2; "
                  "first cantilever frequency 2.9 rad/s)",
                  "set yrange [-1:1]\n", rates, table, {curves, curves});
}

// The formulations of the rates figure: module 7, module 8 and, with the extra, module 8 with
// geometric stiffening (its frame clamped at the hub, where linear FFRF fails first).
struct Formulation {
  const char* column;
  const char* title;
  const char* style;
  BodyFactory make;
  BodyBasis basis;
};
std::vector<Formulation> formulations() {
  std::vector<Formulation> f{{"module7", "module 7: intuitive", kSolid, make_intuitive_body, BodyBasis::craig_bampton},
                             {"module8", "module 8: full FFRF", kDashed, make_ffrf_body, BodyBasis::craig_bampton}};
#ifdef FMBD_HAVE_GEOMETRIC_STIFFENING
  f.push_back({"stiffened", "module 8 + geometric stiffening", "lw 2 lc rgb '#2ca02c'", make_stiffened_ffrf_body,
               BodyBasis::clamped_frame});
#endif
  return f;
}

void rates(const demo::Options& options) {
  const double rates[2] = {options.number("slow-rate"), options.number("fast-rate")};
  const std::vector<Formulation> forms = formulations();
  demo::Table table{{"t [s]"}, {}};
  for (const char* speed : {"slow", "fast"})
    for (const Formulation& f : forms) table.columns.push_back(std::string(speed) + "_" + f.column + " [m]");
  std::vector<std::vector<double>> columns;
  std::vector<Curve> curves[2];
  std::vector<double> t;
  for (int k = 0; k < 2; ++k)
    for (const Formulation& f : forms) {
      columns.push_back(deflections(rates[k], f.make, f.basis, t));
      const double p = peak(columns.back());
      std::printf("spin rate %.0f rad/s, %s: peak tip deflection %.4f m, at the end %.4f m\n", rates[k], f.title, p,
                  columns.back().back());
      char title[128];
      std::snprintf(title, sizeof title, "%s (peak %.2f m)", f.title, p);
      curves[k].push_back({title, f.style});
    }
  for (std::size_t i = 0; i < t.size(); ++i) {
    std::vector<double> row{t[i]};
    for (const auto& c : columns) row.push_back(i < c.size() ? c[i] : std::nan(""));
    table.add(row);
  }
  demo::write_csv(options, "spin_up_tip_deflection", table);

  two_rate_figure(options, "spin_up_tip_deflection", "Beam (8 m, aluminium, consistent mass: module 8 nodal form not exactly Lagrangian, README sec. 2) "
                  "clamped to a hub, spin-up in 15 s", "",
                  rates, table, curves);
}

void spin_up(const demo::Options& options) {
  modes = options.integer("modes");
  rates(options);
  frames(options);
}

}  // namespace

int main(int argc, char** argv) { return demo::run(argc, argv, "spin_up_beam", parameters, spin_up); }
