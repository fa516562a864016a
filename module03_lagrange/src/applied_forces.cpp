// Exercise file of module 3, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory and the hints.
// Module 3, tasks T2 and T3: generalised forces of gravity, point forces and spring-dampers.
#include "fmbd/applied_forces.hpp"
#include "fmbd/errors.hpp"

namespace fmbd {

Vec3 gravity_force(double mass, const Vec2& g) {
  // TODO(M03T2): gravity acts at the centroid, so it has no moment: Q = (m g_x, m g_y, 0).
  unused(mass, g);
  throw NotImplemented("M03T2 gravity_force");
}

Vec3 point_force(const Vec3& q_i, const Vec2& s_i, const Vec2& F, Frame frame) {
  // TODO(M03T2): generalised force of F at the point s_i of body i, by virtual work:
  //   Q_i = (dr_P/dq_i)^T F_global = (F_x, F_y, (A_i I~ s_i)^T F_global),
  //   F_global = F (Frame::global) or A_i F (Frame::body: the force turns with the body).
  // Hint: point_jacobian() of module 1 is dr_P/dq_i.
  unused(q_i, s_i, F, frame);
  throw NotImplemented("M03T2 point_force");
}

PairForces tsda_force(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j, const Vec3& qd_j,
                      const Vec2& s_j, double k, double L0, double c, double f_a) {
  // TODO(M03T3): translational spring-damper-actuator.
  //   d = r_Pj - r_Pi, L = |d|, u = d / L, L_dot = u^T d_dot (d_dot = v_Pj - v_Pi,
  //   v_P = point_jacobian(q, s) * qd), tension f = k (L - L0) + c L_dot + f_a.
  //   The force on P_i is +f u (towards P_j), on P_j it is -f u; turn both into generalised
  //   forces as in point_force().
  // Hint: a stretched spring (L > L0) pulls the points together.
  unused(q_i, qd_i, s_i, q_j, qd_j, s_j, k, L0, c, f_a);
  throw NotImplemented("M03T3 tsda_force");
}

PairForces rsda_force(const Vec3& q_i, const Vec3& qd_i, const Vec3& q_j, const Vec3& qd_j, double k,
                      double theta0, double c, double T_a) {
  // TODO(M03T3): rotational spring-damper-actuator on theta = phi_j - phi_i:
  //   T = k (theta - theta0) + c theta_dot + T_a;  Q_i = (0, 0, +T),  Q_j = (0, 0, -T).
  unused(q_i, qd_i, q_j, qd_j, k, theta0, c, T_a);
  throw NotImplemented("M03T3 rsda_force");
}

}  // namespace fmbd
