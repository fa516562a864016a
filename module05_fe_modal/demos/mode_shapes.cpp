// Module 5 demo: the first bending modes of a free-free and a clamped-free steel beam, with
// their frequencies against Euler-Bernoulli theory, and an animation of one mode (tasks M05T1-T5).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gnuplot-iostream.h>

#include "demo.hpp"
#include "fmbd/modal.hpp"

namespace {

using namespace fmbd;

constexpr double length = 1.0;
constexpr int elements = 40;
const Section steel = square_section(210e9, 7850.0, 0.01);

// betaL of the first four bending modes (Blevins, Formulas for Natural Frequency and Mode
// Shape, table 8-1).
constexpr double free_free_betaL[4] = {4.73004074, 7.85320462, 10.99560784, 14.13716549};
constexpr double clamped_free_betaL[4] = {1.87510407, 4.69409113, 7.85475744, 10.99554073};

double theory_hz(double betaL) {
  return betaL * betaL * std::sqrt(steel.E * steel.I / (steel.rho * steel.A * std::pow(length, 4))) /
         (2 * 3.14159265358979323846);
}

struct Case {
  const char* name;
  const double* betaL;
  std::vector<NodeSupport> supports;
  int skip;  // rigid-body modes before the first bending mode
};

// Bending modes of one case: columns x, then w_1 .. w_4 (transverse displacement, largest |w| = 1).
demo::Table bending_modes(const FeModel& fe, const FeMatrices& m, const Case& c, std::vector<double>& hz) {
  const DofMap map = apply_supports(fe, c.supports);
  Modes modes = modal_analysis(reduce(m.K, map), reduce(m.M, map), c.skip + 6);
  const MatX shapes = expand(modes.shapes, map);
  demo::Table table{{"x [m]", "mode_1 [-]", "mode_2 [-]", "mode_3 [-]", "mode_4 [-]"}, {}};
  std::vector<int> bending;  // skip the axial modes, which have no transverse motion
  for (int i = c.skip; i < modes.omega.size() && bending.size() < 4; ++i) {
    double transverse = 0, axial = 0;
    for (int k = 0; k < fe.num_nodes(); ++k) {
      transverse += std::abs(shapes(3 * k + 1, i));
      axial += std::abs(shapes(3 * k, i));
    }
    if (transverse > axial) bending.push_back(i);
  }
  for (int i : bending) hz.push_back(modes.hertz()(i));
  for (int k = 0; k < fe.num_nodes(); ++k) {
    std::vector<double> row{fe.nodes()[k].x()};
    for (int i : bending) {
      double scale = 0;
      for (int j = 0; j < fe.num_nodes(); ++j) scale = std::max(scale, std::abs(shapes(3 * j + 1, i)));
      // Sign: positive at the free end.
      const double sign = shapes(3 * (fe.num_nodes() - 1) + 1, i) < 0 ? -1.0 : 1.0;
      row.push_back(sign * shapes(3 * k + 1, i) / scale);
    }
    table.add(row);
  }
  return table;
}

void mode_shape_figure(const demo::Options& options) {
  const FeModel fe = straight_beam(length, elements, steel);
  const FeMatrices m = assemble(fe, MassMatrixType::consistent);
  const Case cases[2] = {{"free-free", free_free_betaL, {}, 3},
                         {"clamped-free", clamped_free_betaL, {{0, Support::clamped}}, 0}};
  demo::Figure figure(options, "beam_mode_shapes", 1100, 520);
  if (figure.active())
    figure.gp() << "set multiplot layout 1,2 title 'Steel beam, L = 1 m, 10 mm square, " << elements
                << " elements, consistent mass'\nset xlabel 'x [m]'\nset ylabel 'u_y / max |u_y|'\n"
                << "set key bottom left font ',9' box opaque\nset grid\nset yrange [-1.6:1.1]\n"
                << "set linetype 2 lc rgb '#1f77b4'\nset linetype 3 lc rgb '#d62728'\n"
                << "set linetype 4 lc rgb '#2ca02c'\nset linetype 5 lc rgb '#9467bd'\n";
  for (const Case& c : cases) {
    std::vector<double> hz;
    const demo::Table table = bending_modes(fe, m, c, hz);
    demo::write_csv(options, std::string("modes_") + (c.skip ? "free_free" : "clamped_free"), table);
    std::printf("%-13s", c.name);
    for (int i = 0; i < 4; ++i)
      std::printf("  f%d = %8.3f Hz (theory %8.3f)", i + 1, hz[i], theory_hz(c.betaL[i]));
    std::printf("\n");
    if (!figure.active()) continue;
    Gnuplot& gp = figure.gp();
    gp << "set title '" << c.name << "'\nplot 0 lc rgb '#999999' dt 2 notitle";
    for (int i = 0; i < 4; ++i)
      gp << ", '-' smooth csplines lw 2 title sprintf('mode %d: %.2f Hz (theory %.2f)', " << i + 1 << ", " << hz[i]
         << ", " << theory_hz(c.betaL[i]) << ")";
    gp << "\n";
    for (int i = 1; i <= 4; ++i) figure.send(table, {0, i});
  }
  if (figure.active()) figure.gp() << "unset multiplot\n";
}

// The second clamped-free mode swinging through one period.
void mode_animation(const demo::Options& options) {
  const FeModel fe = straight_beam(length, elements, steel);
  const FeMatrices m = assemble(fe, MassMatrixType::consistent);
  std::vector<double> hz;
  const Case clamped{"clamped-free", clamped_free_betaL, {{0, Support::clamped}}, 0};
  const demo::Table table = bending_modes(fe, m, clamped, hz);
  demo::Figure figure(options, "clamped_free_mode_2", 600, 360, demo::Format::gif_animation);
  if (!figure.active()) return;
  Gnuplot& gp = figure.gp();
  gp << "set xrange [-0.05:1.05]\nset yrange [-0.3:0.3]\nunset key\nset grid\nset xlabel 'x [m]'\n"
     << "set ylabel 'y [m] (amplitude 0.2 m, magnified)'\n";
  const int frames = 36;
  for (int f = 0; f < frames; ++f) {
    const double phase = 2 * 3.14159265358979323846 * f / frames;
    gp << "set title sprintf('Clamped-free beam, mode 2 (%.1f Hz)', " << hz[1] << ")\n"
       << "plot '-' with lines dt 2 lc rgb '#999999', '-' with linespoints lw 3 pt 7 ps 0.6 lc rgb '#d62728'\n"
       << "0 0\n" << length << " 0\ne\n";
    for (const auto& row : table.rows) gp << row[0] << ' ' << 0.2 * std::sin(phase) * row[2] << '\n';
    gp << "e\n";
    figure.end_frame(0.05);
  }
}

}  // namespace

int main(int argc, char** argv) {
  return demo::run(argc, argv, "mode_shapes", [](const demo::Options& options) {
    mode_shape_figure(options);
    mode_animation(options);
  });
}
