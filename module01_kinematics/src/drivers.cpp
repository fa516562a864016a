// Exercise file of module 1, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory and the hints.
// Module 1, task T5: driver equations C = (measured quantity) - f(t), with C_t.
#include "fmbd/drivers.hpp"
#include "fmbd/errors.hpp"

namespace fmbd {

ConstraintBlock absolute_angle_constraint(const Vec3& q_i, const DriveValue& f) {
  // TODO(M01T5): absolute-angle driver, 1 row:
  //   C = phi_i - f(t),   Cq_i = [0, 0, 1],   Ct = -f'(t)   (f.f, f.fd, f.fdd hold f, f', f'').
  unused(q_i, f);
  throw NotImplemented("M01T5 absolute_angle_constraint");
}

ConstraintBlock relative_angle_constraint(const Vec3& q_i, const Vec3& q_j, const DriveValue& f) {
  // TODO(M01T5): relative-angle driver, 1 row:
  //   C = phi_j - phi_i - f(t),   Cq_i = [0, 0, -1],   Cq_j = [0, 0, 1],   Ct = -f'(t).
  unused(q_i, q_j, f);
  throw NotImplemented("M01T5 relative_angle_constraint");
}

ConstraintBlock point_coordinate_constraint(const Vec3& q_i, const Vec2& s_i, Axis axis,
                                            const DriveValue& f) {
  // TODO(M01T5): point-coordinate driver, 1 row, with k = 0 for Axis::x and 1 for Axis::y:
  //   C = r_P(k) - f(t),   Cq_i = row k of dr_P/dq_i,   Ct = -f'(t).
  unused(q_i, s_i, axis, f);
  throw NotImplemented("M01T5 point_coordinate_constraint");
}

ConstraintBlock distance_constraint(const Vec3& q_i, const Vec2& s_i, const Vec3& q_j, const Vec2& s_j,
                                    const DriveValue& f) {
  // TODO(M01T5): distance driver, 1 row, with d = r_Pj - r_Pi:
  //   C = 1/2 (d^T d - f^2),   Cq_i = -d^T dr_Pi/dq_i,   Cq_j = d^T dr_Pj/dq_j,
  //   Ct = -f f'   (chain rule on -f(t)^2 / 2).
  unused(q_i, s_i, q_j, s_j, f);
  throw NotImplemented("M01T5 distance_constraint");
}

}  // namespace fmbd
