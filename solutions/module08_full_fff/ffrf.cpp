// Module 8, tasks T1 to T5: the full floating frame of reference formulation, nodal form.
#include "fmbd/errors.hpp"
#include "fmbd/ffrf.hpp"

namespace fmbd {

namespace {

[[maybe_unused]] VecX elastic(const VecX& q) { return q.tail(q.size() - 3); }

void check_state(const FlexibleBodyData& data, const VecX& v, const char* what, const char* where) {
  Model::check_size(v, 3 + data.num_modes(), what, where);
}

}  // namespace

MatX node_acceleration_map(const NodeModes& node, const VecX& q) {
  Model::check_size(q, 3 + static_cast<int>(node.Phi_t.cols()), "q", "node_acceleration_map");
  // TASK(M08T1): the rows L_k (3 x (3 + n_f)) of node k in the map L of u_ddot^{j,o} = L q_ddot + b,
  //   README section 1, ffrf.hpp: the node's absolute acceleration, with its components in frame j,
  //   as a linear function of q_ddot. Stuck? ./workbook hint M08T1
  // BEGIN SOLUTION
  const int n_f = static_cast<int>(node.Phi_t.cols());
  MatX L = MatX::Zero(3, 3 + n_f);
  L.block<2, 2>(0, 0) = rotation(q(2)).transpose();
  L.block<2, 1>(0, 2) = I_tilde() * (node.x_bar + node.Phi_t * elastic(q));
  L.block(0, 3, 2, n_f) = node.Phi_t;
  L(2, 2) = 1.0;
  L.block(2, 3, 1, n_f) = node.Phi_psi;
  return L;
  // END SOLUTION
  // STUB: unused(node, q);
  // STUB: throw NotImplemented("M08T1 node_acceleration_map");
}

Vec3 node_acceleration_bias(const NodeModes& node, const VecX& q, const VecX& qd) {
  Model::check_size(q, 3 + static_cast<int>(node.Phi_t.cols()), "q", "node_acceleration_bias");
  Model::check_size(qd, 3 + static_cast<int>(node.Phi_t.cols()), "q_dot", "node_acceleration_bias");
  // TASK(M08T2): the rows b_k (3) of node k in the velocity bias b of u_ddot^{j,o} = L q_ddot + b,
  //   README section 1, ffrf.hpp: what remains of the node's absolute acceleration in frame j at
  //   q_ddot = 0. theta_dot is qd(2). Stuck? ./workbook hint M08T2
  // BEGIN SOLUTION
  const double w = qd(2);
  const Vec2 a = -w * w * (node.x_bar + node.Phi_t * elastic(q)) + 2 * w * I_tilde() * (node.Phi_t * elastic(qd));
  return Vec3(a.x(), a.y(), 0.0);
  // END SOLUTION
  // STUB: unused(node, q, qd);
  // STUB: throw NotImplemented("M08T2 node_acceleration_bias");
}

MatX ffrf_mass_matrix(const FlexibleBodyData& data, const VecX& q) {
  check_state(data, q, "q", "ffrf_mass_matrix");
  // TASK(M08T3): the mass matrix M(q) = L^T M_FE L ((3 + n_f) square), README section 2,
  //   ffrf.hpp, with L from the given stacked_map(data, q) and M_FE = data.matrices.M (a sparse
  //   matrix: products with dense ones read as usual, and cost only its non-zero entries).
  //   Stuck? ./workbook hint M08T3
  // BEGIN SOLUTION
  const MatX L = stacked_map(data, q);
  return L.transpose() * data.matrices.M * L;
  // END SOLUTION
  // STUB: unused(data, q);
  // STUB: throw NotImplemented("M08T3 ffrf_mass_matrix");
}

VecX quadratic_velocity_vector(const FlexibleBodyData& data, const VecX& q, const VecX& qd) {
  check_state(data, q, "q", "quadratic_velocity_vector");
  check_state(data, qd, "q_dot", "quadratic_velocity_vector");
  // TASK(M08T4): the quadratic velocity vector Q_v (3 + n_f), README section 2, ffrf.hpp: the FE
  //   inertia forces of the velocity bias b, on the right-hand side of M(q) q_ddot = Q_v + Q_e + Q_a.
  //   L and b come from the given stacked_map(data, q) and stacked_bias(data, q, qd).
  //   Stuck? ./workbook hint M08T4
  // BEGIN SOLUTION
  return -stacked_map(data, q).transpose() * (data.matrices.M * stacked_bias(data, q, qd));
  // END SOLUTION
  // STUB: unused(data, q, qd);
  // STUB: throw NotImplemented("M08T4 quadratic_velocity_vector");
}

VecX ffrf_body_forces(const FlexibleBodyData& data, const VecX& q, const VecX& qd, const Vec2& g) {
  check_state(data, q, "q", "ffrf_body_forces");
  check_state(data, qd, "q_dot", "ffrf_body_forces");
  // TASK(M08T5): the body's own forces Q_v + Q_e + Q_a (3 + n_f), README section 2, ffrf.hpp,
  //   with gravity g (global axes) on the FE masses as Q_a. Build on your quadratic_velocity_vector
  //   and the given stacked_map (data.matrices.M, data.K_ff; data.nodes.size() nodes).
  //   Stuck? ./workbook hint M08T5
  // BEGIN SOLUTION
  const Vec2 g_local = rotation(q(2)).transpose() * g;
  VecX field = VecX::Zero(3 * data.nodes.size());
  for (std::size_t k = 0; k < data.nodes.size(); ++k) field.segment<2>(3 * k) = g_local;
  VecX Q = quadratic_velocity_vector(data, q, qd) + stacked_map(data, q).transpose() * (data.matrices.M * field);
  Q.tail(data.num_modes()) -= data.K_ff * elastic(q);
  return Q;
  // END SOLUTION
  // STUB: unused(data, q, qd, g);
  // STUB: throw NotImplemented("M08T5 ffrf_body_forces");
}

}  // namespace fmbd
