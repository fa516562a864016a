// Project tests (not graded) of the sparse modal path, given code of modules 5 and 6: Matrix Market
// and node-table files of external FE models with their error messages, sparse assembly, the
// shift-invert Lanczos solver sparse_lowest_modes, and sparse Craig-Bampton. The oracles are the
// dense functions of modules 5 and 6 (reference) and Euler-Bernoulli closed forms; the sparse
// assembly calls the element routines of module 5, so this program links the reference stages.
#include <Eigen/Eigenvalues>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "fmbd/fe_assembly.hpp"
#include "fmbd/matrix_market.hpp"
#include "fmbd/modal.hpp"
#include "fmbd/reduction.hpp"
#include "fmbd/sparse_modal.hpp"
#include "fmbd/sparse_reduction.hpp"
#include "fmbd/supports.hpp"
#include "grading.hpp"

using namespace fmbd;
using fmbd::testing::Tolerance;

namespace {

namespace fs = std::filesystem;

const Section kSteel = square_section(2.1e11, 7850.0, 0.02);

// A fresh directory under the system's temporary directory, removed with everything in it.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    path_ = fs::temp_directory_path() /
            ("fmbd-sparse-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  // Writes `text` to the file `name` in this directory; returns its path.
  std::string write(const std::string& name, const std::string& text) const {
    const std::string file = path(name);
    std::ofstream(file) << text;
    return file;
  }
  std::string path(const std::string& name) const { return (path_ / name).string(); }

 private:
  fs::path path_;
};

// The nodes of row j = 0 of a lattice, clamped.
std::vector<NodeSupport> clamp_bottom_row(int cells_x) {
  std::vector<NodeSupport> s;
  for (int i = 0; i <= cells_x; ++i) s.push_back({i, Support::clamped});
  return s;
}

// Largest |A - B| entry relative to max |B|.
double relative_difference(const MatX& A, const MatX& B) {
  return (A - B).cwiseAbs().maxCoeff() / std::max(B.cwiseAbs().maxCoeff(), 1e-300);
}

// Each sparse mode lies in the span of the dense modes of its eigenvalue: the M-projection onto
// them has unit length. That is the same shape up to sign for a simple eigenvalue and the same
// subspace within a repeated one (such as the rigid-body modes). `dense` holds more modes than
// `sparse`, so that a cluster at the end is complete.
void check_same_modes(const Modes& sparse, const Modes& dense, const MatX& M) {
  const VecX lambda_d = dense.omega.array().square();
  const double scale = lambda_d.maxCoeff();
  for (Eigen::Index j = 0; j < sparse.shapes.cols(); ++j) {
    const double lambda = sparse.omega(j) * sparse.omega(j);
    std::vector<Eigen::Index> cluster;
    for (Eigen::Index d = 0; d < lambda_d.size(); ++d)
      if (std::abs(lambda_d(d) - lambda) <= 1e-6 * scale) cluster.push_back(d);
    INFO("mode " << j << ", omega " << sparse.omega(j) << ", cluster of " << cluster.size() << " dense modes");
    REQUIRE(!cluster.empty());
    MatX basis(M.rows(), static_cast<Eigen::Index>(cluster.size()));
    for (std::size_t c = 0; c < cluster.size(); ++c) basis.col(static_cast<Eigen::Index>(c)) = dense.shapes.col(cluster[c]);
    const VecX projection = basis.transpose() * (M * sparse.shapes.col(j));
    CHECK(std::abs(projection.norm() - 1.0) < 1e-7);
  }
}

// phi^T M phi = I.
void check_mass_normalised(const Modes& modes, const MatX& M) {
  const MatX G = modes.shapes.transpose() * M * modes.shapes;
  CHECK_CLOSE(G, MatX::Identity(G.rows(), G.cols()), (Tolerance{1e-10, 0}), "modes are M-orthonormal");
}

// Eigenvalues lambda = omega^2 of a reduced pair (K_bar, M_bar), ascending.
VecX reduced_eigenvalues(const ReducedBasis& b) {
  const MatX K = 0.5 * (b.K_bar + b.K_bar.transpose());
  const MatX M = 0.5 * (b.M_bar + b.M_bar.transpose());
  return Eigen::GeneralizedSelfAdjointEigenSolver<MatX>(K, M).eigenvalues();
}

// A small symmetric matrix by hand and its Matrix Market text (lower triangle, with comments).
const char* kSmallSymmetric =
    "%%MatrixMarket matrix coordinate real symmetric\n"
    "% a 3 x 3 example\n"
    "\n"
    "3 3 4\n"
    "1 1 2.0\n"
    "2 1 -1.0\n"
    "2 2 +2.5e0\n"
    "3 3 1\n";

MatX small_symmetric() {
  MatX A(3, 3);
  A << 2.0, -1.0, 0.0, -1.0, 2.5, 0.0, 0.0, 0.0, 1.0;
  return A;
}

}  // namespace

