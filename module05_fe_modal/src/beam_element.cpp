// Exercise file of module 5, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 5, tasks T1 to T3: the planar Euler-Bernoulli frame element.
#include <cmath>

#include "fmbd/beam_element.hpp"
#include "fmbd/errors.hpp"

namespace fmbd {

Mat6 beam_stiffness(const Section& section, double L) {
  // TODO(M05T1): the stiffness matrix k_e of one beam element in its local axes (6 x 6, DOF order
  //   u_a, v_a, psi_a, u_b, v_b, psi_b), README section 2, eq. (4), beam_element.hpp. EA and EI
  //   come from section.E, .A and .I. Axial and bending parts do not couple.
  //   Stuck? ./workbook hint M05T1
  unused(section, L);
  throw NotImplemented("M05T1 beam_stiffness");
}

Mat6 beam_mass(const Section& section, double L, MassMatrixType type) {
  // TODO(M05T2): the mass matrix m_e of one beam element in its local axes (6 x 6, the DOF order
  //   of k_e), element mass m = rho A L, README section 2, beam_element.hpp: the consistent matrix
  //   for MassMatrixType::consistent, the diagonal (HRZ) lumped one for MassMatrixType::lumped.
  //   Stuck? ./workbook hint M05T2
  unused(section, L, type);
  throw NotImplemented("M05T2 beam_mass");
}

Mat6 beam_transformation(double alpha) {
  // TODO(M05T3): the transformation T (6 x 6) with u_local = T u_global for an element at angle
  //   alpha to the model's x axis, both nodes in the DOF order (u, v, psi), README section 2,
  //   beam_element.hpp. Stuck? ./workbook hint M05T3
  unused(alpha);
  throw NotImplemented("M05T3 beam_transformation");
}

}  // namespace fmbd
