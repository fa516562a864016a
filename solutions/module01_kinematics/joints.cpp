// Module 1, tasks T2-T4: the equations of the revolute, translational and fixed joints.
#include "fmbd/errors.hpp"
#include "fmbd/joints.hpp"

namespace fmbd {

ConstraintBlock revolute_constraint(const Vec3& q_i, const Vec2& s_i, const Vec3& q_j, const Vec2& s_j) {
  // TASK(M01T2): revolute joint, 2 rows, eq. (1):
  //   C    = R_i + A_i s_i - R_j - A_j s_j
  //   Cq_i = + dr_Pi/dq_i = [ I_2 | A_i I~ s_i ]
  //   Cq_j = - dr_Pj/dq_j = [ -I_2 | -A_j I~ s_j ]
  //   Ct   = 0 (a joint does not depend on time).
  // Hints: start from ConstraintBlock::zero(2); point_position() and point_jacobian() of
  //   task T1 do most of the work.
  // BEGIN SOLUTION
  ConstraintBlock b = ConstraintBlock::zero(2);
  b.C = point_position(q_i, s_i) - point_position(q_j, s_j);
  b.Cq_i = point_jacobian(q_i, s_i);
  b.Cq_j = -point_jacobian(q_j, s_j);
  return b;
  // END SOLUTION
  // STUB: unused(q_i, s_i, q_j, s_j);
  // STUB: throw NotImplemented("M01T2 revolute_constraint");
}

ConstraintBlock translational_constraint(const Vec3& q_i, const Vec2& s_i, const Vec3& q_j,
                                         const Vec2& s_j, const Vec2& axis_i, double phi0) {
  // TASK(M01T3): translational joint, 2 rows. With d = r_Pj - r_Pi and the normal of the
  //   sliding line n_i = A_i I~ axis_i (it turns with body i):
  //   C_1 = n_i^T d                    (P_j stays on the line through P_i)
  //   C_2 = phi_j - phi_i - phi0       (no relative rotation)
  // Derivatives of C_1 (product rule; dn_i/dphi_i = A_i I~ I~ axis_i = -A_i axis_i):
  //   dC_1/dR_i = -n_i^T                dC_1/dphi_i = -(A_i axis_i)^T d - n_i^T A_i I~ s_i
  //   dC_1/dR_j = +n_i^T                dC_1/dphi_j = n_i^T A_j I~ s_j
  // Hint: the angle row has -1 in column phi_i and +1 in column phi_j.
  // BEGIN SOLUTION
  ConstraintBlock b = ConstraintBlock::zero(2);
  const Mat2 A_i = rotation(q_i(2));
  const Vec2 n_i = A_i * I_tilde() * axis_i;
  const Vec2 d = point_position(q_j, s_j) - point_position(q_i, s_i);
  b.C(0) = n_i.dot(d);
  b.C(1) = q_j(2) - q_i(2) - phi0;
  b.Cq_i.row(0) << -n_i.transpose(), -(A_i * axis_i).dot(d) - n_i.dot(A_i * I_tilde() * s_i);
  b.Cq_j.row(0) << n_i.transpose(), n_i.dot(rotation_derivative(q_j(2)) * s_j);
  b.Cq_i(1, 2) = -1.0;
  b.Cq_j(1, 2) = 1.0;
  return b;
  // END SOLUTION
  // STUB: unused(q_i, s_i, q_j, s_j, axis_i, phi0);
  // STUB: throw NotImplemented("M01T3 translational_constraint");
}

ConstraintBlock fixed_constraint(const Vec3& q_i, const Vec2& s_i, const Vec3& q_j, const Vec2& s_j,
                                 double phi0) {
  // TASK(M01T4): fixed joint, 3 rows: the two rows of the revolute joint at P_i = P_j,
  //   then C_3 = phi_j - phi_i - phi0 (like the angle row of the translational joint).
  // Hint: reuse revolute_constraint() for the first two rows (.topRows(2)).
  // BEGIN SOLUTION
  ConstraintBlock b = ConstraintBlock::zero(3);
  const ConstraintBlock point = revolute_constraint(q_i, s_i, q_j, s_j);
  b.C.head(2) = point.C;
  b.Cq_i.topRows(2) = point.Cq_i;
  b.Cq_j.topRows(2) = point.Cq_j;
  b.C(2) = q_j(2) - q_i(2) - phi0;
  b.Cq_i(2, 2) = -1.0;
  b.Cq_j(2, 2) = 1.0;
  return b;
  // END SOLUTION
  // STUB: unused(q_i, s_i, q_j, s_j, phi0);
  // STUB: throw NotImplemented("M01T4 fixed_constraint");
}

}  // namespace fmbd
