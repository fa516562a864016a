// Exercise file of module 7, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 7, tasks T1 to T6: the nodes of a flexible body, a joint on a node, and the intuitive
// equations of motion.
#include <stdexcept>
#include <string>

#include "fmbd/errors.hpp"
#include "fmbd/gamma.hpp"
#include "fmbd/intuitive_flexible.hpp"
#include "fmbd/joints.hpp"

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
  // TODO(M07T1): the pose p_k = (r_k, phi_k) of the node (3), README section 1,
  //   intuitive_flexible.hpp, with q = (R, theta, q_f) and node.x_bar, node.Phi_t, node.Phi_psi.
  //   rotation() is module 1's A. Stuck? ./workbook hint M07T1
  unused(node, q);
  throw NotImplemented("M07T1 node_pose");
}

MatX node_jacobian(const NodeModes& node, const VecX& q) {
  check_node_state(node, q, "q", "node_jacobian");
  // TODO(M07T2): the Jacobian G_k = d p_k / d q_j of the node (3 x (3 + n_f); rows r_x, r_y, phi;
  //   columns R_x, R_y, theta, q_f), README section 2, intuitive_flexible.hpp.
  //   Stuck? ./workbook hint M07T2
  unused(node, q);
  throw NotImplemented("M07T2 node_jacobian");
}

Vec3 node_convective_acceleration(const NodeModes& node, const VecX& q, const VecX& qd) {
  check_node_state(node, q, "q", "node_convective_acceleration");
  check_node_state(node, qd, "q_dot", "node_convective_acceleration");
  // TODO(M07T3): the convective acceleration c_k of the node (3): the part of d2 p_k / dt2 that
  //   does not multiply q_ddot, p_ddot_k = G_k q_ddot + c_k, README section 2,
  //   intuitive_flexible.hpp. theta_dot is qd(2). Stuck? ./workbook hint M07T3
  unused(node, q, qd);
  throw NotImplemented("M07T3 node_convective_acceleration");
}

IntuitiveMatrices intuitive_matrices(const MatX& Phi, const SparseMat& M_FE, const SparseMat& K_FE) {
  if (M_FE.rows() != Phi.rows() || M_FE.cols() != Phi.rows() || K_FE.rows() != Phi.rows() || K_FE.cols() != Phi.rows())
    throw std::invalid_argument("intuitive_matrices: Phi has " + std::to_string(Phi.rows()) + " rows, M_FE is " +
                                std::to_string(M_FE.rows()) + " x " + std::to_string(M_FE.cols()) + " and K_FE " +
                                std::to_string(K_FE.rows()) + " x " + std::to_string(K_FE.cols()));
  // TODO(M07T4): the reduced matrices M_bar = Phi^T M_FE Phi and K_bar = Phi^T K_FE Phi
  //   ((3 + n_f) square), README section 3, intuitive_flexible.hpp. M_FE and K_FE are
  //   sparse: a product with a dense matrix reads as usual. Stuck? ./workbook hint M07T4
  unused(Phi, M_FE, K_FE);
  throw NotImplemented("M07T4 intuitive_matrices");
}

NodeJointRows revolute_on_node(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const NodeModes& node,
                               const VecX& q_j, const VecX& qd_j) {
  check_node_state(node, q_j, "q_j", "revolute_on_node");
  check_node_state(node, qd_j, "q_j_dot", "revolute_on_node");
  // TODO(M07T5): a revolute joint between point s_i of rigid body i and node k of flexible body j,
  //   README section 2, intuitive_flexible.hpp: your revolute_constraint (module 1) and
  //   revolute_gamma (module 2) on the node's marker (pose p_k, rate G_k q_j_dot, s_bar = 0), then
  //   the chain rule with your node_jacobian and node_convective_acceleration.
  //   Stuck? ./workbook hint M07T5
  unused(q_i, qd_i, s_i, node, q_j, qd_j);
  throw NotImplemented("M07T5 revolute_on_node");
}

VecX intuitive_body_forces(const ModalBodyData& data, const VecX& q, const Vec2& g) {
  Model::check_size(q, 3 + data.num_modes(), "q", "intuitive_body_forces");
  // TODO(M07T6): the body forces Q (3 + n_f) of the intuitive form, README section 3: minus the
  //   gradient of V, gravity g on the distributed mass plus the strain energy (data.mass, data.S_f,
  //   data.K_ff). Keep the S_f terms, though S_f = 0 for an M-orthogonal basis.
  //   Stuck? ./workbook hint M07T6
  unused(data, q, g);
  throw NotImplemented("M07T6 intuitive_body_forces");
}

}  // namespace fmbd