// ---- frame_lattice and sparse assembly ---------------------------------------------------------

TEST_CASE("frame_lattice: nodes on the grid and an element along every edge and one diagonal per cell", "[sparse]") {
  const FeModel fe = frame_lattice(4, 3, 0.5, 0.25, kSteel);
  CHECK(fe.num_nodes() == 5 * 4);
  CHECK(fe.num_elements() == 4 * 4 + 3 * 5 + 4 * 3);
  CHECK_CLOSE(fe.nodes()[5 * 2 + 3], Vec2(1.5, 0.5), (Tolerance{1e-15, 0}), "node (i, j) at (i w, j h)");
  // Cell (0, 0) has the rising diagonal 0-6, cell (1, 0) the falling one 2-6.
  int rising = 0, falling = 0;
  for (const BeamElement& e : fe.elements()) {
    rising += (e.node_a == 0 && e.node_b == 6);
    falling += (e.node_a == 2 && e.node_b == 6);
  }
  CHECK(rising == 1);
  CHECK(falling == 1);
  CHECK_THROWS_AS(frame_lattice(0, 3, 0.5, 0.5, kSteel), ModelError);
  CHECK_THROWS_AS(frame_lattice(2, 3, -0.5, 0.5, kSteel), ModelError);
}

TEST_CASE("sparse_fe_matrices: the dense assembly of module 5 as sparse matrices", "[sparse]") {
  const FeModel fe = frame_lattice(3, 2, 0.5, 0.4, kSteel);
  for (MassMatrixType type : {MassMatrixType::consistent, MassMatrixType::lumped}) {
    const SparseFeMatrices sparse = sparse_fe_matrices(fe, type);
    const FeMatrices dense = assemble(fe, type);
    CHECK(relative_difference(MatX(sparse.K), dense.K) < 1e-14);
    CHECK(relative_difference(MatX(sparse.M), dense.M) < 1e-14);
    const FeMatrices back = to_dense(sparse);
    CHECK(relative_difference(back.M, dense.M) < 1e-14);
  }
  // The lumped mass matrix stays diagonal: exact zeros are not stored.
  const SparseFeMatrices lumped = sparse_fe_matrices(fe, MassMatrixType::lumped);
  CHECK(lumped.M.nonZeros() == fe.num_dofs());
  CHECK_THROWS_AS(sparse_fe_matrices(FeModel(), MassMatrixType::consistent), ModelError);
}

TEST_CASE("reduce_sparse and sparse_block pick rows and columns like the dense reduce", "[sparse]") {
  const FeModel fe = frame_lattice(2, 2, 0.5, 0.5, kSteel);
  const SparseFeMatrices sparse = sparse_fe_matrices(fe, MassMatrixType::consistent);
  const DofMap map = apply_supports(fe, {{0, Support::clamped}, {2, Support::hinged}});
  CHECK(relative_difference(MatX(reduce_sparse(sparse.K, map)), reduce(MatX(sparse.K), map)) == 0.0);
  const MatX block = MatX(sparse_block(sparse.M, {5, 1, 7}, {2, 0}));
  const MatX M = MatX(sparse.M);
  CHECK(block(0, 0) == M(5, 2));
  CHECK(block(1, 1) == M(1, 0));
  CHECK(block(2, 0) == M(7, 2));
  CHECK_THROWS_AS(sparse_block(sparse.M, {0, 99}, {0}), std::invalid_argument);
}

// ---- sparse_lowest_modes against the dense modal_analysis and closed forms ----------------------

TEST_CASE("sparse_lowest_modes: a clamped lattice has the dense frequencies and mode shapes", "[sparse]") {
  const FeModel fe = frame_lattice(4, 3, 0.5, 0.4, kSteel);
  const SparseFeMatrices sparse = sparse_fe_matrices(fe, MassMatrixType::consistent);
  const DofMap map = apply_supports(fe, clamp_bottom_row(4));
  const SparseMat K = reduce_sparse(sparse.K, map), M = reduce_sparse(sparse.M, map);
  const int count = 10;
  const Modes s = sparse_lowest_modes(K, M, count);
  const Modes d = modal_analysis(MatX(K), MatX(M), count + 4);
  REQUIRE(s.omega.size() == count);
  CHECK_CLOSE(s.omega, VecX(d.omega.head(count)), (Tolerance{0, 1e-9}), "the lowest frequencies, ascending");
  check_same_modes(s, d, MatX(M));
  check_mass_normalised(s, MatX(M));
  const MatX KK = s.shapes.transpose() * MatX(K) * s.shapes;
  CHECK_CLOSE(KK, MatX(s.omega.array().square().matrix().asDiagonal()), (Tolerance{1e-6 * KK.maxCoeff(), 0}),
              "phi^T K phi = diag(omega^2)");
}

