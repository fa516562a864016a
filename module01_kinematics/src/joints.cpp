// Exercise file of module 1, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 1, tasks T2-T4: the equations of the revolute, translational and fixed joints.
#include "fmbd/errors.hpp"
#include "fmbd/joints.hpp"

namespace fmbd {

ConstraintBlock revolute_constraint(const Vec3& q_i, const Vec2& s_i, const Vec3& q_j, const Vec2& s_j) {
  // TODO(M01T2): the revolute joint's block (2 rows): C = r_Pi - r_Pj, the condition that the
  //   point s_i of body i and the point s_j of body j coincide, and its Jacobians Cq_i and
  //   Cq_j (README section 2, eq. (1), joints.hpp). Ct stays zero: a joint does not depend on
  //   time. Build on point_position() and point_jacobian() of T1. Stuck? ./workbook hint M01T2
  unused(q_i, s_i, q_j, s_j);
  throw NotImplemented("M01T2 revolute_constraint");
}

ConstraintBlock translational_constraint(const Vec3& q_i, const Vec2& s_i, const Vec3& q_j,
                                         const Vec2& s_j, const Vec2& axis_i, double phi0) {
  // TODO(M01T3): the translational joint's block (2 rows; README section 2, eq. (1), joints.hpp):
  //   C_1 = n_i^T d keeps P_j on the line through P_i along axis_i, with d = r_Pj - r_Pi and
  //   n_i = A_i I~ axis_i the normal of that line, which turns with body i;
  //   C_2 = phi_j - phi_i - phi0 forbids relative rotation. Derive Cq_i and Cq_j of both rows;
  //   Ct stays zero. Stuck? ./workbook hint M01T3
  unused(q_i, s_i, q_j, s_j, axis_i, phi0);
  throw NotImplemented("M01T3 translational_constraint");
}

ConstraintBlock fixed_constraint(const Vec3& q_i, const Vec2& s_i, const Vec3& q_j, const Vec2& s_j,
                                 double phi0) {
  // TODO(M01T4): the fixed joint's block (3 rows; README section 2, eq. (1), joints.hpp):
  //   rows 1-2 are the revolute joint at P_i = P_j, row 3 is C_3 = phi_j - phi_i - phi0; Ct
  //   stays zero. Build on revolute_constraint() of T2. Stuck? ./workbook hint M01T4
  unused(q_i, s_i, q_j, s_j, phi0);
  throw NotImplemented("M01T4 fixed_constraint");
}

}  // namespace fmbd
