#pragma once
// The intuitive flexible body (module 7, tasks T1-T6): kinematics of its nodes, a joint on a
// node, and its (deliberately incomplete) equations of motion.
//
// Notation of flexible_body.hpp: q = (R, theta, q_f) of one body, node k with x_bar_k,
// Phi_t,k (2 x n_f) and Phi_psi,k (1 x n_f); u_bar_k = Phi_t,k q_f; A = A(theta).

#include "fmbd/constraint_block.hpp"
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

/// The reduced matrices of a body in the coordinates (R, theta, q_f) (M07T4).
struct IntuitiveMatrices {
  MatX M_bar;  ///< Phi^T M_FE Phi, (3 + n_f) square: the intuitive form's constant mass matrix
  MatX K_bar;  ///< Phi^T K_FE Phi, (3 + n_f) square: its rigid rows and columns are zero
};

/// M07T4. M_bar = Phi^T M_FE Phi and K_bar = Phi^T K_FE Phi for a basis Phi = [Phi_r Phi_f]
/// (n x (3 + n_f), Phi_f of eq. (5); README section 3). For free-free modes (M-orthogonal, mass-normalised)
/// M_bar = diag(m, m, J, I) and K_bar = diag(0, 0, 0, omega_i^2); any other basis keeps coupling
/// blocks between (R, theta) and q_f in M_bar. Throws std::invalid_argument if the sizes differ.
IntuitiveMatrices intuitive_matrices(const MatX& Phi, const SparseMat& M_FE, const SparseMat& K_FE);

/// A joint's rows on the coordinates of its two bodies (M07T5).
struct NodeJointRows {
  RowVector C;      ///< C (2)
  RowBlock Cq_i;    ///< dC/dq_i (2 x 3), rigid body i
  MatX Cq_j;        ///< dC/dq_j (2 x (3 + n_f)), flexible body j
  RowVector gamma;  ///< gamma (2): C_q_i q_i_ddot + C_q_j q_j_ddot = gamma
};

/// M07T5. A revolute joint between point s_bar_i of rigid body i (q_i, qd_i; the ground as
/// q_i = 0 with s_bar_i global) and node k of flexible body j (q_j, qd_j of size 3 + n_f). Module 1's
/// revolute_constraint and module 2's revolute_gamma see the node as a rigid marker body at the
/// node pose p_k with s_bar = 0; their block B_j on it enters as C_q_j = B_j G_k, and their gamma
/// becomes gamma - B_j c_k (README section 2).
NodeJointRows revolute_on_node(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const NodeModes& node,
                               const VecX& q_j, const VecX& qd_j);

/// M07T6. Body forces of the intuitive form (3 + n_f): gravity g (global axes) on the distributed
/// mass and the elastic force, Q = -(dV/dq)^T with V = -g^T (m R + A S_f q_f) + 1/2 q_f^T K_ff q_f
/// (README section 3).
VecX intuitive_body_forces(const ModalBodyData& data, const VecX& q, const Vec2& g);

}  // namespace fmbd