TEST_CASE("sparse_lowest_modes: a free-free lattice with the default shift has three zero modes", "[sparse]") {
  const FeModel fe = frame_lattice(5, 2, 0.5, 0.5, kSteel);
  for (MassMatrixType type : {MassMatrixType::consistent, MassMatrixType::lumped}) {
    const SparseFeMatrices sparse = sparse_fe_matrices(fe, type);
    const int count = 9;
    const Modes s = sparse_lowest_modes(sparse.K, sparse.M, count);
    const Modes d = modal_analysis(MatX(sparse.K), MatX(sparse.M), count + 4);
    CHECK_CLOSE(VecX(s.omega.tail(count - 3)), VecX(d.omega.segment(3, count - 3)), (Tolerance{0, 1e-9}),
                "the elastic frequencies");
    CHECK(s.omega.head(3).maxCoeff() < 1e-4 * s.omega(3));
    // The zero modes are rigid motions: K phi = 0.
    const double k_scale = MatX(sparse.K).cwiseAbs().maxCoeff();
    for (int i = 0; i < 3; ++i)
      CHECK((sparse.K * s.shapes.col(i)).norm() < 1e-8 * k_scale * s.shapes.col(i).norm());
    check_same_modes(s, d, MatX(sparse.M));
    check_mass_normalised(s, MatX(sparse.M));
  }
}

TEST_CASE("sparse_lowest_modes: cantilever and free-free beam frequencies of Euler-Bernoulli theory", "[sparse]") {
  const double L = 1.2;
  const Section section = square_section(2.1e11, 7850.0, 0.01);
  const FeModel fe = straight_beam(L, 40, section, Vec2(0.3, -0.2), 0.4);
  const SparseFeMatrices sparse = sparse_fe_matrices(fe, MassMatrixType::consistent);
  const double unit = std::sqrt(section.E * section.I / (section.rho * section.A * std::pow(L, 4)));

  // Clamped-free: beta L of Blevins, table 8-1.
  const DofMap map = apply_supports(fe, {{0, Support::clamped}});
  const Modes cantilever = sparse_lowest_modes(reduce_sparse(sparse.K, map), reduce_sparse(sparse.M, map), 4);
  const double clamped_free[4] = {1.87510407, 4.69409113, 7.85475744, 10.99554073};
  for (int i = 0; i < 4; ++i)
    CHECK_NEAR(cantilever.omega(i), clamped_free[i] * clamped_free[i] * unit, (Tolerance{0, 1e-5}),
               "cantilever mode " + std::to_string(i + 1));

  // Free-free: three zero modes, then beta L = 4.73004, 7.85320, 10.99561.
  const Modes free_free = sparse_lowest_modes(sparse.K, sparse.M, 6);
  const double free[3] = {4.73004074, 7.85320462, 10.99560784};
  for (int i = 0; i < 3; ++i)
    CHECK_NEAR(free_free.omega(3 + i), free[i] * free[i] * unit, (Tolerance{0, 1e-5}),
               "free-free mode " + std::to_string(i + 1));
  CHECK(free_free.omega.head(3).maxCoeff() < 1e-4 * free_free.omega(3));
}

TEST_CASE("sparse_lowest_modes: a long free-free beam keeps all three rigid-body modes", "[sparse]") {
  // 2000 elements: the triple zero eigenvalue is where Lanczos alone may return too few copies;
  // the Sturm count must bring the missing one back, so that the elastic modes keep their place.
  const Section section = square_section(2.1e11, 7850.0, 0.01);
  const FeModel fe = straight_beam(1.0, 2000, section);
  const SparseFeMatrices sparse = sparse_fe_matrices(fe, MassMatrixType::consistent);
  const Modes modes = sparse_lowest_modes(sparse.K, sparse.M, 6);
  const double unit = std::sqrt(section.E * section.I / (section.rho * section.A));
  CHECK(modes.omega.head(3).maxCoeff() < 1e-2 * modes.omega(3));
  CHECK_NEAR(modes.omega(3), 4.73004074 * 4.73004074 * unit, (Tolerance{0, 1e-5}), "free-free mode 1");
  CHECK_NEAR(modes.omega(4), 7.85320462 * 7.85320462 * unit, (Tolerance{0, 1e-5}), "free-free mode 2");
  CHECK_NEAR(modes.omega(5), 10.99560784 * 10.99560784 * unit, (Tolerance{0, 1e-5}), "free-free mode 3");
  check_mass_normalised(modes, MatX(sparse.M));
}

TEST_CASE("sparse_lowest_modes: the Sturm count finds every copy of a triple eigenvalue", "[sparse]") {
  // K = diag(1, 1, 1, 2, 3, ...), M = I: the lowest five eigenvalues are 1, 1, 1, 2, 3.
  const int n = 40;
  SparseMat K(n, n), M(n, n);
  for (int i = 0; i < n; ++i) {
    K.insert(i, i) = i < 3 ? 1.0 : i - 1.0;
    M.insert(i, i) = 1.0;
  }
  const Modes modes = sparse_lowest_modes(K, M, 5, 0.0);
  CHECK_CLOSE(VecX(modes.omega.array().square()), (VecX(5) << 1, 1, 1, 2, 3).finished(), (Tolerance{1e-12, 1e-12}),
              "three copies of lambda = 1");
  // The three shapes span the first three coordinates.
  CHECK(std::abs(std::abs(modes.shapes.topLeftCorner(3, 3).determinant()) - 1.0) < 1e-9);
}

