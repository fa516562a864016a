// Exercise file of module 6, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory and the hints.
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
  // TODO(M06T3): with K_ii_llt (the Cholesky factor of K_ii) and submatrix(A, rows, cols):
  //   Psi = -K_ii^{-1} K_ib (n_i x n_b), by K_ii_llt.solve(...), never an inverse;
  //   the fixed-interface modes Phi_i = modal_analysis(K_ii, M_ii, num_modes).shapes (n_i x num_modes;
  //   with num_modes = 0 there are none: modal_analysis needs at least one, so skip it);
  //   Phi (n x (n_b + num_modes)): row interface[r] is the unit row e_r in the first n_b columns
  //   (zeros after them); row interior[r] is [Psi.row(r), Phi_i.row(r)].
  //   Return with_matrices(Phi, K, M, 0).
  unused(K, M, interface, num_modes);
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
  unused(fe, matrices, basis);
  throw NotImplemented("M06T4 ffrf_basis");
}

}  // namespace fmbd
