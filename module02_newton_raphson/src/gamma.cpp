// Exercise file of module 2, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
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
  // TODO(M02T3): gamma (2 rows) of the revolute joint, C = r_Pi - r_Pj (README section 2,
  //   eq. (2), gamma.hpp): the terms of d2C/dt2 that do not multiply q_ddot, with the opposite
  //   sign. q_i(2) is phi_i and qd_i(2) is phi_dot_i; the helpers centripetal() and
  //   point_velocity() above may serve. Stuck? ./workbook hint M02T3
  unused(q_i, qd_i, s_i, q_j, qd_j, s_j);
  throw NotImplemented("M02T3 revolute_gamma");
}

RowVector translational_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j,
                              const Vec3& qd_j, const Vec2& s_j, const Vec2& axis_i) {
  // TODO(M02T3): gamma (2 rows) of the translational joint, C_1 = n_i^T d and
  //   C_2 = phi_j - phi_i - phi0, with n_i = A_i I~ axis_i and d = r_Pj - r_Pi (README section 2,
  //   eq. (2), gamma.hpp).
  unused(q_i, qd_i, s_i, q_j, qd_j, s_j, axis_i);
  throw NotImplemented("M02T3 translational_gamma");
}

RowVector fixed_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j,
                      const Vec3& qd_j, const Vec2& s_j) {
  // TODO(M02T3): gamma (3 rows) of the fixed joint: rows 1-2 as the revolute joint, row 3 of
  //   C_3 = phi_j - phi_i - phi0 (README section 2, eq. (2)). Build on revolute_gamma().
  unused(q_i, qd_i, s_i, q_j, qd_j, s_j);
  throw NotImplemented("M02T3 fixed_gamma");
}

RowVector absolute_angle_gamma(const DriveValue& f) {
  // TODO(M02T4): gamma (1 row) of the absolute-angle driver C = phi_i - f(t) (README section 2,
  //   eq. (2), gamma.hpp); f.f, f.fd and f.fdd hold f(t), f'(t) and f''(t).
  //   Stuck? ./workbook hint M02T4
  unused(f);
  throw NotImplemented("M02T4 absolute_angle_gamma");
}

RowVector relative_angle_gamma(const DriveValue& f) {
  // TODO(M02T4): gamma (1 row) of the relative-angle driver C = phi_j - phi_i - f(t) (README
  //   section 2, eq. (2), gamma.hpp).
  unused(f);
  throw NotImplemented("M02T4 relative_angle_gamma");
}

RowVector point_coordinate_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, Axis axis,
                                 const DriveValue& f) {
  // TODO(M02T4): gamma (1 row) of the point-coordinate driver C = e_k^T r_P - f(t), with k = 0
  //   for Axis::x and 1 for Axis::y (README section 2, eq. (2), gamma.hpp).
  unused(q_i, qd_i, s_i, axis, f);
  throw NotImplemented("M02T4 point_coordinate_gamma");
}

RowVector distance_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j,
                         const Vec3& qd_j, const Vec2& s_j, const DriveValue& f) {
  // TODO(M02T4): gamma (1 row) of the distance driver C = 1/2 (d^T d - f(t)^2), d = r_Pj - r_Pi
  //   (README section 2, eq. (2), gamma.hpp). point_velocity() above gives a point's velocity.
  unused(q_i, qd_i, s_i, q_j, qd_j, s_j, f);
  throw NotImplemented("M02T4 distance_gamma");
}

void constraint_gamma(const Model& model, const VecX& q, const VecX& qd, double t, VecX& gamma) {
  check_gamma_storage(model, q, qd, gamma);
  // TODO(M02T5): gamma of the whole model into `gamma` (m), README section 2: for each constraint
  //   c of model.constraints(), its markers at (q, q_dot) (constraint_markers()), then its gamma:
  //   kernel_gamma(c, markers, t) (your T3 and T4 for its type) plus node_gamma_terms(c, markers,
  //   t) (zero on rigid bodies; module 7 explains it), at c's rows c.first_row ..
  //   c.first_row + c.rows - 1. Stuck? ./workbook hint M02T5
  unused(model, q, qd, t, gamma);
  throw NotImplemented("M02T5 constraint_gamma");
}

}  // namespace fmbd
