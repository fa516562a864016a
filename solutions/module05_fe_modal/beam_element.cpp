// Module 5, tasks T1 to T3: the planar Euler-Bernoulli frame element.
#include <cmath>

#include "fmbd/beam_element.hpp"
#include "fmbd/errors.hpp"

namespace fmbd {

Mat6 beam_stiffness(const Section& section, double L) {
  // TASK(M05T1): start from Mat6::Zero(). Local DOF order (u_a, v_a, psi_a, u_b, v_b, psi_b).
  //   Axial bar on rows/columns 0 and 3: EA/L [[1, -1], [-1, 1]].
  //   Bending on rows/columns 1, 2, 4, 5: EI/L^3 [[12, 6L, -12, 6L], [6L, 4L^2, -6L, 2L^2],
  //                                                [-12, -6L, 12, -6L], [6L, 2L^2, -6L, 4L^2]].
  // Hint: an index array {1, 2, 4, 5} maps the 4x4 bending block into the 6x6 matrix.
  // BEGIN SOLUTION
  const double EA = section.E * section.A, EI = section.E * section.I;
  Eigen::Matrix4d bending;
  bending << 12, 6 * L, -12, 6 * L,
             6 * L, 4 * L * L, -6 * L, 2 * L * L,
             -12, -6 * L, 12, -6 * L,
             6 * L, 2 * L * L, -6 * L, 4 * L * L;
  bending *= EI / (L * L * L);
  const int b[4] = {1, 2, 4, 5};
  Mat6 k = Mat6::Zero();
  k(0, 0) = k(3, 3) = EA / L;
  k(0, 3) = k(3, 0) = -EA / L;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) k(b[r], b[c]) = bending(r, c);
  return k;
  // END SOLUTION
  // STUB: unused(section, L);
  // STUB: throw NotImplemented("M05T1 beam_stiffness");
}

Mat6 beam_mass(const Section& section, double L, MassMatrixType type) {
  // TASK(M05T2): m = rho A L is the element mass.
  //   consistent: axial m/6 [[2, 1], [1, 2]] on DOFs 0 and 3; bending on DOFs 1, 2, 4, 5:
  //     m/420 [[156, 22L, 54, -13L], [22L, 4L^2, 13L, -3L^2], [54, 13L, 156, -22L], [-13L, -3L^2, -22L, 4L^2]].
  //   lumped: diagonal, m/2 on each translation (u and v alike) and m L^2/78 on each rotation.
  // BEGIN SOLUTION
  const double m = section.rho * section.A * L;
  Mat6 me = Mat6::Zero();
  if (type == MassMatrixType::lumped) {
    me.diagonal() << m / 2, m / 2, m * L * L / 78, m / 2, m / 2, m * L * L / 78;
    return me;
  }
  Eigen::Matrix4d bending;
  bending << 156, 22 * L, 54, -13 * L,
             22 * L, 4 * L * L, 13 * L, -3 * L * L,
             54, 13 * L, 156, -22 * L,
             -13 * L, -3 * L * L, -22 * L, 4 * L * L;
  bending *= m / 420;
  const int b[4] = {1, 2, 4, 5};
  me(0, 0) = me(3, 3) = m / 3;
  me(0, 3) = me(3, 0) = m / 6;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) me(b[r], b[c]) = bending(r, c);
  return me;
  // END SOLUTION
  // STUB: unused(section, L, type);
  // STUB: throw NotImplemented("M05T2 beam_mass");
}

Mat6 beam_transformation(double alpha) {
  // TASK(M05T3): u_local = T u_global. Per node R = [[c, s, 0], [-s, c, 0], [0, 0, 1]] with
  //   c = cos(alpha), s = sin(alpha): the local axial displacement is the global one projected on
  //   the element axis (c, s). The rotation psi is the same in both frames.
  // BEGIN SOLUTION
  const double c = std::cos(alpha), s = std::sin(alpha);
  Eigen::Matrix3d R;
  R << c, s, 0, -s, c, 0, 0, 0, 1;
  Mat6 T = Mat6::Zero();
  T.topLeftCorner<3, 3>() = R;
  T.bottomRightCorner<3, 3>() = R;
  return T;
  // END SOLUTION
  // STUB: unused(alpha);
  // STUB: throw NotImplemented("M05T3 beam_transformation");
}

}  // namespace fmbd
