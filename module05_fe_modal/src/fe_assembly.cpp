// Exercise file of module 5, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory and the hints.
// Module 5, task T3: assembly of M_FE and K_FE.
#include "fmbd/errors.hpp"
#include "fmbd/fe_assembly.hpp"

namespace fmbd {

FeMatrices assemble(const FeModel& fe, MassMatrixType type) {
  fe.validate();
  // TODO(M05T3): start from zero matrices of size fe.num_dofs(). For each element e
  //   (fe.elements()[e] has node_a, node_b and section), with L = fe.length(e),
  //   T = beam_transformation(fe.angle(e)):
  //     k = T^T beam_stiffness(section, L) T,   m = T^T beam_mass(section, L, type) T,
  //   then add the 3x3 blocks of k and m: element DOFs 0..2 belong to node a (global 3a..3a+2),
  //   3..5 to node b (global 3b..3b+2).
  unused(fe, type);
  throw NotImplemented("M05T3 assemble");
}

}  // namespace fmbd
