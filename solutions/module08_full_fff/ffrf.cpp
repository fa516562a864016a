// Module 8, tasks T1 to T5: the full floating frame of reference formulation, nodal form.
#include "fmbd/errors.hpp"
#include "fmbd/ffrf.hpp"
#include "fmbd/intuitive_flexible.hpp"

namespace fmbd {

namespace {

// q = (R, theta, q_f): the elastic part, a view into q (no copy).
[[maybe_unused]] auto elastic(const VecX& q) { return q.tail(q.size() - 3); }

}  // namespace

void node_acceleration_map(const NodeModes& node, const VecX& q, MatX& L) {
  Model::check_size(q, 3 + static_cast<int>(node.Phi_t.cols()), "q", "node_acceleration_map");
  // TASK(M08T1): the rows L_k (3 x (3 + n_f)) of node k in the map L of u_ddot^{j,o} = L q_ddot + b
  //   into L, README section 1, ffrf.hpp: the node's absolute acceleration, with its components in
  //   frame j, as a linear function of q_ddot. L comes from the caller and keeps its memory, as
  //   G in your node_jacobian. Stuck? ./workbook hint M08T1
  // BEGIN SOLUTION
  const int n_f = static_cast<int>(node.Phi_t.cols());
  const Vec2 u_bar = node.Phi_t * elastic(q);
  L.setZero(3, 3 + n_f);
  L.block<2, 2>(0, 0) = rotation(q(2)).transpose();
  L.block<2, 1>(0, 2) = I_tilde() * (node.x_bar + u_bar);
  L.block(0, 3, 2, n_f) = node.Phi_t;
  L(2, 2) = 1.0;
  L.block(2, 3, 1, n_f) = node.Phi_psi;
  // END SOLUTION
  // STUB: unused(node, q, L);
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
  const Vec2 u_bar = node.Phi_t * elastic(q), u_bar_dot = node.Phi_t * elastic(qd);
  const Vec2 a = -w * w * (node.x_bar + u_bar) + 2 * w * I_tilde() * u_bar_dot;
  return Vec3(a.x(), a.y(), 0.0);
  // END SOLUTION
  // STUB: unused(node, q, qd);
  // STUB: throw NotImplemented("M08T2 node_acceleration_bias");
}

void add_ffrf_mass(const FlexibleBodyData& data, const VecX& q, int at, MatX& M) {
  check_body_block(data, q, at, M.rows(), "add_ffrf_mass");
  // TASK(M08T3): M(q) in M: your add_intuitive_mass of module 7 with M_bar replaced by the mass
  //   matrix M(q_j) = L^T M_FE L of the body's coordinates q_j, README section 2, ffrf.hpp, with L
  //   from the given stacked_map(data, q_j, L) and M_FE = data.matrices.M (a sparse matrix:
  //   products with dense ones read as usual, and cost only its non-zero entries). Keep q_j, L and
  //   M_FE L in this thread's FfrfWorkspace (ffrf_workspace()), not in new matrices.
  //   Stuck? ./workbook hint M08T3
  // BEGIN SOLUTION
  const int n = 3 + data.num_modes();
  FfrfWorkspace& w = ffrf_workspace();
  w.q_j = q.segment(at, n);
  stacked_map(data, w.q_j, w.L);
  w.ML.noalias() = data.matrices.M * w.L;
  M.block(at, at, n, n).noalias() += w.L.transpose() * w.ML;
  // END SOLUTION
  // STUB: unused(data, q, at, M);
  // STUB: throw NotImplemented("M08T3 add_ffrf_mass");
}

void add_quadratic_velocity_vector(const FlexibleBodyData& data, const VecX& q, const VecX& qd, int at, VecX& Q_a) {
  check_body_block(data, q, at, Q_a.size(), "add_quadratic_velocity_vector");
  check_body_block(data, qd, at, Q_a.size(), "add_quadratic_velocity_vector");
  // TASK(M08T4): the quadratic velocity vector Q_v (3 + n_f) of the body's (q_j, q_j_dot), added to
  //   Q_a at its rows at .. at + 3 + n_f, README section 2, ffrf.hpp: the FE inertia forces of the
  //   velocity bias b, on the right-hand side of M(q) q_ddot = Q_v + Q_e + Q_a. L and b come from
  //   the given stacked_map(data, q_j, L) and stacked_bias(data, q_j, q_j_dot, b), into this
  //   thread's FfrfWorkspace (ffrf_workspace()). Stuck? ./workbook hint M08T4
  // BEGIN SOLUTION
  const int n = 3 + data.num_modes();
  FfrfWorkspace& w = ffrf_workspace();
  w.q_j = q.segment(at, n);
  w.qd_j = qd.segment(at, n);
  stacked_map(data, w.q_j, w.L);
  stacked_bias(data, w.q_j, w.qd_j, w.b);
  w.Mb.noalias() = data.matrices.M * w.b;
  Q_a.segment(at, n).noalias() -= w.L.transpose() * w.Mb;
  // END SOLUTION
  // STUB: unused(data, q, qd, at, Q_a);
  // STUB: throw NotImplemented("M08T4 add_quadratic_velocity_vector");
}

void add_ffrf_forces(const FlexibleBodyData& data, const VecX& q, const VecX& qd, const Vec2& g, int at,
                     VecX& Q_a) {
  check_body_block(data, q, at, Q_a.size(), "add_ffrf_forces");
  check_body_block(data, qd, at, Q_a.size(), "add_ffrf_forces");
  // TASK(M08T5): Q_v in Q_a: your add_intuitive_forces of module 7 (gravity and -K_bar q_j, as
  //   before) plus your add_quadratic_velocity_vector of the body's (q_j, q_j_dot), README section 2,
  //   ffrf.hpp. Stuck? ./workbook hint M08T5
  // BEGIN SOLUTION
  const int n = 3 + data.num_modes();
  add_flexible_gravity_force(data, q, g, at, Q_a);
  Q_a.segment(at, n).noalias() -= data.basis.K_bar * q.segment(at, n);
  add_quadratic_velocity_vector(data, q, qd, at, Q_a);
  // END SOLUTION
  // STUB: unused(data, q, qd, g, at, Q_a);
  // STUB: throw NotImplemented("M08T5 add_ffrf_forces");
}

}  // namespace fmbd