TEST_CASE("sparse_lowest_modes: an explicit shift gives the same modes", "[sparse]") {
  const FeModel fe = frame_lattice(3, 3, 0.5, 0.5, kSteel);
  const SparseFeMatrices sparse = sparse_fe_matrices(fe, MassMatrixType::lumped);
  const Modes automatic = sparse_lowest_modes(sparse.K, sparse.M, 7);
  const Modes shifted = sparse_lowest_modes(sparse.K, sparse.M, 7, -0.3 * automatic.omega(3) * automatic.omega(3));
  CHECK_CLOSE(VecX(shifted.omega.tail(4)), VecX(automatic.omega.tail(4)), (Tolerance{0, 1e-9}), "same frequencies");
  CHECK(default_shift(sparse.K, sparse.M) < 0.0);
}

TEST_CASE("sparse_lowest_modes: named exceptions for a singular shift and for no convergence", "[sparse]") {
  const FeModel fe = frame_lattice(4, 3, 0.5, 0.4, kSteel);
  const SparseFeMatrices sparse = sparse_fe_matrices(fe, MassMatrixType::consistent);
  // sigma = 0 on a free-free model: K itself is singular.
  CHECK_THROWS_MENTIONING(sparse_lowest_modes(sparse.K, sparse.M, 5, 0.0), SingularShiftedMatrix,
                          "use a negative shift");
  // A shift above the lowest elastic eigenvalue would return the modes nearest it.
  const Modes modes = sparse_lowest_modes(sparse.K, sparse.M, 5);
  CHECK_THROWS_MENTIONING(sparse_lowest_modes(sparse.K, sparse.M, 5, 1.5 * modes.omega(4) * modes.omega(4)),
                          std::invalid_argument, "lies above");
  // Too few restarts with a small subspace.
  ShiftInvertOptions starved;
  starved.subspace = 11;
  starved.max_restarts = 1;
  starved.tolerance = 1e-14;
  CHECK_THROWS_MENTIONING(sparse_lowest_modes(sparse.K, sparse.M, 10, starved), EigenSolverNotConverged,
                          "restarts");
}

TEST_CASE("sparse_lowest_modes: argument checks", "[sparse]") {
  const FeModel fe = frame_lattice(2, 1, 0.5, 0.5, kSteel);
  const SparseFeMatrices sparse = sparse_fe_matrices(fe, MassMatrixType::consistent);
  const int n = fe.num_dofs();
  CHECK_THROWS_MENTIONING(sparse_lowest_modes(sparse.K, sparse.M, 0), std::invalid_argument, "count");
  CHECK_THROWS_MENTIONING(sparse_lowest_modes(sparse.K, sparse.M, n), std::invalid_argument, "count");
  SparseMat asymmetric = sparse.K;
  asymmetric.coeffRef(0, 1) += 1e3 * MatX(sparse.K).cwiseAbs().maxCoeff();
  CHECK_THROWS_MENTIONING(sparse_lowest_modes(asymmetric, sparse.M, 3), std::invalid_argument, "not symmetric");
  const SparseMat smaller = sparse_block(sparse.M, {0, 1, 2}, {0, 1, 2});
  CHECK_THROWS_MENTIONING(sparse_lowest_modes(sparse.K, smaller, 3), std::invalid_argument, "expected");
  SparseMat massless = sparse.M;
  massless.coeffRef(4, 4) = 0.0;
  CHECK_THROWS_MENTIONING(sparse_lowest_modes(sparse.K, massless, 3), std::invalid_argument, "positive definite");
}

// ---- Matrix Market and node tables ---------------------------------------------------------------

TEST_CASE("write_matrix_market and read_matrix_market round-trip exactly", "[sparse][files]") {
  TempDir dir;
  const FeModel fe = frame_lattice(3, 2, 0.37, 0.29, kSteel);
  const SparseFeMatrices sparse = sparse_fe_matrices(fe, MassMatrixType::consistent);
  write_matrix_market(dir.path("K.mtx"), sparse.K);
  write_matrix_market(dir.path("M.mtx"), sparse.M);
  CHECK((MatX(read_matrix_market(dir.path("K.mtx"))) - MatX(sparse.K)).cwiseAbs().maxCoeff() == 0.0);
  CHECK((MatX(read_matrix_market(dir.path("M.mtx"), MatrixShape::symmetric)) - MatX(sparse.M)).cwiseAbs().maxCoeff() ==
        0.0);
  // Only symmetric matrices are written.
  SparseMat asymmetric = sparse.K;
  asymmetric.coeffRef(3, 0) += 1.0e12;
  CHECK_THROWS_AS(write_matrix_market(dir.path("A.mtx"), asymmetric), std::invalid_argument);
  CHECK_THROWS_AS(write_matrix_market(dir.path("missing-folder/K.mtx"), sparse.K), FeFileError);
}

