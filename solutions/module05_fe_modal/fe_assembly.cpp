// Module 5, task T3: assembly of M_FE and K_FE.
#include "fmbd/errors.hpp"
#include "fmbd/fe_assembly.hpp"

namespace fmbd {

FeMatrices assemble(const FeModel& fe, MassMatrixType type) {
  fe.validate();
  // TASK(M05T3): M_FE and K_FE of the whole model (fe.num_dofs() square), README section 2,
  //   eq. (4), fe_assembly.hpp. Every element e (fe.elements()[e]: node_a, node_b, section;
  //   fe.length(e), fe.angle(e)) adds its matrices in global axes, built with your
  //   beam_transformation, beam_stiffness and beam_mass for the given mass type. Node k owns the
  //   global DOFs 3k .. 3k+2. Stuck? ./workbook hint M05T3
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
