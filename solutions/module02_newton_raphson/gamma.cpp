// Module 2, tasks T3 and T4: gamma of every joint and driver type, eq. (2); task T5: gamma of
// the whole model, assembled from them.
#include "fmbd/constraints.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/gamma.hpp"
#include "fmbd/planar.hpp"

namespace fmbd {

namespace {

// Helpers you may use. A_k s phi_dot_k^2: the centripetal part of d2/dt2 (A_k s), with opposite sign.
[[maybe_unused]] Vec2 centripetal(const Vec3& q_k, const Vec3& qd_k, const Vec2& s) {
  return rotation(q_k(2)) * s * qd_k(2) * qd_k(2);
}

// Velocity of a body-fixed point: R_dot + A I~ s phi_dot.
[[maybe_unused]] Vec2 point_velocity(const Vec3& q_k, const Vec3& qd_k, const Vec2& s) {
  return point_jacobian(q_k, s) * qd_k;
}

}  // namespace

RowVector revolute_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j,
                         const Vec3& qd_j, const Vec2& s_j) {
  // TASK(M02T3): gamma (2 rows) of the revolute joint, C = r_Pi - r_Pj (README section 2,
  //   eq. (2), gamma.hpp): the terms of d2C/dt2 that do not multiply q_ddot, with the opposite
  //   sign. q_i(2) is phi_i and qd_i(2) is phi_dot_i; the helpers centripetal() and
  //   point_velocity() above may serve. Stuck? ./workbook hint M02T3
  // BEGIN SOLUTION
  return centripetal(q_i, qd_i, s_i) - centripetal(q_j, qd_j, s_j);
  // END SOLUTION
  // STUB: unused(q_i, qd_i, s_i, q_j, qd_j, s_j);
  // STUB: throw NotImplemented("M02T3 revolute_gamma");
}

RowVector translational_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j,
                              const Vec3& qd_j, const Vec2& s_j, const Vec2& axis_i) {
  // TASK(M02T3): gamma (2 rows) of the translational joint, C_1 = n_i^T d and
  //   C_2 = phi_j - phi_i - phi0, with n_i = A_i I~ axis_i and d = r_Pj - r_Pi (README section 2,
  //   eq. (2), gamma.hpp).
  // BEGIN SOLUTION
  const Mat2 A_i = rotation(q_i(2));
  const Vec2 n_i = A_i * I_tilde() * axis_i;
  const Vec2 d = point_position(q_j, s_j) - point_position(q_i, s_i);
  const Vec2 d_dot = point_velocity(q_j, qd_j, s_j) - point_velocity(q_i, qd_i, s_i);
  const double w_i = qd_i(2);
  RowVector gamma = RowVector::Zero(2);
  gamma(0) = w_i * w_i * n_i.dot(d) + 2 * w_i * (A_i * axis_i).dot(d_dot) +
             n_i.dot(centripetal(q_j, qd_j, s_j) - centripetal(q_i, qd_i, s_i));
  return gamma;
  // END SOLUTION
  // STUB: unused(q_i, qd_i, s_i, q_j, qd_j, s_j, axis_i);
  // STUB: throw NotImplemented("M02T3 translational_gamma");
}

RowVector fixed_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j,
                      const Vec3& qd_j, const Vec2& s_j) {
  // TASK(M02T3): gamma (3 rows) of the fixed joint: rows 1-2 as the revolute joint, row 3 of
  //   C_3 = phi_j - phi_i - phi0 (README section 2, eq. (2)). Build on revolute_gamma().
  // BEGIN SOLUTION
  RowVector gamma = RowVector::Zero(3);
  gamma.head(2) = revolute_gamma(q_i, qd_i, s_i, q_j, qd_j, s_j);
  return gamma;
  // END SOLUTION
  // STUB: unused(q_i, qd_i, s_i, q_j, qd_j, s_j);
  // STUB: throw NotImplemented("M02T3 fixed_gamma");
}

