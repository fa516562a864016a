// Exercise file of module 5, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 5, task T3: assembly of M_FE and K_FE.
#include "fmbd/errors.hpp"
#include "fmbd/fe_assembly.hpp"

namespace fmbd {

FeMatrices assemble(const FeModel& fe, MassMatrixType type) {
  fe.validate();
  // TODO(M05T3): M_FE and K_FE of the whole model (fe.num_dofs() square), README section 2,
  //   eq. (4), fe_assembly.hpp. Every element e (fe.elements()[e]: node_a, node_b, section;
  //   fe.length(e), fe.angle(e)) adds its matrices in global axes, built with your
  //   beam_transformation, beam_stiffness and beam_mass for the given mass type. Node k owns the
  //   global DOFs 3k .. 3k+2. Stuck? ./workbook hint M05T3
  unused(fe, type);
  throw NotImplemented("M05T3 assemble");
}

}  // namespace fmbd
