// Module 7, tasks T1 to T6: the nodes of a flexible body, which its joints grip, and its terms of
// the system's equations of motion in the intuitive form: M_bar in M, gravity and -K_bar q in Q_a.
#include "fmbd/errors.hpp"
#include "fmbd/intuitive_flexible.hpp"

namespace fmbd {

namespace {

// q = (R, theta, q_f): the elastic part, a view into q (no copy).
[[maybe_unused]] auto elastic(const VecX& q) { return q.tail(q.size() - 3); }

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
  const Vec2 u_bar = node.Phi_t * elastic(q);
  const Vec2 r = q.head<2>() + rotation(q(2)) * (node.x_bar + u_bar);
  return Vec3(r.x(), r.y(), q(2) + node.Phi_psi.row(0).dot(elastic(q)));
  // END SOLUTION
  // STUB: unused(node, q);
  // STUB: throw NotImplemented("M07T1 node_pose");
}

void node_jacobian(const NodeModes& node, const VecX& q, MatX& G) {
  check_node_state(node, q, "q", "node_jacobian");
  // TASK(M07T2): the Jacobian G_k = d p_k / d q_j of the node (3 x (3 + n_f); rows r_x, r_y, phi;
  //   columns R_x, R_y, theta, q_f) into G, README section 2, intuitive_flexible.hpp. G comes
  //   from the caller and keeps its memory: size it with G.setZero(rows, cols), and write a
  //   product into a block with .noalias() (no temporary). Stuck? ./workbook hint M07T2
  // BEGIN SOLUTION
  const int n_f = static_cast<int>(node.Phi_t.cols());
  const Mat2 A = rotation(q(2));
  const Vec2 u_bar = node.Phi_t * elastic(q);
  G.setZero(3, 3 + n_f);
  G.block<2, 2>(0, 0).setIdentity();
  G.block<2, 1>(0, 2) = A * I_tilde() * (node.x_bar + u_bar);
  G.block(0, 3, 2, n_f).noalias() = A * node.Phi_t;
  G(2, 2) = 1.0;
  G.block(2, 3, 1, n_f) = node.Phi_psi;
  // END SOLUTION
  // STUB: unused(node, q, G);
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
  const Vec2 u_bar = node.Phi_t * elastic(q), u_bar_dot = node.Phi_t * elastic(qd);
  const Vec2 a = -w * w * A * (node.x_bar + u_bar) + 2 * w * A * I_tilde() * u_bar_dot;
  return Vec3(a.x(), a.y(), 0.0);
  // END SOLUTION
  // STUB: unused(node, q, qd);
  // STUB: throw NotImplemented("M07T3 node_convective_acceleration");
}

void add_node_block_columns(const NodeMarker& node, const RowBlock& B, int first_row, int at, MatX& Cq) {
  // TASK(M07T2): the block B (rows x 3) of a joint or driver on the node's pose into C_q, at the
  //   rows first_row .. and the body's 3 + n_f columns from `at`, through the chain rule with the
  //   node's Jacobian node.G (your node_jacobian), README section 2, intuitive_flexible.hpp.
  //   Module 1's add_jacobian_columns hands a node's block here. Stuck? ./workbook hint M07T2
  // BEGIN SOLUTION
  Cq.block(first_row, at, B.rows(), node.G.cols()).noalias() += B * node.G;
  // END SOLUTION
  // STUB: unused(node, B, first_row, at, Cq);
  // STUB: throw NotImplemented("M07T2 add_node_block_columns");
}

void add_node_force_rows(const NodeMarker& node, const Vec3& Q, int at, VecX& Q_a) {
  // TASK(M07T2): a kernel's force Q (3) on the node's pose into Q_a at the body's 3 + n_f rows
  //   from `at`: the generalised force that does the same virtual work, README section 2.
  //   Module 3's add_generalised_force hands a node's force here.
  // BEGIN SOLUTION
  Q_a.segment(at, node.G.cols()).noalias() += node.G.transpose() * Q;
  // END SOLUTION
  // STUB: unused(node, Q, at, Q_a);
  // STUB: throw NotImplemented("M07T2 add_node_force_rows");
}

RowVector node_gamma_correction(const NodeMarker& node, const RowBlock& B) {
  // TASK(M07T3): the term the node adds to the gamma of a constraint whose kernel block on the
  //   node's pose is B (rows x 3), with the node's convective acceleration node.convective (your
  //   node_convective_acceleration), README section 2. Module 2's constraint_gamma adds it
  //   through node_gamma_terms. Stuck? ./workbook hint M07T3
  // BEGIN SOLUTION
  return -(B * node.convective);
  // END SOLUTION
  // STUB: unused(node, B);
  // STUB: throw NotImplemented("M07T3 node_gamma_correction");
}

void add_intuitive_mass(const ModalBodyData& data, [[maybe_unused]] const VecX& q, int at, MatX& M) {
  check_body_block(data, q, at, M.rows(), "add_intuitive_mass");
  // TASK(M07T4): M_bar in M: add the body's mass matrix of the intuitive form, the constant
  //   M_bar = Phi^T M_FE Phi of its basis (data.basis.M_bar, your M06T2), to the system's M at
  //   the body's rows and columns at .. at + 3 + n_f, README section 3, intuitive_flexible.hpp.
  //   Stuck? ./workbook hint M07T4
  // BEGIN SOLUTION
  const int n = 3 + data.num_modes();
  M.block(at, at, n, n) += data.basis.M_bar;
  // END SOLUTION
  // STUB: unused(data, q, at, M);
  // STUB: throw NotImplemented("M07T4 add_intuitive_mass");
}

void add_flexible_gravity_force(const ModalBodyData& data, const VecX& q, const Vec2& g, int at, VecX& Q_a) {
  check_body_block(data, q, at, Q_a.size(), "add_flexible_gravity_force");
  // TASK(M07T5): the generalised force (3 + n_f) of gravity g (global axes) on the body's
  //   distributed mass, added to Q_a at the body's rows at .. at + 3 + n_f: minus the gradient of
  //   its potential, README section 3, intuitive_flexible.hpp (data.mass, data.S_f), at the body's
  //   q_j = q.segment(at, 3 + n_f). Keep the S_f terms, though S_f = 0 for the free-free modes of
  //   this module: module 8 uses this force with other bases. Stuck? ./workbook hint M07T5
  // BEGIN SOLUTION
  const int n_f = data.num_modes();
  const auto q_f = q.segment(at + 3, n_f);
  const Mat2 A = rotation(q(at + 2));
  const Vec2 S_f_q_f = data.S_f * q_f;
  Q_a.segment<2>(at) += data.mass * g;
  Q_a(at + 2) += g.dot(A * I_tilde() * S_f_q_f);
  Q_a.segment(at + 3, n_f).noalias() += data.S_f.transpose() * (A.transpose() * g);
  // END SOLUTION
  // STUB: unused(data, q, g, at, Q_a);
  // STUB: throw NotImplemented("M07T5 add_flexible_gravity_force");
}

void add_intuitive_forces(const ModalBodyData& data, const VecX& q, [[maybe_unused]] const VecX& qd, const Vec2& g,
                          int at, VecX& Q_a) {
  check_body_block(data, q, at, Q_a.size(), "add_intuitive_forces");
  check_body_block(data, qd, at, Q_a.size(), "add_intuitive_forces");
  // TASK(M07T6): -K_bar q in Q_a: add the body's own forces of the intuitive form to the system's
  //   Q_a at its rows at .. at + 3 + n_f: your add_flexible_gravity_force and the elastic force
  //   -K_bar q_j (K_bar = data.basis.K_bar, your M06T2), README section 3,
  //   intuitive_flexible.hpp. Stuck? ./workbook hint M07T6
  // BEGIN SOLUTION
  const int n = 3 + data.num_modes();
  add_flexible_gravity_force(data, q, g, at, Q_a);
  Q_a.segment(at, n).noalias() -= data.basis.K_bar * q.segment(at, n);
  // END SOLUTION
  // STUB: unused(data, q, qd, g, at, Q_a);
  // STUB: throw NotImplemented("M07T6 add_intuitive_forces");
}

}  // namespace fmbd
