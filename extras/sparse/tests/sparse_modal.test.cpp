// Tests of the sparse modal path (extras/sparse): sparse assembly, round trips of FE models through
// Matrix Market and node-table files (extras/fe_import tests the files themselves), the
// shift-invert Lanczos solver sparse_lowest_modes, and sparse Craig-Bampton. The oracles are the
// dense functions of modules 5 and 6 (reference) and Euler-Bernoulli closed forms; the sparse
// assembly calls the element routines of module 5, so this program links the reference stages.
#include <Eigen/Eigenvalues>
#include <cmath>
#include <string>
#include <vector>

#include "fe_files.hpp"
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
using fmbd::testing::TempDir;

namespace {

const Section kSteel = square_section(2.1e11, 7850.0, 0.02);

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
