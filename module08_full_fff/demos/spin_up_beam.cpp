// Module 8 demo: the spin-up beam. Tip deflection in the hub frame for a slow and a fast spin-up,
// with the intuitive equations (module 7), the full FFRF (module 8) and the full FFRF with your
// geometric stiffening (M08T7, M08T8; left out, with a note, until they are done); then the full FFRF with the body's frame at its centroid
// and clamped at the hub, above the first cantilever frequency. With --threshold on, instead: the
// spin rate at which steady spin loses stability for module 7 and for module 8 in both frames,
// from the eigenvalues about steady spin, checked by kicked runs below and above it
// (spin_stability.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>
#include <gnuplot-iostream.h>

#include "demo.hpp"
#include "spin_stability.hpp"
#include "fmbd/ffrf.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/geometric_stiffening.hpp"

namespace {

using namespace fmbd;

constexpr double t_end = 30.0;

const std::vector<demo::Parameter> parameters{
    {"slow-rate", "2", "rad/s", "the slow spin rate of the first figure (first cantilever frequency: 2.9 rad/s)"},
    {"fast-rate", "8", "rad/s", "the fast spin rate of the first figure"},
    {"modes", "3", "", "fixed-interface (cantilever) modes of the beam, in every figure"},
    {"threshold", "off", "",
     "on: instead of the spin-up, the spin rate at which steady spin loses stability, per model and frame",
     {"off", "on"}},
    {"margin", "3", "%", "--threshold on: the kicked runs spin this far below and above each threshold"},
};
int modes = 3;  // --modes

using spin::tip_deflection;

SimulationOptions spin_up_options() { return spin::run_options(); }

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
    std::snprintf(panel, sizeof panel, "set title 'spin rate %g rad/s'\n", rates[k]);
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
      std::printf("spin rate %g rad/s, frame %s: tip deflection %.4f m at t = %.2f s\n", rate,
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

// True once the stiffened body's terms run: your M08T7 and M08T8 (and T1 to T5 under them) are done.
bool stiffening_done() {
  SpinUpBeamParameters p;
  p.modes = 1;
  p.basis = BodyBasis::clamped_frame;
  try {
    const FlexibleExample ex = spin_up_beam(p, make_ffrf_body);
    const VecX q = VecX::Constant(3 + ex.data->num_modes(), 0.1);
    (void)make_stiffened_ffrf_body(ex.data)->body_forces(q, q, Vec2::Zero());
  } catch (const NotImplemented& e) {
    std::printf("spin_up_beam: the stiffened curve is left out until your geometric stiffening runs (%s; "
                "./workbook hint M08T7)\n", e.what());
    return false;
  }
  return true;
}

// The formulations of the rates figure: module 7, module 8 and, once your M08T7 and M08T8 run,
// module 8 with geometric stiffening (its frame clamped at the hub, where linear FFRF fails first).
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
  if (stiffening_done())
    f.push_back({"stiffened", "module 8 + geometric stiffening", "lw 2 lc rgb '#2ca02c'", make_stiffened_ffrf_body,
                 BodyBasis::clamped_frame});
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
      std::printf("spin rate %g rad/s, %s: peak tip deflection %.4f m, at the end %.4f m\n", rates[k], f.title, p,
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

// The models and frames of the threshold figure (module 7 refuses the clamped frame: its S_f is
// not zero, module 7's README sec. 3).
struct Case {
  const char* column;
  const char* title;
  int model;
  int frame;  // 0: at the centroid, 1: clamped at the hub
  BodyFactory make;
  BodyBasis basis;
  const char* colour;
};
std::vector<Case> threshold_cases() {
  return {{"module7_centroid", "module 7, frame at the centroid", 7, 0, make_intuitive_body, BodyBasis::craig_bampton,
           "#1f77b4"},
          {"module8_centroid", "module 8, frame at the centroid", 8, 0, make_ffrf_body, BodyBasis::craig_bampton,
           "#d62728"},
          {"module8_clamped", "module 8, frame clamped at the hub", 8, 1, make_ffrf_body, BodyBasis::clamped_frame,
           "#2ca02c"}};
}

SpinUpBeamParameters beam_at(const Case& c, double rate) {
  SpinUpBeamParameters p;
  p.modes = modes;
  p.basis = c.basis;
  p.spin_rate = rate;
  return p;
}

// One case: its threshold, the linear growth rate above it, and the kicked runs below and above.
struct CaseResult {
  double threshold = 0, growth_above = 0;
  spin::KickedRun below, above;
};
CaseResult threshold_case(const Case& c, double margin, double kick) {
  CaseResult r;
  r.threshold = spin::stability_threshold(beam_at(c, 0.0), c.make, 20.0);
  if (!std::isfinite(r.threshold)) throw std::runtime_error(std::string(c.title) + ": stable up to 20 rad/s");
  const double below = (1 - margin) * r.threshold, above = (1 + margin) * r.threshold;
  r.growth_above = spin::steady_spin(beam_at(c, above), c.make).growth;
  r.below = spin::kicked_run(beam_at(c, below), c.make, kick, 20.0, 200 * kick);
  r.above = spin::kicked_run(beam_at(c, above), c.make, kick, 20.0, 200 * kick);
  std::printf("threshold, %s: steady spin loses stability at %.3f rad/s (eigenvalues: largest real part %.3f 1/s at "
              "%.3f rad/s); kicked by %g m: peak %.4f m at %.3f rad/s, %.3f m at %.3f rad/s (growth %.3f 1/s)\n",
              c.title, r.threshold, r.growth_above, above, kick, r.below.peak, below, r.above.peak, above,
              r.above.growth);
  return r;
}

// The largest real part of the eigenvalues over spin rates, per case (the first panel).
demo::Table growth_sweep(const std::vector<Case>& cases) {
  demo::Table table{{"spin rate [rad/s]"}, {}};
  for (const Case& c : cases) table.columns.push_back(std::string(c.column) + " [1/s]");
  for (int i = 1; i <= 60; ++i) {
    std::vector<double> row{0.2 * i};
    for (const Case& c : cases) row.push_back(spin::steady_spin(beam_at(c, 0.2 * i), c.make).growth);
    table.add(row);
  }
  return table;
}

// The kicked runs as one table: t and |deviation|, below and above, per case (the second panel).
demo::Table kicked_table(const std::vector<Case>& cases, const std::vector<CaseResult>& results) {
  demo::Table table{{"t [s]"}, {}};
  for (const Case& c : cases)
    for (const char* side : {"below", "above"}) table.columns.push_back(std::string(c.column) + "_" + side + " [m]");
  const std::vector<double>& t = results.front().below.t;
  for (std::size_t i = 0; i < t.size(); ++i) {
    std::vector<double> row{t[i]};
    for (const CaseResult& r : results)
      for (const spin::KickedRun* run : {&r.below, &r.above})
        row.push_back(i < run->deviation.size() ? std::abs(run->deviation[i]) : std::nan(""));
    table.add(row);
  }
  return table;
}

void threshold_figure(const demo::Options& options, const std::vector<Case>& cases,
                      const std::vector<CaseResult>& results, const demo::Table& sweep, const demo::Table& runs,
                      double margin, double kick) {
  demo::Figure figure(options, "spin_up_thresholds", 1200, 560);
  if (!figure.active()) return;
  Gnuplot& gp = figure.gp();
  gp << "set multiplot layout 1,2 title 'Spin-up beam (8 m, 3 cantilever shapes): the spin rate at which steady "
        "spin loses stability (a real eigenvalue pair)'\nset grid\nset key top left\n";
  gp << "set title 'largest real part of the eigenvalues about steady spin'\nset xlabel 'spin rate [rad/s]'\n"
     << "set ylabel 'growth rate [1/s]'\nplot ";
  for (std::size_t k = 0; k < cases.size(); ++k) {
    char title[160];
    std::snprintf(title, sizeof title, "%s: %.2f rad/s", cases[k].title, results[k].threshold);
    gp << (k ? ", " : "") << "'-' w l lw 2 lc rgb '" << cases[k].colour << "' title '" << title << "'";
  }
  gp << "\n";
  for (std::size_t k = 0; k < cases.size(); ++k) figure.send(sweep, {0, static_cast<int>(k) + 1});
  char panel[200];
  std::snprintf(panel, sizeof panel,
                "set title 'tip kicked by %g m: %g %% below (dashed), above (solid)'\n", kick,
                100 * margin);
  gp << panel << "set xlabel 't [s]'\nset ylabel '|tip deflection - steady spin| [m]'\nset logscale y\n"
     << "set yrange [1e-3:10]\nset format y '10^{%L}'\nset key top right\nplot ";
  for (std::size_t k = 0; k < cases.size(); ++k) {
    gp << (k ? ", " : "") << "'-' w l lw 2 dt 2 lc rgb '" << cases[k].colour << "' notitle";
    gp << ", '-' w l lw 2 lc rgb '" << cases[k].colour << "' title '" << cases[k].title << "'";
  }
  gp << "\n";
  for (std::size_t k = 0; k < cases.size(); ++k)
    for (int side = 0; side < 2; ++side) figure.send(runs, {0, 1 + 2 * static_cast<int>(k) + side});
  gp << "unset multiplot\n";
}

// --threshold on: the thresholds, each checked by kicked runs below and above it.
void thresholds(const demo::Options& options) {
  const double margin = options.number("margin") / 100, kick = 0.01;
  if (!(margin > 0 && margin < 0.5)) throw std::invalid_argument("--margin: between 0 and 50 %");
  const std::vector<Case> cases = threshold_cases();
  std::vector<CaseResult> results;
  demo::Table summary{{"model [-]", "frame [-]", "threshold [rad/s]", "rate_below [rad/s]", "peak_below [m]",
                       "rate_above [rad/s]", "peak_above [m]", "growth_linear [1/s]", "growth_simulated [1/s]",
                       "kick [m]"},
                      {}};
  for (const Case& c : cases) {
    results.push_back(threshold_case(c, margin, kick));
    const CaseResult& r = results.back();
    summary.add({double(c.model), double(c.frame), r.threshold, (1 - margin) * r.threshold, r.below.peak,
                 (1 + margin) * r.threshold, r.above.peak, r.growth_above, r.above.growth, kick});
  }
  demo::write_csv(options, "spin_up_thresholds", summary);
  const demo::Table sweep = growth_sweep(cases), runs = kicked_table(cases, results);
  demo::write_csv(options, "spin_up_growth", sweep);
  demo::write_csv(options, "spin_up_kicked", runs);
  threshold_figure(options, cases, results, sweep, runs, margin, kick);
}

void spin_up(const demo::Options& options) {
  modes = options.integer("modes");
  if (options.text("threshold") == "on") return thresholds(options);
  rates(options);
  frames(options);
}

}  // namespace

int main(int argc, char** argv) { return demo::run(argc, argv, "spin_up_beam", parameters, spin_up); }
