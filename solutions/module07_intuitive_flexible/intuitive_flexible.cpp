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
  // TASK(M07T1): the pose p_k = (r_k, phi_k) of the node (3), README section 1,
  //   intuitive_flexible.hpp, with q = (R, theta, q_f) and node.x_bar, node.Phi_t, node.Phi_psi.
  //   rotation() is module 1's A. Stuck? ./workbook hint M07T1
  // BEGIN SOLUTION
  const VecX q_f = elastic(q);
  const Vec2 r = q.head<2>() + rotation(q(2)) * (node.x_bar + node.Phi_t * q_f);
  return Vec3(r.x(), r.y(), q(2) + (node.Phi_psi * q_f)(0));
  // END SOLUTION
  // STUB: unused(node, q);
  // STUB: throw NotImplemented("M07T1 node_pose");
}

MatX node_jacobian(const NodeModes& node, const VecX& q) {
  check_node_state(node, q, "q", "node_jacobian");
  // TASK(M07T2): the Jacobian G_k = d p_k / d q_j of the node (3 x (3 + n_f); rows r_x, r_y, phi;
  //   columns R_x, R_y, theta, q_f), README section 2, intuitive_flexible.hpp.
  //   Stuck? ./workbook hint M07T2
  // BEGIN SOLUTION
  const int n_f = static_cast<int>(node.Phi_t.cols());
  const Mat2 A = rotation(q(2));
  MatX G = MatX::Zero(3, 3 + n_f);
  G.block<2, 2>(0, 0).setIdentity();
  G.block<2, 1>(0, 2) = A * I_tilde() * (node.x_bar + node.Phi_t * elastic(q));
  G.block(0, 3, 2, n_f) = A * node.Phi_t;
  G(2, 2) = 1.0;
  G.block(2, 3, 1, n_f) = node.Phi_psi;
  return G;
  // END SOLUTION
  // STUB: unused(node, q);
  // STUB: throw NotImplemented("M07T2 node_jacobian");
}

Vec3 node_convective_acceleration(const NodeModes& node, const VecX& q, const VecX& qd) {
  check_node_state(node, q, "q", "node_convective_acceleration");
  check_node_state(node, qd, "q_dot", "node_convective_acceleration");
  // TASK(M07T3): the convective acceleration c_k of the node (3): the part of d2 p_k / dt2 that
  //   does not multiply q_ddot, p_ddot_k = G_k q_ddot + c_k, README section 2,
  //   intuitive_flexible.hpp. theta_dot is qd(2). Stuck? ./workbook hint M07T3
  // BEGIN SOLUTION
  const double w = qd(2);
  const Mat2 A = rotation(q(2));
  const Vec2 a = -w * w * A * (node.x_bar + node.Phi_t * elastic(q)) + 2 * w * A * I_tilde() * (node.Phi_t * elastic(qd));
  return Vec3(a.x(), a.y(), 0.0);
  // END SOLUTION
  // STUB: unused(node, q, qd);
  // STUB: throw NotImplemented("M07T3 node_convective_acceleration");
}

IntuitiveMatrices intuitive_matrices(const MatX& Phi, const SparseMat& M_FE, const SparseMat& K_FE) {
  if (M_FE.rows() != Phi.rows() || M_FE.cols() != Phi.rows() || K_FE.rows() != Phi.rows() || K_FE.cols() != Phi.rows())
    throw std::invalid_argument("intuitive_matrices: Phi has " + std::to_string(Phi.rows()) + " rows, M_FE is " +
                                std::to_string(M_FE.rows()) + " x " + std::to_string(M_FE.cols()) + " and K_FE " +
                                std::to_string(K_FE.rows()) + " x " + std::to_string(K_FE.cols()));
  // TASK(M07T4): the reduced matrices M_bar = Phi^T M_FE Phi and K_bar = Phi^T K_FE Phi
  //   ((3 + n_f) square), README section 3, intuitive_flexible.hpp. M_FE and K_FE are
  //   sparse: a product with a dense matrix reads as usual. Stuck? ./workbook hint M07T4
  // BEGIN SOLUTION
  IntuitiveMatrices r;
  r.M_bar = Phi.transpose() * (M_FE * Phi);
  r.K_bar = Phi.transpose() * (K_FE * Phi);
  return r;
  // END SOLUTION
  // STUB: unused(Phi, M_FE, K_FE);
  // STUB: throw NotImplemented("M07T4 intuitive_matrices");
}

NodeJointRows revolute_on_node(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const NodeModes& node,
                               const VecX& q_j, const VecX& qd_j) {
  check_node_state(node, q_j, "q_j", "revolute_on_node");
  check_node_state(node, qd_j, "q_j_dot", "revolute_on_node");
  // TASK(M07T5): a revolute joint between point s_i of rigid body i and node k of flexible body j,
  //   README section 2, intuitive_flexible.hpp: your revolute_constraint (module 1) and
  //   revolute_gamma (module 2) on the node's marker (pose p_k, rate G_k q_j_dot, s_bar = 0), then
  //   the chain rule with your node_jacobian and node_convective_acceleration.
  //   Stuck? ./workbook hint M07T5
  // BEGIN SOLUTION
  const Vec3 p = node_pose(node, q_j);
  const MatX G = node_jacobian(node, q_j);
  const Vec3 p_dot = G * qd_j;
  const ConstraintBlock kernel = revolute_constraint(q_i, s_i, p, Vec2::Zero());
  NodeJointRows rows;
  rows.C = kernel.C;
  rows.Cq_i = kernel.Cq_i;
  rows.Cq_j = kernel.Cq_j * G;
  rows.gamma = revolute_gamma(q_i, qd_i, s_i, p, p_dot, Vec2::Zero()) -
               kernel.Cq_j * node_convective_acceleration(node, q_j, qd_j);
  return rows;
  // END SOLUTION
  // STUB: unused(q_i, qd_i, s_i, node, q_j, qd_j);
  // STUB: throw NotImplemented("M07T5 revolute_on_node");
}

VecX intuitive_body_forces(const ModalBodyData& data, const VecX& q, const Vec2& g) {
  Model::check_size(q, 3 + data.num_modes(), "q", "intuitive_body_forces");
  // TASK(M07T6): the body forces Q (3 + n_f) of the intuitive form, README section 3: minus the
  //   gradient of V, gravity g on the distributed mass plus the strain energy (data.mass, data.S_f,
  //   data.K_ff). Keep the S_f terms, though S_f = 0 for an M-orthogonal basis.
  //   Stuck? ./workbook hint M07T6
  // BEGIN SOLUTION
  const VecX q_f = elastic(q);
  const Mat2 A = rotation(q(2));
  VecX Q(q.size());
  Q.head<2>() = data.mass * g;
  Q(2) = g.dot(A * I_tilde() * (data.S_f * q_f));
  Q.tail(q_f.size()) = data.S_f.transpose() * (A.transpose() * g) - data.K_ff * q_f;
  return Q;
  // END SOLUTION
  // STUB: unused(data, q, g);
  // STUB: throw NotImplemented("M07T6 intuitive_body_forces");
}

}  // namespace fmbd
