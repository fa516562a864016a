// Exercise file of module 6, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
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
  // TODO(M06T3): the Craig-Bampton basis of README section 3, craig_bampton.hpp: the
  //   n_b constraint modes (in the order of `interface`), then the num_modes lowest fixed-interface
  //   normal modes; rows in the original DOF order; num_rigid = 0. Use K_ii_llt and submatrix, never
  //   an inverse, and modal_analysis, which needs count >= 1 (num_modes may be 0). Return
  //   with_matrices(...). Stuck? ./workbook hint M06T3
  unused(K, M, interface, num_modes);
  throw NotImplemented("M06T3 craig_bampton");
}

ReducedBasis ffrf_basis(const FeModel& fe, const FeMatrices& matrices, const ReducedBasis& basis) {
  [[maybe_unused]] const MatX& M = matrices.M;
  [[maybe_unused]] const MatX& K = matrices.K;
  if (basis.Phi.rows() != fe.num_dofs())
    throw std::invalid_argument("ffrf_basis: the basis has " + std::to_string(basis.Phi.rows()) +
                                " rows, the model has " + std::to_string(fe.num_dofs()) + " DOFs");
  // TODO(M06T4): the FFRF basis of any basis, README section 4 (four steps), craig_bampton.hpp:
  //   [Phi_r, Phi_f], num_rigid = 3, Phi_r from rigid_body_modes. Tolerances: drop a column whose
  //   M-norm after step 1 is at most 1e-8 of its M-norm before; in step 3 keep the eigenvalues
  //   above 1e-10 of the largest. Return with_matrices(...). Stuck? ./workbook hint M06T4
  unused(fe, matrices, basis);
  throw NotImplemented("M06T4 ffrf_basis");
}

}  // namespace fmbd