TEST_CASE("read_matrix_market: symmetric and general files with comments and repeated entries", "[sparse][files]") {
  TempDir dir;
  CHECK(MatX(read_matrix_market(dir.write("small.mtx", kSmallSymmetric))) == small_symmetric());
  // A general file, CRLF line ends, a repeated entry summed: (2, 2) = 1.5 + 1.0.
  const std::string general =
      "%%MatrixMarket Matrix Coordinate Real General\r\n"
      "%\r\n"
      "3 3 6\r\n"
      "1 1 2\r\n"
      "1 2 -1\r\n"
      "2 1 -1\r\n"
      "2 2 1.5\r\n"
      "3 3 1\r\n"
      "2 2 1.0\r\n";
  CHECK(MatX(read_matrix_market(dir.write("general.mtx", general), MatrixShape::symmetric)) == small_symmetric());
  // A rectangular general matrix is read as it is where no shape is demanded.
  const MatX rect = MatX(read_matrix_market(dir.write("rect.mtx", "%%MatrixMarket matrix coordinate integer general\n"
                                                                     "2 3 2\n1 3 4\n2 1 -2\n")));
  CHECK(rect.rows() == 2);
  CHECK(rect.cols() == 3);
  CHECK(rect(0, 2) == 4.0);
  CHECK(rect(1, 0) == -2.0);
}

TEST_CASE("read_matrix_market: the example of the module 5 README is a one-element cantilever", "[sparse][files]") {
  TempDir dir;
  const std::string example =
      "%%MatrixMarket matrix coordinate real symmetric\n"
      "% one-element cantilever, DOFs u_x, u_y, psi of node 1\n"
      "3 3 4\n"
      "1 1 2.0e8\n"
      "2 2 2.4e5\n"
      "3 2 -1.2e5\n"
      "3 3 8.0e4\n";
  const FeModel fe = straight_beam(1.0, 1, Section{2e11, 7850.0, 1e-3, 1e-7});
  const DofMap map = apply_supports(fe, {{0, Support::clamped}});
  const MatX K_ff = MatX(reduce_sparse(sparse_fe_matrices(fe, MassMatrixType::consistent).K, map));
  CHECK(relative_difference(MatX(read_matrix_market(dir.write("stiffness.mtx", example))), K_ff) < 1e-15);
  const NodeTable table = read_node_table(
      dir.write("nodes.txt", "# x    y    dof_ux  dof_uy  dof_psi\n0.0    0.0  -1      -1      -1\n"
                             "1.0    0.0   0       1       2\n"),
      3);
  CHECK(table.num_nodes() == 2);
  CHECK(table.dofs[1][1] == 1);
  std::string wrong = example;
  wrong.replace(wrong.find("2 2 2.4e5"), 9, "4 2 2.4e5");
  CHECK_THROWS_MENTIONING(read_matrix_market(dir.write("stiffness.mtx", wrong)), FeFileError,
                          "stiffness.mtx:5: row index 4 is outside 1 .. 3");
}

TEST_CASE("load_sparse_fe_model: permuted DOF numbers and removed DOFs map back to the nodes", "[sparse][files]") {
  TempDir dir;
  // A cantilever: node 0 is clamped, so its DOFs are not in the matrices; the others are numbered
  // in reverse order.
  const int elements = 12;
  const FeModel fe = straight_beam(0.8, elements, kSteel);
  const SparseFeMatrices full = sparse_fe_matrices(fe, MassMatrixType::consistent);
  const DofMap map = apply_supports(fe, {{0, Support::clamped}});
  const int n = map.num_free();
  std::vector<int> order(n);  // order[r]: the free DOF written as row r
  for (int r = 0; r < n; ++r) order[r] = map.free[n - 1 - r];
  write_matrix_market(dir.path("mass.mtx"), sparse_block(full.M, order, order));
  write_matrix_market(dir.path("stiffness.mtx"), sparse_block(full.K, order, order));
  NodeTable table;
  for (int k = 0; k < fe.num_nodes(); ++k) {
    table.nodes.push_back(fe.nodes()[k]);
    NodeDofNumbers dofs{-1, -1, -1};
    for (int r = 0; r < n; ++r)
      if (order[r] / 3 == k) dofs[order[r] % 3] = r;
    table.dofs.push_back(dofs);
  }
  write_node_table(dir.path("nodes.txt"), table);

  const SparseFeModel model = load_sparse_fe_model(dir.path("mass.mtx"), dir.path("stiffness.mtx"), dir.path("nodes.txt"));
  REQUIRE(model.num_nodes() == fe.num_nodes());
  REQUIRE(model.num_dofs() == n);
  CHECK_CLOSE(model.table.nodes[elements], fe.nodes()[elements], (Tolerance{0, 0}), "node coordinates read back");
  CHECK(model.dof(0, NodeDof::uy) == -1);
  CHECK(model.dof(elements, NodeDof::psi) == 0);
  CHECK(model.dof(1, NodeDof::ux) == n - 1);

  // Same modes as the model in its own order; the tip deflection of mode 1 found through the table.
  const Modes original = sparse_lowest_modes(reduce_sparse(full.K, map), reduce_sparse(full.M, map), 3);
  const Modes loaded = sparse_lowest_modes(model.K, model.M, 3);
  CHECK_CLOSE(loaded.omega, original.omega, (Tolerance{0, 1e-10}), "the same frequencies");
  const VecX tip_original = expand(VecX(original.shapes.col(0)), map);
  const double a = tip_original(dof_index(elements, NodeDof::uy));
  const double b = loaded.shapes(model.dof(elements, NodeDof::uy), 0);
  CHECK(std::abs(std::abs(a) - std::abs(b)) < 1e-8 * std::abs(a));
}