RowVector absolute_angle_gamma(const DriveValue& f) {
  // TASK(M02T4): gamma (1 row) of the absolute-angle driver C = phi_i - f(t) (README section 2,
  //   eq. (2), gamma.hpp); f.f, f.fd and f.fdd hold f(t), f'(t) and f''(t).
  //   Stuck? ./workbook hint M02T4
  // BEGIN SOLUTION
  return RowVector::Constant(1, f.fdd);
  // END SOLUTION
  // STUB: unused(f);
  // STUB: throw NotImplemented("M02T4 absolute_angle_gamma");
}

RowVector relative_angle_gamma(const DriveValue& f) {
  // TASK(M02T4): gamma (1 row) of the relative-angle driver C = phi_j - phi_i - f(t) (README
  //   section 2, eq. (2), gamma.hpp).
  // BEGIN SOLUTION
  return RowVector::Constant(1, f.fdd);
  // END SOLUTION
  // STUB: unused(f);
  // STUB: throw NotImplemented("M02T4 relative_angle_gamma");
}

RowVector point_coordinate_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, Axis axis,
                                 const DriveValue& f) {
  // TASK(M02T4): gamma (1 row) of the point-coordinate driver C = e_k^T r_P - f(t), with k = 0
  //   for Axis::x and 1 for Axis::y (README section 2, eq. (2), gamma.hpp).
  // BEGIN SOLUTION
  return RowVector::Constant(1, centripetal(q_i, qd_i, s_i)(static_cast<int>(axis)) + f.fdd);
  // END SOLUTION
  // STUB: unused(q_i, qd_i, s_i, axis, f);
  // STUB: throw NotImplemented("M02T4 point_coordinate_gamma");
}

RowVector distance_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j,
                         const Vec3& qd_j, const Vec2& s_j, const DriveValue& f) {
  // TASK(M02T4): gamma (1 row) of the distance driver C = 1/2 (d^T d - f(t)^2), d = r_Pj - r_Pi
  //   (README section 2, eq. (2), gamma.hpp). point_velocity() above gives a point's velocity.
  // BEGIN SOLUTION
  const Vec2 d = point_position(q_j, s_j) - point_position(q_i, s_i);
  const Vec2 d_dot = point_velocity(q_j, qd_j, s_j) - point_velocity(q_i, qd_i, s_i);
  return RowVector::Constant(1, -d_dot.squaredNorm() +
                                    d.dot(centripetal(q_j, qd_j, s_j) - centripetal(q_i, qd_i, s_i)) +
                                    f.fd * f.fd + f.f * f.fdd);
  // END SOLUTION
  // STUB: unused(q_i, qd_i, s_i, q_j, qd_j, s_j, f);
  // STUB: throw NotImplemented("M02T4 distance_gamma");
}

void constraint_gamma(const Model& model, const VecX& q, const VecX& qd, double t, VecX& gamma) {
  check_gamma_storage(model, q, qd, gamma);
  // TASK(M02T5): gamma of the whole model into `gamma` (m), README section 2: for each constraint
  //   c of model.constraints(), its markers at (q, q_dot) (constraint_markers()), then its gamma:
  //   kernel_gamma(c, markers, t) (your T3 and T4 for its type) plus node_gamma_terms(c, markers,
  //   t) (zero on rigid bodies; module 7 explains it), at c's rows c.first_row ..
  //   c.first_row + c.rows - 1. Stuck? ./workbook hint M02T5
  // BEGIN SOLUTION
  for (const Constraint& c : model.constraints()) {
    const ConstraintMarkers markers = constraint_markers(model, c, q, qd);
    gamma.segment(c.first_row, c.rows) = kernel_gamma(c, markers, t) + node_gamma_terms(c, markers, t);
  }
  // END SOLUTION
  // STUB: unused(model, q, qd, t, gamma);
  // STUB: throw NotImplemented("M02T5 constraint_gamma");
}

}  // namespace fmbd
