// Module 6, task T2: modal truncation on free-free modes, Phi = [Phi_r, Phi_f].
#include <string>

#include "fmbd/errors.hpp"
#include "fmbd/reduction.hpp"

namespace fmbd {

ReducedBasis modal_truncation(const FeModel& fe, const FeMatrices& matrices, int num_elastic) {
  const int n = fe.num_dofs();
  if (num_elastic < 0 || num_elastic > n - 3)
    throw std::invalid_argument("modal_truncation: num_elastic must be between 0 and " + std::to_string(n - 3) +
                                " (3 N - 3), got " + std::to_string(num_elastic));
  // TASK(M06T2): the basis Phi = [Phi_r, Phi_f] of README section 2 with `num_elastic` elastic
  //   free-free modes, num_rigid = 3, and its reduced matrices M_bar and K_bar (README
  //   introduction), modal_truncation.hpp.
  //   Build on rigid_body_modes and modal_analysis. Stuck? ./workbook hint M06T2
  // BEGIN SOLUTION
  const RigidBodyModes rigid = rigid_body_modes(fe, matrices.M);
  const Modes modes = modal_analysis(matrices.K, matrices.M, 3 + num_elastic);
  ReducedBasis basis;
  basis.num_rigid = 3;
  basis.Phi.resize(n, 3 + num_elastic);
  basis.Phi << rigid.Phi_r, modes.shapes.rightCols(num_elastic);
  basis.M_bar = basis.Phi.transpose() * matrices.M * basis.Phi;
  basis.K_bar = basis.Phi.transpose() * matrices.K * basis.Phi;
  return basis;
  // END SOLUTION
  // STUB: unused(fe, matrices, num_elastic);
  // STUB: throw NotImplemented("M06T2 modal_truncation");
}

}  // namespace fmbd
