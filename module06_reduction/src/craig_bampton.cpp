// Exercise file of module 6, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory and the hints.
// Module 6, tasks T3 and T4: Craig-Bampton, and a Craig-Bampton basis made ready for the FFRF.
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>

#include "fmbd/errors.hpp"
#include "fmbd/reduction.hpp"

namespace fmbd {

namespace {

// Interior DOFs: every index of 0 .. n-1 that is not an interface DOF, ascending.
std::vector<int> interior_dofs(int n, const std::vector<int>& interface) {
  std::vector<bool> is_interface(n, false);
  for (std::size_t r = 0; r < interface.size(); ++r) {
    const int b = interface[r];
    if (b < 0 || b >= n)
      throw std::invalid_argument("craig_bampton: interface DOF " + std::to_string(b) + " (entry " +
                                  std::to_string(r) + ") is out of range 0 .. " + std::to_string(n - 1));
    if (is_interface[b])
      throw std::invalid_argument("craig_bampton: interface DOF " + std::to_string(b) + " is listed twice");
    is_interface[b] = true;
  }
  std::vector<int> interior;
  for (int i = 0; i < n; ++i)
    if (!is_interface[i]) interior.push_back(i);
  return interior;
}

// A(rows, cols) for index lists.
[[maybe_unused]] MatX pick(const MatX& A, const std::vector<int>& rows, const std::vector<int>& cols) {
  MatX out(rows.size(), cols.size());
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (std::size_t c = 0; c < cols.size(); ++c) out(r, c) = A(rows[r], cols[c]);
  return out;
}

// Fills M_bar and K_bar of a basis.
[[maybe_unused]] ReducedBasis with_matrices(MatX Phi, const MatX& K, const MatX& M, int num_rigid) {
  ReducedBasis basis;
  basis.M_bar = Phi.transpose() * M * Phi;
  basis.K_bar = Phi.transpose() * K * Phi;
  basis.Phi = std::move(Phi);
  basis.num_rigid = num_rigid;
  return basis;
}

}  // namespace

ReducedBasis craig_bampton(const MatX& K, const MatX& M, const std::vector<int>& interface, int num_modes) {
  const int n = static_cast<int>(K.rows());
  if (K.cols() != n || M.rows() != n || M.cols() != n)
    throw std::invalid_argument("craig_bampton: K and M must both be n x n");
  if (interface.empty()) throw std::invalid_argument("craig_bampton: the interface has no DOFs");
  const std::vector<int> interior = interior_dofs(n, interface);
  [[maybe_unused]] const int n_b = static_cast<int>(interface.size());
  const int n_i = static_cast<int>(interior.size());
  if (num_modes < 0 || num_modes > n_i)
    throw std::invalid_argument("craig_bampton: num_modes must be between 0 and the " + std::to_string(n_i) +
                                " interior DOFs, got " + std::to_string(num_modes));
  const MatX K_ii = pick(K, interior, interior);
  const Eigen::LLT<MatX> K_ii_llt(K_ii);
  // A singular K_ii may factor with a tiny positive pivot after round-off: check the pivots too.
  const VecX pivots = K_ii_llt.matrixLLT().diagonal().cwiseAbs2();
  if (K_ii_llt.info() != Eigen::Success ||
      (pivots.size() > 0 && !(pivots.minCoeff() > 1e-12 * pivots.maxCoeff())))
    throw std::invalid_argument(
        "craig_bampton: K_ii is singular: with the interface DOFs fixed the interior can still move "
        "rigidly; choose interface DOFs that hold the body (for example all three DOFs of one node)");
  // TODO(M06T3): with K_ii_llt (the Cholesky factor of K_ii) and pick(A, rows, cols):
  //   Psi = -K_ii^{-1} K_ib (n_i x n_b), by K_ii_llt.solve(...), never an inverse;
  //   the fixed-interface modes Phi_i = modal_analysis(K_ii, M_ii, num_modes).shapes (n_i x num_modes;
  //   with num_modes = 0 there are none: modal_analysis needs at least one, so skip it);
  //   Phi (n x (n_b + num_modes)): row interface[r] is the unit row e_r in the first n_b columns
  //   (zeros after them); row interior[r] is [Psi.row(r), Phi_i.row(r)].
  //   Return with_matrices(Phi, K, M, 0).
  throw NotImplemented("M06T3 craig_bampton");
}

ReducedBasis ffrf_basis(const FeModel& fe, const FeMatrices& matrices, const ReducedBasis& basis) {
  [[maybe_unused]] const MatX& M = matrices.M;
  [[maybe_unused]] const MatX& K = matrices.K;
  if (basis.Phi.rows() != fe.num_dofs())
    throw std::invalid_argument("ffrf_basis: the basis has " + std::to_string(basis.Phi.rows()) +
                                " rows, the model has " + std::to_string(fe.num_dofs()) + " DOFs");
  // TODO(M06T4): four steps (README, section 4).
  //   1. Phi_r = rigid_body_modes(fe, M).Phi_r; remove the rigid content of every column:
  //      T_e = Phi - Phi_r (Phi_r^T M Phi_r)^{-1} Phi_r^T M Phi.
  //   2. Scale each column of T_e to unit M-norm, and drop columns whose M-norm fell below 1e-8
  //      of their norm before step 1 (they were rigid motions).
  //   3. The scaled columns may still be dependent: take the eigen-decomposition
  //      G = T_e^T M T_e = V diag(g) V^T (Eigen::SelfAdjointEigenSolver), keep the eigenvectors with
  //      g > 1e-10 g_max, and set S = T_e V_kept diag(g_kept)^{-1/2}, so that S^T M S = I.
  //   4. Diagonalise the stiffness: S^T K S = Z diag(omega^2) Z^T (ascending), Phi_f = S Z.
  //   Return with_matrices([Phi_r, Phi_f], K, M, 3).
  throw NotImplemented("M06T4 ffrf_basis");
}

}  // namespace fmbd