TEST_CASE("read_matrix_market: every fault names the file and its line", "[sparse][files]") {
  TempDir dir;
  struct Case {
    const char* name;
    const char* text;
    const char* where;  // "name:line:"
    const char* what;
  };
  const Case cases[] = {
      {"empty.mtx", "", "empty.mtx:1:", "empty"},
      {"array.mtx", "%%MatrixMarket matrix array real general\n2 2\n1\n0\n0\n1\n", "array.mtx:1:", "coordinate"},
      {"banner.mtx", "%MatrixMarket matrix coordinate real general\n1 1 1\n1 1 1\n", "banner.mtx:1:", "header"},
      {"complex.mtx", "%%MatrixMarket matrix coordinate complex general\n1 1 1\n1 1 1 0\n", "complex.mtx:1:", "field"},
      {"hermitian.mtx", "%%MatrixMarket matrix coordinate real hermitian\n1 1 1\n1 1 1\n", "hermitian.mtx:1:",
       "symmetry"},
      {"nosize.mtx", "%%MatrixMarket matrix coordinate real general\n% only comments\n", "nosize.mtx:3:", "size line"},
      {"size.mtx", "%%MatrixMarket matrix coordinate real general\n%\n3 x 4\n", "size.mtx:3:", "three integers"},
      {"huge.mtx", "%%MatrixMarket matrix coordinate real general\n300000000 3 1\n1 1 1\n", "huge.mtx:2:",
       "1 .. 10^8"},
      {"count.mtx", "%%MatrixMarket matrix coordinate real general\n3 3 50000000\n1 1 1\n", "count.mtx:2:",
       "holds only 1"},
      {"few.mtx", "%%MatrixMarket matrix coordinate real symmetric\n% c\n3 3 4\n1 1 1\n2 2 1\n3 3 1\n", "few.mtx:3:",
       "holds only 3"},
      {"many.mtx", "%%MatrixMarket matrix coordinate real symmetric\n3 3 2\n1 1 1\n2 2 1\n\n3 3 1\n", "many.mtx:6:",
       "more entries than the 2"},
      {"range.mtx", "%%MatrixMarket matrix coordinate real general\n3 3 3\n1 1 1\n2 2 1\n4 3 1\n", "range.mtx:5:",
       "outside 1 .. 3"},
      {"zero.mtx", "%%MatrixMarket matrix coordinate real general\n3 3 2\n1 1 1\n2 0 1\n", "zero.mtx:4:",
       "column index 0"},
      {"text.mtx", "%%MatrixMarket matrix coordinate real general\n3 3 2\n1 1 1\n% c\n2 2 abc\n", "text.mtx:5:",
       "'abc' is not a number"},
      {"index.mtx", "%%MatrixMarket matrix coordinate real general\n3 3 2\n1 1 1\n2.5 2 1\n", "index.mtx:4:",
       "not an integer"},
      {"nan.mtx", "%%MatrixMarket matrix coordinate real general\n3 3 2\n1 1 nan\n2 2 1\n", "nan.mtx:3:", "not finite"},
      {"fields.mtx", "%%MatrixMarket matrix coordinate real general\n3 3 2\n1 1 1\n2 2\n", "fields.mtx:4:",
       "three fields"},
      {"upper.mtx", "%%MatrixMarket matrix coordinate real symmetric\n3 3 3\n1 1 1\n1 2 5\n2 2 1\n", "upper.mtx:4:",
       "above the diagonal"},
      {"square.mtx", "%%MatrixMarket matrix coordinate real symmetric\n\n3 4 1\n1 1 1\n", "square.mtx:3:", "square"},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    const std::string path = dir.write(c.name, c.text);
    CHECK_THROWS_MENTIONING(read_matrix_market(path), FeFileError, c.where);
    CHECK_THROWS_MENTIONING(read_matrix_market(path), FeFileError, c.what);
  }
  // A general file that is not symmetric, where symmetry is demanded: the line of the entry.
  const std::string asymmetric = dir.write("asym.mtx",
                                           "%%MatrixMarket matrix coordinate real general\n3 3 4\n1 1 2\n"
                                           "2 2 2\n3 1 0.5\n3 3 2\n");
  CHECK_NOTHROW(read_matrix_market(asymmetric));
  CHECK_THROWS_MENTIONING(read_matrix_market(asymmetric, MatrixShape::symmetric), FeFileError, "asym.mtx:5:");
  CHECK_THROWS_MENTIONING(read_matrix_market(asymmetric, MatrixShape::symmetric), FeFileError, "(1, 3) = 0 (no entry)");
  const std::string rectangular =
      dir.write("rectangular.mtx", "%%MatrixMarket matrix coordinate real general\n%\n2 3 1\n1 1 1\n");
  CHECK_THROWS_MENTIONING(read_matrix_market(rectangular, MatrixShape::symmetric), FeFileError, "rectangular.mtx:3:");
  // A file that does not exist.
  try {
    read_matrix_market(dir.path("absent.mtx"));
    FAIL("no exception");
  } catch (const FeFileError& e) {
    CHECK(e.line() == 0);
    CHECK(e.path() == dir.path("absent.mtx"));
    CHECK(std::string(e.what()).find("absent.mtx: cannot open") != std::string::npos);
  }
}

