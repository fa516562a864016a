// Module 5, task T3: assembly of M_FE and K_FE.
#include "fmbd/errors.hpp"
#include "fmbd/fe_assembly.hpp"

namespace fmbd {

FeMatrices assemble(const FeModel& fe, MassMatrixType type) {
  fe.validate();
  // TASK(M05T3): start from zero matrices of size fe.num_dofs(). For each element e
  //   (fe.elements()[e] has node_a, node_b and section), with L = fe.length(e),
  //   T = beam_transformation(fe.angle(e)):
  //     k = T^T beam_stiffness(section, L) T,   m = T^T beam_mass(section, L, type) T,
  //   then add the 3x3 blocks of k and m: element DOFs 0..2 belong to node a (global 3a..3a+2),
  //   3..5 to node b (global 3b..3b+2).
  // BEGIN SOLUTION
  const int n = fe.num_dofs();
  FeMatrices out{MatX::Zero(n, n), MatX::Zero(n, n)};
  for (int e = 0; e < fe.num_elements(); ++e) {
    const BeamElement& el = fe.elements()[e];
    const double L = fe.length(e);
    const Mat6 T = beam_transformation(fe.angle(e));
    const Mat6 k = T.transpose() * beam_stiffness(el.section, L) * T;
    const Mat6 m = T.transpose() * beam_mass(el.section, L, type) * T;
    const int at[2] = {3 * el.node_a, 3 * el.node_b};
    for (int r = 0; r < 2; ++r)
      for (int c = 0; c < 2; ++c) {
        out.K.block<3, 3>(at[r], at[c]) += k.block<3, 3>(3 * r, 3 * c);
        out.M.block<3, 3>(at[r], at[c]) += m.block<3, 3>(3 * r, 3 * c);
      }
  }
  return out;
  // END SOLUTION
  // STUB: unused(fe, type);
  // STUB: throw NotImplemented("M05T3 assemble");
}

}  // namespace fmbd
