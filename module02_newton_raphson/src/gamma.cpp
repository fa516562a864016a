// Exercise file of module 2, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory and the hints.
// Module 2, tasks T3 and T4: gamma of every joint and driver type, eq. (2).
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
  // TODO(M02T3): revolute joint, 2 rows: differentiate C = R_i + A_i s_i - R_j - A_j s_j twice;
  //   the terms without q_ddot give
  //   gamma = A_i s_i phi_dot_i^2 - A_j s_j phi_dot_j^2.
  // Hint: q_i(2) is phi_i and qd_i(2) is phi_dot_i.
  unused(q_i, qd_i, s_i, q_j, qd_j, s_j);
  throw NotImplemented("M02T3 revolute_gamma");
}

RowVector translational_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j,
                              const Vec3& qd_j, const Vec2& s_j, const Vec2& axis_i) {
  // TODO(M02T3): translational joint, 2 rows. Row 1 from C_1 = n_i^T d (README, section 2):
  //   gamma_1 = phi_dot_i^2 n_i^T d + 2 phi_dot_i (A_i axis_i)^T d_dot
  //             + n_i^T (A_j s_j phi_dot_j^2 - A_i s_i phi_dot_i^2)
  //   with n_i = A_i I~ axis_i, d = r_Pj - r_Pi, d_dot = its time derivative.
  //   Row 2 (phi_j - phi_i - phi0) is linear in q: gamma_2 = 0.
  unused(q_i, qd_i, s_i, q_j, qd_j, s_j, axis_i);
  throw NotImplemented("M02T3 translational_gamma");
}

RowVector fixed_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j,
                      const Vec3& qd_j, const Vec2& s_j) {
  // TODO(M02T3): fixed joint, 3 rows: the revolute gamma, then 0 for the angle row.
  unused(q_i, qd_i, s_i, q_j, qd_j, s_j);
  throw NotImplemented("M02T3 fixed_gamma");
}

RowVector absolute_angle_gamma(const DriveValue& f) {
  // TODO(M02T4): C = phi_i - f(t) gives C_tt = -f'', so gamma = f''(t) (f.fdd).
  unused(f);
  throw NotImplemented("M02T4 absolute_angle_gamma");
}

RowVector relative_angle_gamma(const DriveValue& f) {
  // TODO(M02T4): C = phi_j - phi_i - f(t): gamma = f''(t).
  unused(f);
  throw NotImplemented("M02T4 relative_angle_gamma");
}

RowVector point_coordinate_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, Axis axis,
                                 const DriveValue& f) {
  // TODO(M02T4): C = e_k^T r_P - f(t) (k = 0 for Axis::x, 1 for Axis::y):
  //   gamma = e_k^T A_i s_i phi_dot_i^2 + f''(t).
  unused(q_i, qd_i, s_i, axis, f);
  throw NotImplemented("M02T4 point_coordinate_gamma");
}

RowVector distance_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j,
                         const Vec3& qd_j, const Vec2& s_j, const DriveValue& f) {
  // TODO(M02T4): C = 1/2 (d^T d - f^2), d = r_Pj - r_Pi. Differentiating twice:
  //   gamma = -d_dot^T d_dot + d^T (A_j s_j phi_dot_j^2 - A_i s_i phi_dot_i^2) + f'^2 + f f''.
  // Hint: the velocity of a point is dr_P/dq_k q_dot_k = point_jacobian(q_k, s) * qd_k.
  unused(q_i, qd_i, s_i, q_j, qd_j, s_j, f);
  throw NotImplemented("M02T4 distance_gamma");
}

}  // namespace fmbd
