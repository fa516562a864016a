// Exercise file of module 1, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 1, task T5: driver equations C = (measured quantity) - f(t), with C_t.
#include "fmbd/drivers.hpp"
#include "fmbd/errors.hpp"

namespace fmbd {

ConstraintBlock absolute_angle_constraint(const Vec3& q_i, const DriveValue& f) {
  // TODO(M01T5): the absolute-angle driver's block (1 row): C = phi_i - f(t), its Jacobian
  //   Cq_i and Ct = dC/dt (README section 2, eq. (1), drivers.hpp). f.f, f.fd and f.fdd hold
  //   f(t), f'(t) and f''(t). Stuck? ./workbook hint M01T5
  unused(q_i, f);
  throw NotImplemented("M01T5 absolute_angle_constraint");
}

ConstraintBlock relative_angle_constraint(const Vec3& q_i, const Vec3& q_j, const DriveValue& f) {
  // TODO(M01T5): the relative-angle driver's block (1 row): C = phi_j - phi_i - f(t), with
  //   Cq_i, Cq_j and Ct (README section 2, eq. (1), drivers.hpp).
  unused(q_i, q_j, f);
  throw NotImplemented("M01T5 relative_angle_constraint");
}

ConstraintBlock point_coordinate_constraint(const Vec3& q_i, const Vec2& s_i, Axis axis,
                                            const DriveValue& f) {
  // TODO(M01T5): the point-coordinate driver's block (1 row): C = e_k^T r_P - f(t), coordinate
  //   k of the point s_i of body i, with k = 0 for Axis::x and 1 for Axis::y; Cq_i and Ct
  //   (README section 2, eq. (1), drivers.hpp). Build on point_position() and point_jacobian().
  unused(q_i, s_i, axis, f);
  throw NotImplemented("M01T5 point_coordinate_constraint");
}

ConstraintBlock distance_constraint(const Vec3& q_i, const Vec2& s_i, const Vec3& q_j, const Vec2& s_j,
                                    const DriveValue& f) {
  // TODO(M01T5): the distance driver's block (1 row): C = 1/2 (d^T d - f(t)^2) with
  //   d = r_Pj - r_Pi, with Cq_i, Cq_j and Ct (README section 2, eq. (1), drivers.hpp).
  //   Build on point_position() and point_jacobian().
  unused(q_i, s_i, q_j, s_j, f);
  throw NotImplemented("M01T5 distance_constraint");
}

}  // namespace fmbd
