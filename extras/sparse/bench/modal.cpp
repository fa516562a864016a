// Benchmark: the dense modal_analysis of module 5 against the sparse shift-invert path
// (sparse_lowest_modes) on free-free planar frame lattices (frame_lattice). The import of such a
// model from Matrix Market files is extras/fe_import's benchmark.
//
// Prints CSV rows "group,case,quantity,value,unit" (no header):
//   modal   dense n=N / sparse n=N: seconds for the 20 lowest modes (the matrices already
//           assembled), the first elastic frequency, and where both ran the largest relative
//           difference of the 17 elastic frequencies.
// Dense up to about 2400 DOFs, sparse up to about 100 000. --quick: small sizes only.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "fmbd/modal.hpp"
#include "fmbd/sparse_modal.hpp"
#include "bench.hpp"

using namespace fmbd;
using fmbd::bench::row;
using fmbd::bench::seconds;

namespace {

constexpr int kModes = 20;
constexpr double kTwoPi = 2.0 * 3.14159265358979323846;

// A steel lattice of square 0.1 m cells, 20 mm square members.
FeModel lattice(int cells_x, int cells_y) {
  return frame_lattice(cells_x, cells_y, 0.1, 0.1, square_section(2.1e11, 7850.0, 0.02));
}

std::string case_name(const char* kind, int n) { return std::string(kind) + " n=" + std::to_string(n); }

// Largest relative difference of the elastic frequencies (after the three rigid-body modes).
double elastic_difference(const Modes& a, const Modes& b) {
  double worst = 0.0;
  for (Eigen::Index i = 3; i < a.omega.size(); ++i)
    worst = std::max(worst, std::abs(a.omega(i) - b.omega(i)) / b.omega(i));
  return worst;
}

void dense_and_sparse(int cells_x, int cells_y) {
  const FeModel fe = lattice(cells_x, cells_y);
  const int n = fe.num_dofs();
  const SparseFeMatrices sparse = sparse_fe_matrices(fe, MassMatrixType::consistent);
  const FeMatrices dense = to_dense(sparse);
  Modes d, s;
  const double t_dense = seconds([&] { d = modal_analysis(dense.K, dense.M, kModes); });
  const double t_sparse = seconds([&] { s = sparse_lowest_modes(sparse.K, sparse.M, kModes); });
  row("modal", case_name("dense", n), "seconds", t_dense, "s");
  row("modal", case_name("sparse", n), "seconds", t_sparse, "s");
  row("modal", case_name("dense", n), "first elastic frequency", d.hertz()(3), "Hz");
  row("modal", case_name("sparse", n), "first elastic frequency", s.hertz()(3), "Hz");
  row("modal", case_name("sparse", n), "max relative difference to dense", elastic_difference(s, d), "1");
}

// The sparse path alone.
void sparse_only(int cells) {
  const FeModel fe = lattice(cells, cells);
  const int n = fe.num_dofs();
  SparseFeMatrices sparse;
  const double t_assembly = seconds([&] { sparse = sparse_fe_matrices(fe, MassMatrixType::consistent); });
  Modes s;
  const double t_modes = seconds([&] { s = sparse_lowest_modes(sparse.K, sparse.M, kModes); });
  row("modal", case_name("sparse", n), "assembly seconds", t_assembly, "s");
  row("modal", case_name("sparse", n), "seconds", t_modes, "s");
  row("modal", case_name("sparse", n), "first elastic frequency", s.omega(3) / kTwoPi, "Hz");
  row("modal", case_name("sparse", n), "nonzeros of K", static_cast<double>(sparse.K.nonZeros()), "1");
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  try {
    // Dense and sparse side by side: n = 330, 630, 1260, 2436.
    using Cells = std::vector<std::pair<int, int>>;
    const Cells both = quick ? Cells{{10, 9}} : Cells{{10, 9}, {14, 13}, {20, 19}, {28, 27}};
    for (const auto& [cx, cy] : both) dense_and_sparse(cx, cy);
    // Sparse only: n = 2883, 10 092, 30 603, 101 568.
    const std::vector<int> cells = quick ? std::vector<int>{30} : std::vector<int>{30, 57, 100, 183};
    for (int c : cells) sparse_only(c);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fmbd-bench-modal: %s\n", e.what());
    return 1;
  }
  return 0;
}
