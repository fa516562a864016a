// Benchmark of the FE model import: a free-free steel lattice of 101 568 DOFs (frame_lattice and
// sparse_fe_matrices of extras/sparse make it) written as Matrix Market files with its node table,
// then read back with load_sparse_fe_model.
//
// Prints CSV rows "group,case,quantity,value,unit" (no header):
//   import  n=N: seconds to write M, K and the node table, their size, seconds to read them back,
//           the read rate, and whether the matrices read back exactly (files in a temporary
//           folder, removed afterwards).
// --quick: a lattice of 2883 DOFs.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <string>

#include "fmbd/matrix_market.hpp"
#include "fmbd/sparse_modal.hpp"
#include "bench.hpp"

using namespace fmbd;
using fmbd::bench::row;
using fmbd::bench::seconds;

namespace {

void import(const FeModel& fe) {
  namespace fs = std::filesystem;
  const int n = fe.num_dofs();
  const std::string name = "n=" + std::to_string(n);
  const fs::path dir = fs::temp_directory_path() / ("fmbd-bench-fe_import-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string mass = (dir / "mass.mtx").string(), stiffness = (dir / "stiffness.mtx").string(),
                    nodes = (dir / "nodes.txt").string();
  try {
    const SparseFeMatrices sparse = sparse_fe_matrices(fe, MassMatrixType::consistent);
    NodeTable table;
    for (int k = 0; k < fe.num_nodes(); ++k) {
      table.nodes.push_back(fe.nodes()[k]);
      table.dofs.push_back({3 * k, 3 * k + 1, 3 * k + 2});
    }
    const double t_write = seconds([&] {
      write_matrix_market(mass, sparse.M);
      write_matrix_market(stiffness, sparse.K);
      write_node_table(nodes, table);
    });
    const double bytes = static_cast<double>(fs::file_size(mass) + fs::file_size(stiffness) + fs::file_size(nodes));
    SparseFeModel model;
    const double t_read = seconds([&] { model = load_sparse_fe_model(mass, stiffness, nodes); });
    row("import", name, "write seconds", t_write, "s");
    row("import", name, "file size", bytes / 1e6, "MB");
    row("import", name, "read seconds", t_read, "s");
    row("import", name, "read rate", bytes / 1e6 / t_read, "MB/s");
    const bool exact = SparseMat(model.K - sparse.K).norm() == 0.0 && SparseMat(model.M - sparse.M).norm() == 0.0;
    row("import", name, "read back exactly", exact ? 1.0 : 0.0, "1");
  } catch (...) {
    fs::remove_all(dir);
    throw;
  }
  fs::remove_all(dir);
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  try {
    // A steel lattice of square 0.1 m cells, 20 mm square members: n = 2883 or 101 568.
    const int cells = quick ? 30 : 183;
    import(frame_lattice(cells, cells, 0.1, 0.1, square_section(2.1e11, 7850.0, 0.02)));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fmbd-bench-fe_import: %s\n", e.what());
    return 1;
  }
  return 0;
}
