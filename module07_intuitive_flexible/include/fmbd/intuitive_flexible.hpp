#pragma once
// The intuitive flexible body (module 7, tasks T1-T6): kinematics of its nodes, which its joints,
// drivers and forces grip, and its (deliberately incomplete) terms of the system's equations.
//
// Notation of flexible_body.hpp: q = (R, theta, q_f) of one body, node k with x_bar_k,
// Phi_t,k (2 x n_f) and Phi_psi,k (1 x n_f); u_bar_k = Phi_t,k q_f; A = A(theta).

#include "fmbd/flexible_body.hpp"

namespace fmbd {

/// M07T1. Pose of node k: (r_k, phi_k) = (R + A (x_bar_k + u_bar_k), theta + Phi_psi,k q_f).
/// q has size 3 + n_f.
Vec3 node_pose(const NodeModes& node, const VecX& q);

/// M07T2. Jacobian G_k = d(r_k, phi_k)/dq (3 x (3 + n_f)) into G: rows (r_x, r_y, phi_k), columns
/// (R_x, R_y, theta, q_f) (README section 2). G takes that size (it keeps its memory if it has it).
void node_jacobian(const NodeModes& node, const VecX& q, MatX& G);
/// The same as a value (given code, src/flexible_body_given.cpp).
MatX node_jacobian(const NodeModes& node, const VecX& q);

/// M07T3. Convective acceleration c_k = G_k_dot q_dot (3), the part of d2/dt2 (r_k, phi_k)
/// without q_ddot: d2/dt2 (r_k, phi_k) = G_k q_ddot + c_k (README section 2).
Vec3 node_convective_acceleration(const NodeModes& node, const VecX& q, const VecX& qd);

// The chain rule of a node into the system's equations: your assembly of modules 1 to 3 hands a
// node's block or force to the node's body (DeformableBody::add_node_columns, node_gamma_term,
// add_node_force), and the IntuitiveBody (and module 8's body) answers with these. `node` holds
// your node_pose, node_jacobian (G) and node_convective_acceleration (convective) of the node;
// the body's coordinates start at `at` in the system's q (README section 2).

/// M07T2. A joint's or driver's block B (rows x 3), the kernel's Jacobian on the node's pose,
/// into the system's C_q at the rows first_row .. first_row + rows - 1 and the body's 3 + n_f
/// columns from `at`: the block of C_q with respect to the body's coordinates (it adds).
void add_node_block_columns(const NodeMarker& node, const RowBlock& B, int first_row, int at, MatX& Cq);

/// M07T2. A kernel's generalised force Q (3) on the node's pose, into the system's Q_a at the
/// body's 3 + n_f rows from `at`: the force that does the same virtual work on the body's
/// coordinates (it adds).
void add_node_force_rows(const NodeMarker& node, const Vec3& Q, int at, VecX& Q_a);

/// M07T3. The term (rows) that a node adds to the gamma of a constraint whose kernel block on the
/// node's pose is B: the part of B times the node's acceleration that does not multiply q_ddot,
/// moved to the right-hand side.
RowVector node_gamma_correction(const NodeMarker& node, const RowBlock& B);

// The body's terms of the system's equations of motion (3), M q_ddot + C_q^T lambda = Q_a, in the
// intuitive form (README section 3): its constant mass matrix M_bar in M, gravity and -K_bar q in
// Q_a, and nothing else. They add into the system's M and Q_a at the body's coordinates
// at .. at + 3 + n_f (q, q_dot of the system: the body's q_j = q.segment(at, 3 + n_f)); module 3's
// mass_matrix(model, q) and applied_forces call them through the IntuitiveBody. Module 8 corrects
// these same two functions (add_ffrf_mass, add_ffrf_forces). Both throw std::invalid_argument if
// the body's coordinates do not fit in q, or M, Q_a and q differ in size.

/// M07T4. M_bar in M: adds M_bar = Phi^T M_FE Phi (data.basis.M_bar, (3 + n_f) square) to the
/// rows and columns at .. at + 3 + n_f of the system's mass matrix M (n x n). For the free-free
/// modes of this module (M-orthogonal, mass-normalised) M_bar = diag(m, m, J, I). M_bar does not
/// depend on q: the first thing module 8 corrects.
void add_intuitive_mass(const ModalBodyData& data, const VecX& q, int at, MatX& M);

/// M07T5. The generalised force of gravity g (global axes) on the body's distributed mass (3 + n_f):
/// Q_g = -(dV_g/dq_j)^T with V_g = -g^T (m R + A S_f q_f), the potential of the body's first moment
/// (S_f = 0 for an M-orthogonal basis; module 8 uses this force with other bases too). Like
/// add_intuitive_forces, it adds at the body's rows at .. at + 3 + n_f of the system's Q_a, with
/// the body's q_j = q.segment(at, 3 + n_f) of the system's q; same errors.
void add_flexible_gravity_force(const ModalBodyData& data, const VecX& q, const Vec2& g, int at, VecX& Q_a);
/// Q_g of the body's own coordinates q_j (3 + n_f) as a value (given code: add_flexible_gravity_force
/// into a zero vector).
VecX flexible_gravity_force(const ModalBodyData& data, const VecX& q_j, const Vec2& g);

/// M07T6. -K_bar q in Q_a: adds the body's own forces of the intuitive form, its gravity
/// (add_flexible_gravity_force) and the elastic force -K_bar q_j (K_bar = data.basis.K_bar, whose rigid
/// rows and columns are zero), to the rows at .. at + 3 + n_f of the system's Q_a (n). The
/// intuitive form has no velocity terms: q_dot is not used (module 8 adds Q_v here).
void add_intuitive_forces(const ModalBodyData& data, const VecX& q, const VecX& qd, const Vec2& g, int at,
                          VecX& Q_a);

}  // namespace fmbd
