// Exercise file of module 1, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory and the hints.
// Module 1, tasks T2-T4: the equations of the revolute, translational and fixed joints.
#include "fmbd/errors.hpp"
#include "fmbd/joints.hpp"

namespace fmbd {

ConstraintBlock revolute_constraint(const Vec3& q_i, const Vec2& s_i, const Vec3& q_j, const Vec2& s_j) {
  // TODO(M01T2): revolute joint, 2 rows, eq. (1):
  //   C    = R_i + A_i s_i - R_j - A_j s_j
  //   Cq_i = + dr_Pi/dq_i = [ I_2 | A_i I~ s_i ]
  //   Cq_j = - dr_Pj/dq_j = [ -I_2 | -A_j I~ s_j ]
  //   Ct   = 0 (a joint does not depend on time).
  // Hints: start from ConstraintBlock::zero(2); point_position() and point_jacobian() of
  //   task T1 do most of the work.
  unused(q_i, s_i, q_j, s_j);
  throw NotImplemented("M01T2 revolute_constraint");
}

ConstraintBlock translational_constraint(const Vec3& q_i, const Vec2& s_i, const Vec3& q_j,
                                         const Vec2& s_j, const Vec2& axis_i, double phi0) {
  // TODO(M01T3): translational joint, 2 rows. With d = r_Pj - r_Pi and the normal of the
  //   sliding line n_i = A_i I~ axis_i (it turns with body i):
  //   C_1 = n_i^T d                    (P_j stays on the line through P_i)
  //   C_2 = phi_j - phi_i - phi0       (no relative rotation)
  // Derivatives of C_1 (product rule; dn_i/dphi_i = A_i I~ I~ axis_i = -A_i axis_i):
  //   dC_1/dR_i = -n_i^T                dC_1/dphi_i = -(A_i axis_i)^T d - n_i^T A_i I~ s_i
  //   dC_1/dR_j = +n_i^T                dC_1/dphi_j = n_i^T A_j I~ s_j
  // Hint: the angle row has -1 in column phi_i and +1 in column phi_j.
  unused(q_i, s_i, q_j, s_j, axis_i, phi0);
  throw NotImplemented("M01T3 translational_constraint");
}

ConstraintBlock fixed_constraint(const Vec3& q_i, const Vec2& s_i, const Vec3& q_j, const Vec2& s_j,
                                 double phi0) {
  // TODO(M01T4): fixed joint, 3 rows: the two rows of the revolute joint at P_i = P_j,
  //   then C_3 = phi_j - phi_i - phi0 (like the angle row of the translational joint).
  // Hint: reuse revolute_constraint() for the first two rows (.topRows(2)).
  unused(q_i, s_i, q_j, s_j, phi0);
  throw NotImplemented("M01T4 fixed_constraint");
}

}  // namespace fmbd
