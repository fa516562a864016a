#pragma once
// Generalised applied forces Q_a (module 3, tasks T2-T3).
//
// A force F acting at point P of body i does the virtual work dW = F^T dr_P = F^T (dr_P/dq_i) dq_i,
// so its generalised force is Q_i = (dr_P/dq_i)^T F = (F_x, F_y, (A_i I~ s_i)^T F): the force
// itself, and its moment about the centroid. A torque T adds (0, 0, T).

#include "fmbd/marker.hpp"
#include "fmbd/model.hpp"

namespace fmbd {

/// Generalised forces of one element on its two bodies (each (Q_x, Q_y, Q_phi)).
struct PairForces {
  Vec3 Q_i = Vec3::Zero();
  Vec3 Q_j = Vec3::Zero();
};

/// M03T2. Gravity on a body of mass m: (m g_x, m g_y, 0).
Vec3 gravity_force(double mass, const Vec2& g);

/// M03T2. A force F at the point s_i of body i, with F in the global frame (frame == global)
/// or in the body frame of body i (frame == body, then F_global = A_i F).
Vec3 point_force(const Vec3& q_i, const Vec2& s_i, const Vec2& F, Frame frame);

/// M03T3. Translational spring-damper-actuator between P_i (body i) and P_j (body j):
/// d = r_Pj - r_Pi, L = |d| > 0, u = d / L, L_dot = u^T d_dot,
/// tension f = k (L - L0) + c L_dot + f_a; the force on P_i is +f u, on P_j it is -f u.
PairForces tsda_force(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j, const Vec3& qd_j,
                      const Vec2& s_j, double k, double L0, double c, double f_a);

/// M03T3. Rotational spring-damper-actuator: theta = phi_j - phi_i,
/// T = k (theta - theta0) + c theta_dot + T_a; Q_i = (0, 0, +T), Q_j = (0, 0, -T).
PairForces rsda_force(const Vec3& q_i, const Vec3& qd_i, const Vec3& q_j, const Vec3& qd_j, double k,
                      double theta0, double c, double T_a);

/// The kernel forces of one force element at (q, q_dot, t) on its two markers (given code): your
/// point_force, tsda_force or rsda_force for its type, or its torque (0, 0, T). A one-body
/// element's second marker is the ground, with no force. Throws std::domain_error naming a
/// spring-damper whose points coincide.
struct ElementForces {
  Marker i, j;
  Vec3 Q_i = Vec3::Zero();
  Vec3 Q_j = Vec3::Zero();
};
ElementForces element_forces(const Model& model, const Force& force, const VecX& q, const VecX& qd, double t);

/// M03T3. Q(rows of marker's body) += Q_kernel: the 3 rows of a rigid body from marker.offset,
/// none for the ground. A marker on a node of a flexible body (marker.on_node()) chains the force
/// with the node's G over the body's 3 + n_f rows (module 7).
void add_generalised_force(VecX& Q, const Marker& marker, const Vec3& Q_kernel);

/// M03T3. Q_a of the whole model at (q, q_dot, t), written into `Q_a`, which the caller provides
/// with n entries holding anything (every entry is overwritten): gravity on every rigid body, a
/// flexible body's own forces through its DeformableBody::add_forces (module 7 on), and every
/// force element's forces on its markers. Throws std::invalid_argument if q, q_dot or Q_a has the
/// wrong size, std::domain_error from element_forces.
void applied_forces(const Model& model, const VecX& q, const VecX& qd, double t, VecX& Q_a);
/// The precondition of applied_forces(model, q, qd, t, Q_a), which checks it first.
void check_force_storage(const Model& model, const VecX& q, const VecX& qd, const VecX& Q_a);
/// Q_a in new storage.
VecX applied_forces(const Model& model, const VecX& q, const VecX& qd, double t);

}  // namespace fmbd
