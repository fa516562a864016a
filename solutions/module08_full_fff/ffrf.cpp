// Module 8, tasks T1 to T5: the full floating frame of reference formulation, nodal form.
#include "fmbd/errors.hpp"
#include "fmbd/ffrf.hpp"
#include "fmbd/intuitive_flexible.hpp"

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

void add_ffrf_mass(const FlexibleBodyData& data, const VecX& q, int at, MatX& M) {
  check_body_block(data, q, at, M.rows(), "add_ffrf_mass");
  // TASK(M08T3): M(q) in M: your add_intuitive_mass of module 7 with M_bar replaced by the mass
  //   matrix M(q_j) = L^T M_FE L of the body's coordinates q_j, README section 2, ffrf.hpp, with L
  //   from the given stacked_map(data, q_j) and M_FE = data.matrices.M (a sparse matrix: products
  //   with dense ones read as usual, and cost only its non-zero entries).
  //   Stuck? ./workbook hint M08T3
  // BEGIN SOLUTION
  const int n = 3 + data.num_modes();
  const MatX L = stacked_map(data, q.segment(at, n));
  M.block(at, at, n, n) += L.transpose() * data.matrices.M * L;
  // END SOLUTION
  // STUB: unused(data, q, at, M);
  // STUB: throw NotImplemented("M08T3 add_ffrf_mass");
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

void add_ffrf_forces(const FlexibleBodyData& data, const VecX& q, const VecX& qd, const Vec2& g, int at,
                     VecX& Q_a) {
  check_body_block(data, q, at, Q_a.size(), "add_ffrf_forces");
  check_body_block(data, qd, at, Q_a.size(), "add_ffrf_forces");
  // TASK(M08T5): Q_v in Q_a: your add_intuitive_forces of module 7 (gravity and -K_bar q_j, as
  //   before) plus the quadratic velocity vector of the body's (q_j, q_j_dot), README section 2,
  //   ffrf.hpp. Stuck? ./workbook hint M08T5
  // BEGIN SOLUTION
  const int n = 3 + data.num_modes();
  const VecX q_j = q.segment(at, n);
  Q_a.segment(at, n) += flexible_gravity_force(data, q_j, g) - data.basis.K_bar * q_j +
                        quadratic_velocity_vector(data, q_j, qd.segment(at, n));
  // END SOLUTION
  // STUB: unused(data, q, qd, g, at, Q_a);
  // STUB: throw NotImplemented("M08T5 add_ffrf_forces");
}

}  // namespace fmbd
