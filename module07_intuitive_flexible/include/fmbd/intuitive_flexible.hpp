#pragma once
// The intuitive flexible body (module 7, tasks T1-T4): kinematics of its nodes and its
// (deliberately incomplete) equations of motion.
//
// Notation of flexible_body.hpp: q = (R, theta, q_f) of one body, node k with x_bar_k,
// Phi_t,k (2 x n_f) and Phi_psi,k (1 x n_f); u_bar_k = Phi_t,k q_f; A = A(theta).

#include "fmbd/flexible_body.hpp"

namespace fmbd {

/// M07T1. Pose of node k: (r_k, phi_k) = (R + A (x_bar_k + u_bar_k), theta + Phi_psi,k q_f).
/// q has size 3 + n_f.
Vec3 node_pose(const NodeModes& node, const VecX& q);

/// M07T2. Jacobian G_k = d(r_k, phi_k)/dq (3 x (3 + n_f)): rows (r_x, r_y, phi_k), columns
/// (R_x, R_y, theta, q_f) (README section 2).
MatX node_jacobian(const NodeModes& node, const VecX& q);

/// M07T3. Convective acceleration c_k = G_k_dot q_dot (3), the part of d2/dt2 (r_k, phi_k)
/// without q_ddot: d2/dt2 (r_k, phi_k) = G_k q_ddot + c_k (README section 2).
Vec3 node_convective_acceleration(const NodeModes& node, const VecX& q, const VecX& qd);

/// M07T4. Mass matrix of the intuitive form, constant: M_bar = Phi^T M_FE Phi in the coordinates
/// (R, theta, q_f) (data.basis.M_bar; diag(m, m, J, M_ff) for an M-orthogonal basis).
MatX intuitive_mass_matrix(const ModalBodyData& data);

/// M07T4. Body forces of the intuitive form (3 + n_f): gravity g (global axes) on the distributed
/// mass and the elastic force, Q = -(dV/dq)^T with V = -g^T (m R + A S_f q_f) + 1/2 q_f^T K_ff q_f
/// (README section 3).
VecX intuitive_body_forces(const ModalBodyData& data, const VecX& q, const Vec2& g);

}  // namespace fmbd
