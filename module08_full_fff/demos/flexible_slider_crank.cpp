// Module 8 demo: the flexible slider-crank. Mid-span deflection of the connecting rod over time
// with the intuitive equations (module 7) and the full FFRF (module 8), and an animation of the
// mechanism with the deformation magnified.
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>
#include <gnuplot-iostream.h>

#include "demo.hpp"
#include "fmbd/ffrf.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/intuitive_flexible.hpp"
#include "fmbd/marker.hpp"
#include "fmbd/simulation.hpp"

namespace {

using namespace fmbd;

const std::vector<demo::Parameter> parameters{
    {"crank-speed", "150", "rad/s", "constant crank speed"},
    {"turns", "3", "", "crank turns simulated"},
    {"modes", "2", "", "elastic modes of the rod (Craig-Bampton: fixed-interface modes)"},
    {"basis", "craig-bampton", "", "the rod's modes: Craig-Bampton on its pins, or free-free",
     {"craig-bampton", "free-free"}},
    {"mass", "consistent", "", "FE mass matrix", {"consistent", "lumped"}},
    {"rtol", "1e-8", "-", "relative tolerance of Dormand-Prince"},
};

// Global position of a named point (point_position, not the marker's pose: see marker.hpp).
Vec2 position(const Model& m, const char* point, const VecX& q) {
  return point_position(m, m.find_point(point), q);
}

// Deflection of the rod's middle from the chord through its ends (positive to the left of the chord).
double midspan_deflection(const Model& m, const VecX& q) {
  const Vec2 a = position(m, "rod start", q), b = position(m, "rod end", q), c = position(m, "rod mid", q);
  const Vec2 chord = (b - a).normalized();
  const Vec2 d = c - a;
  return chord.x() * d.y() - chord.y() * d.x();
}

Trajectory run(const FlexibleExample& ex, double t_end, double rtol) {
  SimulationOptions o;
  o.integrator = Integrator::dormand_prince;
  o.step = 1e-5;
  o.rtol = rtol;
  o.atol = 1e-11;
  o.max_step = 1e-4;
  o.stabilisation = Stabilisation::projection;
  o.output_interval = 2.5e-4;
  return simulate(ex.model, ex.q0, ex.qd0, 0.0, t_end, o);
}

// The rod's mid-span deflection in both runs, row by row, with module 8's crank hub and tip; and
// the largest deflection of each and their largest difference [mm].
struct Deflections {
  demo::Table table;
  double peak7 = 0, peak8 = 0, gap = 0;
};

Deflections deflections(const FlexibleExample& intuitive, const Trajectory& t7, const FlexibleExample& full,
                        const Trajectory& t8) {
  // The crank's hub and tip (module 8) let a reader check the drawing: |tip - hub| is the crank length.
  Deflections out;
  out.table.columns = {"t [s]", "crank_angle [rad]", "deflection_module7 [mm]", "deflection_module8 [mm]",
                       "difference [um]", "crank_hub_x [m]", "crank_hub_y [m]", "crank_tip_x [m]", "crank_tip_y [m]"};
  for (std::size_t i = 0; i < t7.t.size() && i < t8.t.size(); ++i) {
    const double d7 = 1e3 * midspan_deflection(intuitive.model, t7.q[i]);
    const double d8 = 1e3 * midspan_deflection(full.model, t8.q[i]);
    out.peak7 = std::max(out.peak7, std::abs(d7));
    out.peak8 = std::max(out.peak8, std::abs(d8));
    out.gap = std::max(out.gap, std::abs(d8 - d7));
    const Vec2 hub = position(full.model, "crank hub", t8.q[i]), tip = position(full.model, "crank tip", t8.q[i]);
    out.table.add({t7.t[i], t7.q[i](2), d7, d8, 1e3 * (d8 - d7), hub.x(), hub.y(), tip.x(), tip.y()});
  }
  return out;
}

// The figure: both deflections over time, and their difference below.
void plot_deflections(const demo::Options& options, const FlexibleSliderCrankParameters& p, double t_end,
                      const Deflections& d) {
  demo::Figure figure(options, "slider_crank_deflection", 1000, 700);
  if (!figure.active()) return;
  char title[120];
  std::snprintf(title, sizeof title, "Flexible slider-crank (0.15 m crank at %g rad/s, 0.30 m steel rod, 5 mm square)",
                p.crank_speed);
  // The numbers the figure exists to show, and the known approximation of the consistent mass.
  const bool consistent = p.mass_type == MassMatrixType::consistent;
  char label[200];
  std::snprintf(label, sizeof label, "largest deflection: module 7 %.2f mm, module 8 %.2f mm; they differ by at most %.3f mm",
                d.peak7, d.peak8, d.gap);
  figure.gp() << "set multiplot layout 2,1 title '" << title << "'\nset xrange [0:" << t_end << "]\nset grid\nset key top left\n"
              << "set ylabel 'rod mid-span deflection [mm]'\n"
              << "set label 1 '" << label << "' at graph 0.98, graph 0.08 right front\n"
              << "plot '-' w l lw 2 lc rgb '#1f77b4' title 'module 7: intuitive', "
              << "'-' w l lw 2 dt 2 lc rgb '#d62728' title '"
              << (consistent ? "module 8: full FFRF, consistent mass (nodal form not exactly Lagrangian, README sec. 2)"
                             : "module 8: full FFRF, lumped mass")
              << "'\n";
  figure.send(d.table, {0, 2});
  figure.send(d.table, {0, 3});
  figure.gp() << "unset label 1\nset xlabel 't [s]'\nset ylabel 'module 8 - module 7 [{/Symbol m}m]'\n"
              << "plot '-' w l lw 2 lc rgb '#2ca02c' notitle\n";
  figure.send(d.table, {0, 4});
  figure.gp() << "unset multiplot\n";
}

// Animation of module 8 over the last of `turns` crank turns: the rod's deflection from the chord
// through its end nodes is magnified, so its ends stay on the pins.
void animate(const demo::Options& options, const FlexibleExample& full, const Trajectory& t8, std::size_t turns) {
  const int magnify = 10;
  demo::Figure anim(options, "slider_crank_animation", 700, 330, demo::Format::gif_animation);
  if (!anim.active()) return;
  Gnuplot& gp = anim.gp();
  gp << "set size ratio -1\nset xrange [-0.2:0.5]\nset yrange [-0.18:0.18]\nunset key\nset grid\n";
  const Model& m = full.model;
  const int nodes = full.data->fe.num_nodes();
  const std::size_t first = t8.t.size() * (turns - 1) / turns;
  for (std::size_t i = first; i < t8.t.size(); i += 2) {
    const VecX& q = t8.q[i];
    const VecX q_rod = m.body_state(q, full.flexible);
    std::vector<Vec2> r;
    for (int k = 0; k < nodes; ++k) r.push_back(node_pose(full.data->nodes[k], q_rod).head<2>());
    const Vec2 a = r.front(), chord = (r.back() - a).normalized(), normal(-chord.y(), chord.x());
    char title[96];
    std::snprintf(title, sizeof title, "set title 'module 8, t = %.4f s, rod deflection x %d'\n", t8.t[i], magnify);
    gp << title
       << "plot '-' w lp lw 4 pt 7 lc rgb '#555555', '-' w l lw 3 lc rgb '#d62728', '-' w l lw 2 lc rgb '#1f77b4'\n";
    const Vec2 hub = position(m, "crank hub", q), tip = position(m, "crank tip", q);
    gp << hub.x() << ' ' << hub.y() << '\n' << tip.x() << ' ' << tip.y() << "\ne\n";
    for (const Vec2& x : r) {
      const Vec2 d = x - a;
      const Vec2 shown = a + chord * chord.dot(d) + normal * (magnify * normal.dot(d));
      gp << shown.x() << ' ' << shown.y() << '\n';
    }
    const Vec2 s = position(m, "slider", q);
    gp << "e\n" << s.x() - 0.02 << ' ' << -0.01 << '\n' << s.x() + 0.02 << ' ' << -0.01 << '\n'
       << s.x() + 0.02 << ' ' << 0.01 << '\n' << s.x() - 0.02 << ' ' << 0.01 << '\n' << s.x() - 0.02 << ' ' << -0.01
       << "\ne\n";
    anim.end_frame(0.05);
  }
}

void slider_crank(const demo::Options& options) {
  FlexibleSliderCrankParameters p;
  p.crank_speed = options.number("crank-speed");
  p.modes = options.integer("modes");
  p.basis = options.text("basis") == "free-free" ? BodyBasis::free_free_modes : BodyBasis::craig_bampton;
  p.mass_type = options.text("mass") == "lumped" ? MassMatrixType::lumped : MassMatrixType::consistent;
  if (p.crank_speed <= 0 || options.integer("turns") < 1) throw std::invalid_argument("crank speed > 0, one turn at least");
  const double t_end = 2.0 * 3.14159265358979323846 * options.integer("turns") / p.crank_speed;
  const FlexibleExample intuitive = flexible_slider_crank(p, make_intuitive_body);
  const FlexibleExample full = flexible_slider_crank(p, make_ffrf_body);
  const Trajectory t7 = run(intuitive, t_end, options.number("rtol")), t8 = run(full, t_end, options.number("rtol"));
  std::printf("module 7: %d steps, module 8: %d steps\n", t7.steps, t8.steps);

  const Deflections d = deflections(intuitive, t7, full, t8);
  std::printf("largest mid-span deflection: module 7 %.3f mm, module 8 %.3f mm\n", d.peak7, d.peak8);
  demo::write_csv(options, "slider_crank_deflection", d.table);
  plot_deflections(options, p, t_end, d);
  animate(options, full, t8, static_cast<std::size_t>(options.integer("turns")));
}

}  // namespace

int main(int argc, char** argv) { return demo::run(argc, argv, "flexible_slider_crank", parameters, slider_crank); }
