// Module 6, tasks T3 and T4: Craig-Bampton, and a Craig-Bampton basis made ready for the FFRF.
#include <Eigen/Eigenvalues>
#include <cmath>
#include <string>

#include "fmbd/errors.hpp"
#include "fmbd/reduction.hpp"

namespace fmbd {

ReducedBasis craig_bampton(const MatX& K, const MatX& M, const std::vector<int>& interface, int num_modes) {
  // The argument checks, the interior DOFs and the Cholesky factor of K_ii are given
  // (split_interface, src/craig_bampton_given.cpp).
  const InterfaceSplit split = split_interface(K, M, interface, num_modes);
  [[maybe_unused]] const std::vector<int>& interior = split.interior;
  [[maybe_unused]] const MatX& K_ii = split.K_ii;
  [[maybe_unused]] const Eigen::LLT<MatX>& K_ii_llt = split.K_ii_llt;
  [[maybe_unused]] const int n = static_cast<int>(K.rows());
  [[maybe_unused]] const int n_b = static_cast<int>(interface.size());
  [[maybe_unused]] const int n_i = static_cast<int>(interior.size());
  // TASK(M06T3): with K_ii_llt (the Cholesky factor of K_ii) and submatrix(A, rows, cols):
  //   Psi = -K_ii^{-1} K_ib (n_i x n_b), by K_ii_llt.solve(...), never an inverse;
  //   the fixed-interface modes Phi_i = modal_analysis(K_ii, M_ii, num_modes).shapes (n_i x num_modes;
  //   with num_modes = 0 there are none: modal_analysis needs at least one, so skip it);
  //   Phi (n x (n_b + num_modes)): row interface[r] is the unit row e_r in the first n_b columns
  //   (zeros after them); row interior[r] is [Psi.row(r), Phi_i.row(r)].
  //   Return with_matrices(Phi, K, M, 0).
  // BEGIN SOLUTION
  const MatX Psi = -K_ii_llt.solve(submatrix(K, interior, interface));
  MatX Phi = MatX::Zero(n, n_b + num_modes);
  for (int r = 0; r < n_b; ++r) Phi(interface[r], r) = 1.0;
  for (int r = 0; r < n_i; ++r) Phi.row(interior[r]).head(n_b) = Psi.row(r);
  if (num_modes > 0) {
    const Modes fixed = modal_analysis(K_ii, submatrix(M, interior, interior), num_modes);
    for (int r = 0; r < n_i; ++r) Phi.row(interior[r]).tail(num_modes) = fixed.shapes.row(r);
  }
  return with_matrices(Phi, K, M, 0);
  // END SOLUTION
  // STUB: unused(K, M, interface, num_modes);
  // STUB: throw NotImplemented("M06T3 craig_bampton");
}

ReducedBasis ffrf_basis(const FeModel& fe, const FeMatrices& matrices, const ReducedBasis& basis) {
  [[maybe_unused]] const MatX& M = matrices.M;
  [[maybe_unused]] const MatX& K = matrices.K;
  if (basis.Phi.rows() != fe.num_dofs())
    throw std::invalid_argument("ffrf_basis: the basis has " + std::to_string(basis.Phi.rows()) +
                                " rows, the model has " + std::to_string(fe.num_dofs()) + " DOFs");
  // TASK(M06T4): four steps (README, section 4).
  //   1. Phi_r = rigid_body_modes(fe, M).Phi_r; remove the rigid content of every column:
  //      T_e = Phi - Phi_r (Phi_r^T M Phi_r)^{-1} Phi_r^T M Phi.
  //   2. Scale each column of T_e to unit M-norm, and drop columns whose M-norm fell below 1e-8
  //      of their norm before step 1 (they were rigid motions).
  //   3. The scaled columns may still be dependent: take the eigen-decomposition
  //      G = T_e^T M T_e = V diag(g) V^T (Eigen::SelfAdjointEigenSolver), keep the eigenvectors with
  //      g > 1e-10 g_max, and set S = T_e V_kept diag(g_kept)^{-1/2}, so that S^T M S = I.
  //   4. Diagonalise the stiffness: S^T K S = Z diag(omega^2) Z^T (ascending), Phi_f = S Z.
  //   Return with_matrices([Phi_r, Phi_f], K, M, 3).
  // BEGIN SOLUTION
  const MatX Phi_r = rigid_body_modes(fe, M).Phi_r;
  const MatX MPhi_r = M * Phi_r;
  const Eigen::Matrix3d M_rr = Phi_r.transpose() * MPhi_r;
  const MatX rigid_part = Phi_r * M_rr.ldlt().solve(MPhi_r.transpose() * basis.Phi);
  const MatX T = basis.Phi - rigid_part;

  std::vector<int> kept;
  for (int c = 0; c < T.cols(); ++c) {
    const double before = std::sqrt(basis.Phi.col(c).dot(M * basis.Phi.col(c)));
    const double after = std::sqrt(T.col(c).dot(M * T.col(c)));
    if (after > 1e-8 * before) kept.push_back(c);
  }
  MatX T_e(T.rows(), kept.size());
  for (std::size_t c = 0; c < kept.size(); ++c) {
    const VecX col = T.col(kept[c]);
    T_e.col(c) = col / std::sqrt(col.dot(M * col));
  }

  const Eigen::SelfAdjointEigenSolver<MatX> gram(T_e.transpose() * M * T_e);
  const VecX& g = gram.eigenvalues();
  const double g_max = g.size() > 0 ? g.maxCoeff() : 0.0;
  std::vector<int> independent;
  for (int c = 0; c < g.size(); ++c)
    if (g(c) > 1e-10 * g_max) independent.push_back(c);
  MatX S(T_e.rows(), independent.size());
  for (std::size_t c = 0; c < independent.size(); ++c)
    S.col(c) = T_e * gram.eigenvectors().col(independent[c]) / std::sqrt(g(independent[c]));

  const Eigen::SelfAdjointEigenSolver<MatX> stiffness(S.transpose() * K * S);
  MatX Phi(T.rows(), 3 + S.cols());
  Phi << Phi_r, S * stiffness.eigenvectors();
  return with_matrices(Phi, K, M, 3);
  // END SOLUTION
  // STUB: unused(fe, matrices, basis);
  // STUB: throw NotImplemented("M06T4 ffrf_basis");
}

}  // namespace fmbd
