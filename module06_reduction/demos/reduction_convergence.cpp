// Module 6 demo: how many modes does a flexible connecting rod need? The rod is reduced on its
// free-free body (the FFRF bases of tasks M06T2 and M06T4) and then pinned at both ends, as in a
// slider-crank. Its first frequencies from the reduced model are compared with the full FE model.
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gnuplot-iostream.h>

#include "demo.hpp"
#include "fmbd/reduction.hpp"

namespace {

using namespace fmbd;

constexpr int elements = 60;
constexpr int max_elastic = 16;
constexpr int compared = 3;  // frequencies compared

// The lowest `count` frequencies [Hz] (fewer if the basis has fewer DOFs left) of a reduced body whose DOFs `fixed` are held at zero:
// the constraint Phi(fixed, :) q = 0 is solved by q = N q', N an orthonormal null-space basis.
VecX pinned_frequencies(const ReducedBasis& basis, const std::vector<int>& fixed, int count) {
  MatX B(fixed.size(), basis.size());
  for (std::size_t r = 0; r < fixed.size(); ++r) B.row(r) = basis.Phi.row(fixed[r]);
  Eigen::JacobiSVD<MatX> svd(B, Eigen::ComputeFullV);
  svd.setThreshold(1e-10);
  const MatX N = svd.matrixV().rightCols(basis.size() - svd.rank());
  count = std::min(count, static_cast<int>(N.cols()));
  if (count == 0) return VecX();
  const MatX K = N.transpose() * basis.K_bar * N, M = N.transpose() * basis.M_bar * N;
  return modal_analysis(0.5 * (K + K.transpose()), 0.5 * (M + M.transpose()), count).hertz();
}

void convergence(const demo::Options& options) {
  const FeModel rod = straight_beam(0.3, elements, square_section(210e9, 7850.0, 0.008));
  const FeMatrices m = assemble(rod, MassMatrixType::consistent);
  const std::vector<int> fixed = {dof_index(0, NodeDof::ux), dof_index(0, NodeDof::uy),
                                  dof_index(elements, NodeDof::ux), dof_index(elements, NodeDof::uy)};

  const DofMap pinned = apply_supports(rod, {{0, Support::hinged}, {elements, Support::hinged}});
  const VecX exact = modal_analysis(reduce(m.K, pinned), reduce(m.M, pinned), compared).hertz();
  std::printf("pinned-pinned rod, full FE model (%d DOFs):", pinned.num_free());
  for (int i = 0; i < compared; ++i) std::printf(" f%d = %.2f Hz", i + 1, exact(i));
  std::printf("\n%8s %28s %28s\n", "elastic", "free-free modes: error f1..f3", "Craig-Bampton: error f1..f3");

  demo::Table table{{"elastic_modes [-]", "truncation_f1 [-]", "truncation_f2 [-]", "truncation_f3 [-]", "cb_f1 [-]", "cb_f2 [-]", "cb_f3 [-]"},
                    {}};
  const std::vector<int> interface = node_dofs({0, elements});
  for (int k = 1; k <= max_elastic; ++k) {
    // Craig-Bampton on both end nodes: 6 constraint modes + j normal modes, 3 + j elastic columns.
    const ReducedBasis truncation = modal_truncation(rod, m, k);
    const VecX f_t = pinned_frequencies(truncation, fixed, compared);
    VecX f_cb;
    if (k >= 3) f_cb = pinned_frequencies(ffrf_basis(rod, m, craig_bampton(m.K, m.M, interface, k - 3)), fixed, compared);
    std::vector<double> row{double(k)};
    for (const VecX* f : {&f_t, static_cast<const VecX*>(&f_cb)})
      for (int i = 0; i < compared; ++i)
        row.push_back(i < f->size() ? std::max(std::abs((*f)(i) / exact(i) - 1.0), 1e-15) : std::nan(""));
    table.add(row);
    std::printf("%8d   %8.1e %8.1e %8.1e   %8.1e %8.1e %8.1e\n", k, row[1], row[2], row[3], row[4], row[5], row[6]);
  }
  demo::write_csv(options, "reduction_convergence", table);

  demo::Figure figure(options, "reduction_convergence", 900, 560);
  if (!figure.active()) return;
  Gnuplot& gp = figure.gp();
  gp << "set title 'Steel rod 0.3 m, 8 mm square, pinned at both ends, reduced on the free-free body'\n"
     << "set xlabel 'elastic coordinates of the body'\nset ylabel 'relative frequency error'\n"
     << "set logscale y\nset format y '10^{%T}'\nset grid\nset key top right\nset xrange [0.5:16.5]\n"
     << "set datafile missing 'nan'\n"
     << "plot '-' w lp lw 2 pt 7 lc rgb '#1f77b4' title 'free-free modes, f_1', "
     << "'-' w lp lw 2 pt 5 dt 2 lc rgb '#1f77b4' title 'free-free modes, f_3', "
     << "'-' w lp lw 2 pt 7 lc rgb '#d62728' title 'Craig-Bampton (both ends), f_1', "
     << "'-' w lp lw 2 pt 5 dt 2 lc rgb '#d62728' title 'Craig-Bampton (both ends), f_3'\n";
  for (int c : {1, 3, 4, 6}) {
    demo::Table valid{table.columns, {}};
    for (const auto& row : table.rows)
      if (!std::isnan(row[c])) valid.add(row);
    figure.send(valid, {0, c});
  }
}

}  // namespace

int main(int argc, char** argv) {
  return demo::run(argc, argv, "reduction_convergence", convergence);
}
