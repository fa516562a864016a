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
  // TASK(M06T3): the Craig-Bampton basis of README section 3, craig_bampton.hpp: the
  //   n_b constraint modes (in the order of `interface`), then the num_modes lowest fixed-interface
  //   normal modes; rows in the original DOF order; num_rigid = 0. Use K_ii_llt and submatrix, never
  //   an inverse, and modal_analysis, which needs count >= 1 (num_modes may be 0). Return
  //   with_matrices(...). Stuck? ./workbook hint M06T3
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
  // TASK(M06T4): the FFRF basis of any basis, README section 4 (four steps), craig_bampton.hpp:
  //   [Phi_r, Phi_f], num_rigid = 3, Phi_r from rigid_body_modes. Tolerances: drop a column whose
  //   M-norm after step 1 is at most 1e-8 of its M-norm before; in step 3 keep the eigenvalues
  //   above 1e-10 of the largest. Return with_matrices(...). Stuck? ./workbook hint M06T4
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
