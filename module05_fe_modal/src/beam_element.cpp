// Exercise file of module 5, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory and the hints.
// Module 5, tasks T1 to T3: the planar Euler-Bernoulli frame element.
#include <cmath>

#include "fmbd/beam_element.hpp"
#include "fmbd/errors.hpp"

namespace fmbd {

Mat6 beam_stiffness(const Section& section, double L) {
  // TODO(M05T1): start from Mat6::Zero(). Local DOF order (u_a, v_a, psi_a, u_b, v_b, psi_b).
  //   Axial bar on rows/columns 0 and 3: EA/L [[1, -1], [-1, 1]].
  //   Bending on rows/columns 1, 2, 4, 5: EI/L^3 [[12, 6L, -12, 6L], [6L, 4L^2, -6L, 2L^2],
  //                                                [-12, -6L, 12, -6L], [6L, 2L^2, -6L, 4L^2]].
  // Hint: an index array {1, 2, 4, 5} maps the 4x4 bending block into the 6x6 matrix.
  unused(section, L);
  throw NotImplemented("M05T1 beam_stiffness");
}

Mat6 beam_mass(const Section& section, double L, MassMatrixType type) {
  // TODO(M05T2): m = rho A L is the element mass.
  //   consistent: axial m/6 [[2, 1], [1, 2]] on DOFs 0 and 3; bending on DOFs 1, 2, 4, 5:
  //     m/420 [[156, 22L, 54, -13L], [22L, 4L^2, 13L, -3L^2], [54, 13L, 156, -22L], [-13L, -3L^2, -22L, 4L^2]].
  //   lumped: diagonal, m/2 on each translation (u and v alike) and m L^2/78 on each rotation.
  unused(section, L, type);
  throw NotImplemented("M05T2 beam_mass");
}

Mat6 beam_transformation(double alpha) {
  // TODO(M05T3): u_local = T u_global. Per node R = [[c, s, 0], [-s, c, 0], [0, 0, 1]] with
  //   c = cos(alpha), s = sin(alpha): the local axial displacement is the global one projected on
  //   the element axis (c, s). The rotation psi is the same in both frames.
  unused(alpha);
  throw NotImplemented("M05T3 beam_transformation");
}

}  // namespace fmbd
