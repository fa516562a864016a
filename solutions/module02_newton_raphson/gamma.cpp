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
  // TASK(M02T3): revolute joint, 2 rows: differentiate C = R_i + A_i s_i - R_j - A_j s_j twice;
  //   the terms without q_ddot give
  //   gamma = A_i s_i phi_dot_i^2 - A_j s_j phi_dot_j^2.
  // Hint: q_i(2) is phi_i and qd_i(2) is phi_dot_i.
  // BEGIN SOLUTION
  return centripetal(q_i, qd_i, s_i) - centripetal(q_j, qd_j, s_j);
  // END SOLUTION
  // STUB: unused(q_i, qd_i, s_i, q_j, qd_j, s_j);
  // STUB: throw NotImplemented("M02T3 revolute_gamma");
}

RowVector translational_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j,
                              const Vec3& qd_j, const Vec2& s_j, const Vec2& axis_i) {
  // TASK(M02T3): translational joint, 2 rows. Row 1 from C_1 = n_i^T d (README, section 2):
  //   gamma_1 = phi_dot_i^2 n_i^T d + 2 phi_dot_i (A_i axis_i)^T d_dot
  //             + n_i^T (A_j s_j phi_dot_j^2 - A_i s_i phi_dot_i^2)
  //   with n_i = A_i I~ axis_i, d = r_Pj - r_Pi, d_dot = its time derivative.
  //   Row 2 (phi_j - phi_i - phi0) is linear in q: gamma_2 = 0.
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
  // TASK(M02T3): fixed joint, 3 rows: the revolute gamma, then 0 for the angle row.
  // BEGIN SOLUTION
  RowVector gamma = RowVector::Zero(3);
  gamma.head(2) = revolute_gamma(q_i, qd_i, s_i, q_j, qd_j, s_j);
  return gamma;
  // END SOLUTION
  // STUB: unused(q_i, qd_i, s_i, q_j, qd_j, s_j);
  // STUB: throw NotImplemented("M02T3 fixed_gamma");
}

RowVector absolute_angle_gamma(const DriveValue& f) {
  // TASK(M02T4): C = phi_i - f(t) gives C_tt = -f'', so gamma = f''(t) (f.fdd).
  // BEGIN SOLUTION
  return RowVector::Constant(1, f.fdd);
  // END SOLUTION
  // STUB: unused(f);
  // STUB: throw NotImplemented("M02T4 absolute_angle_gamma");
}

RowVector relative_angle_gamma(const DriveValue& f) {
  // TASK(M02T4): C = phi_j - phi_i - f(t): gamma = f''(t).
  // BEGIN SOLUTION
  return RowVector::Constant(1, f.fdd);
  // END SOLUTION
  // STUB: unused(f);
  // STUB: throw NotImplemented("M02T4 relative_angle_gamma");
}

RowVector point_coordinate_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, Axis axis,
                                 const DriveValue& f) {
  // TASK(M02T4): C = e_k^T r_P - f(t) (k = 0 for Axis::x, 1 for Axis::y):
  //   gamma = e_k^T A_i s_i phi_dot_i^2 + f''(t).
  // BEGIN SOLUTION
  return RowVector::Constant(1, centripetal(q_i, qd_i, s_i)(static_cast<int>(axis)) + f.fdd);
  // END SOLUTION
  // STUB: unused(q_i, qd_i, s_i, axis, f);
  // STUB: throw NotImplemented("M02T4 point_coordinate_gamma");
}

RowVector distance_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j,
                         const Vec3& qd_j, const Vec2& s_j, const DriveValue& f) {
  // TASK(M02T4): C = 1/2 (d^T d - f^2), d = r_Pj - r_Pi. Differentiating twice:
  //   gamma = -d_dot^T d_dot + d^T (A_j s_j phi_dot_j^2 - A_i s_i phi_dot_i^2) + f'^2 + f f''.
  // Hint: the velocity of a point is dr_P/dq_k q_dot_k = point_jacobian(q_k, s) * qd_k.
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

}  // namespace fmbd
