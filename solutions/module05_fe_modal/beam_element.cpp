// Module 5, tasks T1 to T3: the planar Euler-Bernoulli frame element.
#include <cmath>

#include "fmbd/beam_element.hpp"
#include "fmbd/errors.hpp"

namespace fmbd {

Mat6 beam_stiffness(const Section& section, double L) {
  // TASK(M05T1): the stiffness matrix k_e of one beam element in its local axes (6 x 6, DOF order
  //   u_a, v_a, psi_a, u_b, v_b, psi_b), README section 2, eq. (4), beam_element.hpp. EA and EI
  //   come from section.E, .A and .I. Axial and bending parts do not couple.
  //   Stuck? ./workbook hint M05T1
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
  // TASK(M05T2): the mass matrix m_e of one beam element in its local axes (6 x 6, the DOF order
  //   of k_e), element mass m = rho A L, README section 2, beam_element.hpp: the consistent matrix
  //   for MassMatrixType::consistent, the diagonal (HRZ) lumped one for MassMatrixType::lumped.
  //   Stuck? ./workbook hint M05T2
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
  // TASK(M05T3): the transformation T (6 x 6) with u_local = T u_global for an element at angle
  //   alpha to the model's x axis, both nodes in the DOF order (u, v, psi), README section 2,
  //   beam_element.hpp. Stuck? ./workbook hint M05T3
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