TEST_CASE("load_sparse_fe_model: every fault of a node table or a size mismatch names the file and line", "[sparse][files]") {
  TempDir dir;
  const std::string mass = dir.write("m.mtx", kSmallSymmetric);
  const std::string stiffness = dir.write("k.mtx", kSmallSymmetric);
  const std::string good = dir.write("good.txt", "# x y ux uy psi\n0 0 -1 -1 -1\n\n1.5 0  0 1 2  # the free node\n");
  const SparseFeModel model = load_sparse_fe_model(mass, stiffness, good);
  CHECK(model.num_nodes() == 2);
  CHECK(model.dof(1, NodeDof::psi) == 2);
  CHECK(model.table.nodes[1].x() == 1.5);

  struct Case {
    const char* name;
    const char* text;
    const char* where;
    const char* what;
  };
  const Case cases[] = {
      {"outside.txt", "0 0 -1 -1 -1\n# c\n1 0 0 1 3\n", "outside.txt:3:", "DOF number 3 of psi is outside the matrices"},
      {"negative.txt", "0 0 -2 0 1\n", "negative.txt:1:", "outside the matrices"},
      {"twice.txt", "0 0 0 1 -1\n1 0 2 -1 -1\n\n2 0 -1 1 -1\n", "twice.txt:4:",
       "DOF number 1 of u_y is already used by u_y of node 0 (line 1)"},
      {"fields.txt", "0 0 0 1\n", "fields.txt:1:", "five fields"},
      {"coordinate.txt", "# header\n0 zero 0 1 2\n", "coordinate.txt:2:", "'zero' is not a number"},
      {"integer.txt", "0 0 0 1.0 2\n", "integer.txt:1:", "not an integer"},
      {"nodes.txt", "# nothing\n\n", "nodes.txt:", "no nodes"},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    const std::string path = dir.write(c.name, c.text);
    CHECK_THROWS_MENTIONING(load_sparse_fe_model(mass, stiffness, path), FeFileError, c.where);
    CHECK_THROWS_MENTIONING(load_sparse_fe_model(mass, stiffness, path), FeFileError, c.what);
  }

  // M and K of different sizes: at the size line of the stiffness file, naming the mass file.
  const std::string bigger = dir.write("k4.mtx", "%%MatrixMarket matrix coordinate real symmetric\n% c\n4 4 1\n4 4 1\n");
  CHECK_THROWS_MENTIONING(load_sparse_fe_model(mass, bigger, good), FeFileError, "k4.mtx:3:");
  CHECK_THROWS_MENTIONING(load_sparse_fe_model(mass, bigger, good), FeFileError, "m.mtx:4");
  // A general stiffness file that is not symmetric.
  const std::string general = dir.write("kg.mtx", "%%MatrixMarket matrix coordinate real general\n3 3 4\n1 1 2\n2 1 -1\n"
                                                  "2 2 2\n3 3 1\n");
  CHECK_THROWS_MENTIONING(load_sparse_fe_model(mass, general, good), FeFileError, "kg.mtx:4:");
}

// ---- sparse Craig-Bampton ------------------------------------------------------------------------

