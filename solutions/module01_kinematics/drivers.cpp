// Module 1, task T5: driver equations C = (measured quantity) - f(t), with C_t.
#include "fmbd/drivers.hpp"
#include "fmbd/errors.hpp"

namespace fmbd {

ConstraintBlock absolute_angle_constraint(const Vec3& q_i, const DriveValue& f) {
  // TASK(M01T5): the absolute-angle driver's block (1 row): C = phi_i - f(t), its Jacobian
  //   Cq_i and Ct = dC/dt (README section 2, eq. (1), drivers.hpp). f.f, f.fd and f.fdd hold
  //   f(t), f'(t) and f''(t). Stuck? ./workbook hint M01T5
  // BEGIN SOLUTION
  ConstraintBlock b = ConstraintBlock::zero(1);
  b.C(0) = q_i(2) - f.f;
  b.Cq_i(0, 2) = 1.0;
  b.Ct(0) = -f.fd;
  return b;
  // END SOLUTION
  // STUB: unused(q_i, f);
  // STUB: throw NotImplemented("M01T5 absolute_angle_constraint");
}

ConstraintBlock relative_angle_constraint(const Vec3& q_i, const Vec3& q_j, const DriveValue& f) {
  // TASK(M01T5): the relative-angle driver's block (1 row): C = phi_j - phi_i - f(t), with
  //   Cq_i, Cq_j and Ct (README section 2, eq. (1), drivers.hpp).
  // BEGIN SOLUTION
  ConstraintBlock b = ConstraintBlock::zero(1);
  b.C(0) = q_j(2) - q_i(2) - f.f;
  b.Cq_i(0, 2) = -1.0;
  b.Cq_j(0, 2) = 1.0;
  b.Ct(0) = -f.fd;
  return b;
  // END SOLUTION
  // STUB: unused(q_i, q_j, f);
  // STUB: throw NotImplemented("M01T5 relative_angle_constraint");
}

ConstraintBlock point_coordinate_constraint(const Vec3& q_i, const Vec2& s_i, Axis axis,
                                            const DriveValue& f) {
  // TASK(M01T5): the point-coordinate driver's block (1 row): C = e_k^T r_P - f(t), coordinate
  //   k of the point s_i of body i, with k = 0 for Axis::x and 1 for Axis::y; Cq_i and Ct
  //   (README section 2, eq. (1), drivers.hpp). Build on point_position() and point_jacobian().
  // BEGIN SOLUTION
  const int k = static_cast<int>(axis);
  ConstraintBlock b = ConstraintBlock::zero(1);
  b.C(0) = point_position(q_i, s_i)(k) - f.f;
  b.Cq_i.row(0) = point_jacobian(q_i, s_i).row(k);
  b.Ct(0) = -f.fd;
  return b;
  // END SOLUTION
  // STUB: unused(q_i, s_i, axis, f);
  // STUB: throw NotImplemented("M01T5 point_coordinate_constraint");
}

ConstraintBlock distance_constraint(const Vec3& q_i, const Vec2& s_i, const Vec3& q_j, const Vec2& s_j,
                                    const DriveValue& f) {
  // TASK(M01T5): the distance driver's block (1 row): C = 1/2 (d^T d - f(t)^2) with
  //   d = r_Pj - r_Pi, with Cq_i, Cq_j and Ct (README section 2, eq. (1), drivers.hpp).
  //   Build on point_position() and point_jacobian().
  // BEGIN SOLUTION
  ConstraintBlock b = ConstraintBlock::zero(1);
  const Vec2 d = point_position(q_j, s_j) - point_position(q_i, s_i);
  b.C(0) = 0.5 * (d.squaredNorm() - f.f * f.f);
  b.Cq_i.row(0) = -d.transpose() * point_jacobian(q_i, s_i);
  b.Cq_j.row(0) = d.transpose() * point_jacobian(q_j, s_j);
  b.Ct(0) = -f.f * f.fd;
  return b;
  // END SOLUTION
  // STUB: unused(q_i, s_i, q_j, s_j, f);
  // STUB: throw NotImplemented("M01T5 distance_constraint");
}

}  // namespace fmbd
