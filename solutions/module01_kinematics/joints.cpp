// Module 1, tasks T2-T4: the equations of the revolute, translational and fixed joints.
#include "fmbd/errors.hpp"
#include "fmbd/joints.hpp"

namespace fmbd {

ConstraintBlock revolute_constraint(const Vec3& q_i, const Vec2& s_i, const Vec3& q_j, const Vec2& s_j) {
  // TASK(M01T2): the revolute joint's block (2 rows): C = r_Pi - r_Pj, the condition that the
  //   point s_i of body i and the point s_j of body j coincide, and its Jacobians Cq_i and
  //   Cq_j (README section 2, eq. (1), joints.hpp). Ct stays zero: a joint does not depend on
  //   time. Build on point_position() and point_jacobian() of T1. Stuck? ./workbook hint M01T2
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
  // TASK(M01T3): the translational joint's block (2 rows; README section 2, eq. (1), joints.hpp):
  //   C_1 = n_i^T d keeps P_j on the line through P_i along axis_i, with d = r_Pj - r_Pi and
  //   n_i = A_i I~ axis_i the normal of that line, which turns with body i;
  //   C_2 = phi_j - phi_i - phi0 forbids relative rotation. Derive Cq_i and Cq_j of both rows;
  //   Ct stays zero. Stuck? ./workbook hint M01T3
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
  // TASK(M01T4): the fixed joint's block (3 rows; README section 2, eq. (1), joints.hpp):
  //   rows 1-2 are the revolute joint at P_i = P_j, row 3 is C_3 = phi_j - phi_i - phi0; Ct
  //   stays zero. Build on revolute_constraint() of T2. Stuck? ./workbook hint M01T4
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