TEST_CASE("sparse_craig_bampton: the basis and reduced frequencies of the dense craig_bampton", "[sparse][reduction]") {
  const FeModel fe = straight_beam(1.0, 30, square_section(2.1e11, 7850.0, 0.01));
  const SparseFeMatrices sparse = sparse_fe_matrices(fe, MassMatrixType::consistent);
  const FeMatrices dense = to_dense(sparse);
  const std::vector<int> interface = node_dofs({0, 30});
  const int modes = 6;
  const ReducedBasis s = sparse_craig_bampton(sparse.K, sparse.M, interface, modes);
  const ReducedBasis d = craig_bampton(dense.K, dense.M, interface, modes);
  REQUIRE(s.size() == d.size());
  CHECK(s.num_rigid == 0);
  // The constraint modes are unique; the normal modes are equal up to sign.
  CHECK(relative_difference(MatX(s.Phi.leftCols(6)), MatX(d.Phi.leftCols(6))) < 1e-9);
  for (int c = 6; c < s.size(); ++c) {
    const double dot = s.Phi.col(c).dot(dense.M * d.Phi.col(c));
    CHECK(std::abs(std::abs(dot) - 1.0) < 1e-8);
  }
  const VecX ls = reduced_eigenvalues(s), ld = reduced_eigenvalues(d);
  // Three rigid motions of the free beam (zero), then the elastic ones agree.
  CHECK_CLOSE(VecX(ls.tail(ls.size() - 3)), VecX(ld.tail(ld.size() - 3)), (Tolerance{0, 1e-8}),
              "the reduced frequencies");
  CHECK_CLOSE(s.M_bar, d.M_bar.cwiseAbs().cwiseProduct(s.M_bar.cwiseSign()), (Tolerance{1e-9 * s.M_bar.norm(), 0}),
              "M_bar up to the signs of the normal modes");

  // ffrf_basis of module 6 takes the sparse basis unchanged.
  const ReducedBasis fs = ffrf_basis(fe, dense, s), fd = ffrf_basis(fe, dense, d);
  REQUIRE(fs.size() == fd.size());
  CHECK_CLOSE(VecX(fs.K_bar.diagonal()), VecX(fd.K_bar.diagonal()),
              (Tolerance{1e-8 * fd.K_bar.diagonal().maxCoeff(), 1e-8}),
              "the FFRF basis of both has the same elastic frequencies");
}

TEST_CASE("sparse_craig_bampton: a lattice clamped along its base row as the interface", "[sparse][reduction]") {
  const FeModel fe = frame_lattice(4, 3, 0.5, 0.4, kSteel);
  const SparseFeMatrices sparse = sparse_fe_matrices(fe, MassMatrixType::lumped);
  const FeMatrices dense = to_dense(sparse);
  const std::vector<int> interface = node_dofs({0, 1, 2, 3, 4});
  const ReducedBasis s = sparse_craig_bampton(sparse.K, sparse.M, interface, 8);
  const ReducedBasis d = craig_bampton(dense.K, dense.M, interface, 8);
  CHECK_CLOSE(reduced_eigenvalues(s), reduced_eigenvalues(d), (Tolerance{1e-6 * reduced_eigenvalues(d)(4), 1e-8}),
              "the reduced frequencies");
  // With the interface held, the normal-mode block is the clamped lattice: its frequencies.
  const MatX K_nn = s.K_bar.bottomRightCorner(8, 8), M_nn = s.M_bar.bottomRightCorner(8, 8);
  CHECK_CLOSE(M_nn, MatX::Identity(8, 8), (Tolerance{1e-10, 0}), "mass-normalised normal modes");
  const DofMap map = apply_supports(fe, clamp_bottom_row(4));
  const Modes clamped = modal_analysis(reduce(dense.K, map), reduce(dense.M, map), 8);
  CHECK_CLOSE(VecX(K_nn.diagonal()), VecX(clamped.omega.array().square().matrix()), (Tolerance{0, 1e-8}),
              "the fixed-interface frequencies");
}

TEST_CASE("sparse_craig_bampton: argument checks and a singular K_ii", "[sparse][reduction]") {
  const FeModel fe = straight_beam(1.0, 6, kSteel);
  const SparseFeMatrices sparse = sparse_fe_matrices(fe, MassMatrixType::consistent);
  CHECK_THROWS_MENTIONING(sparse_craig_bampton(sparse.K, sparse.M, {}, 2), std::invalid_argument, "no DOFs");
  CHECK_THROWS_MENTIONING(sparse_craig_bampton(sparse.K, sparse.M, {0, 0}, 2), std::invalid_argument, "twice");
  CHECK_THROWS_MENTIONING(sparse_craig_bampton(sparse.K, sparse.M, {21}, 2), std::invalid_argument, "out of range");
  CHECK_THROWS_MENTIONING(sparse_craig_bampton(sparse.K, sparse.M, node_dofs({0}), 18), std::invalid_argument,
                          "num_modes");
  CHECK_THROWS_MENTIONING(sparse_craig_bampton(sparse.K, sparse.M, {0, 1}, 2), std::invalid_argument,
                          "K_ii is singular");
  const ReducedBasis static_only = sparse_craig_bampton(sparse.K, sparse.M, node_dofs({0}), 0);
  CHECK(static_only.size() == 3);
}
