// Exercise file of module 7, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory and the hints.
// Module 7, tasks T1 to T4: the nodes of a flexible body and its intuitive equations of motion.
#include "fmbd/errors.hpp"
#include "fmbd/intuitive_flexible.hpp"

namespace fmbd {

namespace {

// q = (R, theta, q_f): the elastic part.
[[maybe_unused]] VecX elastic(const VecX& q) { return q.tail(q.size() - 3); }

void check_node_state(const NodeModes& node, const VecX& v, const char* what, const char* where) {
  Model::check_size(v, 3 + static_cast<int>(node.Phi_t.cols()), what, where);
}

}  // namespace

Vec3 node_pose(const NodeModes& node, const VecX& q) {
  check_node_state(node, q, "q", "node_pose");
  // TODO(M07T1): u_bar = Phi_t q_f is the node's elastic displacement in the frame, psi = Phi_psi q_f
  //   its section rotation (a 1x1 product: take (...)(0)). Return (R + A(theta) (x_bar + u_bar),
  //   theta + psi). rotation() is module 1's A.
  unused(node, q);
  throw NotImplemented("M07T1 node_pose");
}

MatX node_jacobian(const NodeModes& node, const VecX& q) {
  check_node_state(node, q, "q", "node_jacobian");
  // TODO(M07T2): G (3 x (3 + n_f)), zero to start. Rows 0-1 (the position r):
  //   columns 0-1 the identity, column 2 A I~ (x_bar + u_bar) (the rigid point Jacobian of
  //   module 1 with s_bar = x_bar + u_bar), columns 3.. A Phi_t.
  //   Row 2 (the angle theta + psi): 1 in column 2, Phi_psi in columns 3...
  unused(node, q);
  throw NotImplemented("M07T2 node_jacobian");
}

Vec3 node_convective_acceleration(const NodeModes& node, const VecX& q, const VecX& qd) {
  check_node_state(node, q, "q", "node_convective_acceleration");
  check_node_state(node, qd, "q_dot", "node_convective_acceleration");
  // TODO(M07T3): differentiate r = R + A (x_bar + u_bar) twice. With theta_dot = qd(2) and
  //   u_bar_dot = Phi_t q_f_dot, the terms without a second derivative are
  //     -theta_dot^2 A (x_bar + u_bar)          (centripetal)
  //     +2 theta_dot A I~ u_bar_dot             (Coriolis)
  //   and the angle theta + psi is linear in q: its convective term is 0.
  unused(node, q, qd);
  throw NotImplemented("M07T3 node_convective_acceleration");
}

MatX intuitive_mass_matrix(const ModalBodyData& data) {
  // TODO(M07T4): the intuitive form keeps the reduced mass matrix of module 6 as it is:
  //   M_bar = Phi^T M_FE Phi (data.basis.M_bar), constant, in the coordinates (R, theta, q_f).
  unused(data);
  throw NotImplemented("M07T4 intuitive_mass_matrix");
}

VecX intuitive_body_forces(const ModalBodyData& data, const VecX& q, const Vec2& g) {
  Model::check_size(q, 3 + data.num_modes(), "q", "intuitive_body_forces");
  // TODO(M07T4): Q (3 + n_f) is minus the gradient of V = -g^T (m R + A S_f q_f) + 1/2 q_f^T K_ff q_f:
  //   Q_R = m g,   Q_theta = g^T A I~ S_f q_f,   Q_f = S_f^T A^T g - K_ff q_f
  //   (data.mass, data.S_f, data.K_ff). S_f is zero for an M-orthogonal basis, but keep it.
  unused(data, q, g);
  throw NotImplemented("M07T4 intuitive_body_forces");
}

}  // namespace fmbd
