// Exercise file of module 8, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
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
  // TODO(M08T1): the rows L_k (3 x (3 + n_f)) of node k in the map L of u_ddot^{j,o} = L q_ddot + b
  //   into L, README section 1, ffrf.hpp: the node's absolute acceleration, with its components in
  //   frame j, as a linear function of q_ddot. L comes from the caller and keeps its memory, as
  //   G in your node_jacobian. Stuck? ./workbook hint M08T1
  unused(node, q, L);
  throw NotImplemented("M08T1 node_acceleration_map");
}

Vec3 node_acceleration_bias(const NodeModes& node, const VecX& q, const VecX& qd) {
  Model::check_size(q, 3 + static_cast<int>(node.Phi_t.cols()), "q", "node_acceleration_bias");
  Model::check_size(qd, 3 + static_cast<int>(node.Phi_t.cols()), "q_dot", "node_acceleration_bias");
  // TODO(M08T2): the rows b_k (3) of node k in the velocity bias b of u_ddot^{j,o} = L q_ddot + b,
  //   README section 1, ffrf.hpp: what remains of the node's absolute acceleration in frame j at
  //   q_ddot = 0. theta_dot is qd(2). Stuck? ./workbook hint M08T2
  unused(node, q, qd);
  throw NotImplemented("M08T2 node_acceleration_bias");
}

void add_ffrf_mass(const FlexibleBodyData& data, const VecX& q, int at, MatX& M) {
  check_body_block(data, q, at, M.rows(), "add_ffrf_mass");
  // TODO(M08T3): M(q) in M: your add_intuitive_mass of module 7 with M_bar replaced by the mass
  //   matrix M(q_j) = L^T M_FE L of the body's coordinates q_j, README section 2, ffrf.hpp, with L
  //   from the given stacked_map(data, q_j, L) and M_FE = data.matrices.M (a sparse matrix:
  //   products with dense ones read as usual, and cost only its non-zero entries). Keep q_j, L and
  //   M_FE L in this thread's FfrfWorkspace (ffrf_workspace()), not in new matrices.
  //   Stuck? ./workbook hint M08T3
  unused(data, q, at, M);
  throw NotImplemented("M08T3 add_ffrf_mass");
}

void add_quadratic_velocity_vector(const FlexibleBodyData& data, const VecX& q, const VecX& qd, int at, VecX& Q_a) {
  check_body_block(data, q, at, Q_a.size(), "add_quadratic_velocity_vector");
  check_body_block(data, qd, at, Q_a.size(), "add_quadratic_velocity_vector");
  // TODO(M08T4): the quadratic velocity vector Q_v (3 + n_f) of the body's (q_j, q_j_dot), added to
  //   Q_a at its rows at .. at + 3 + n_f, README section 2, ffrf.hpp: the FE inertia forces of the
  //   velocity bias b, on the right-hand side of M(q) q_ddot = Q_v + Q_e + Q_a. L and b come from
  //   the given stacked_map(data, q_j, L) and stacked_bias(data, q_j, q_j_dot, b), into this
  //   thread's FfrfWorkspace (ffrf_workspace()). Stuck? ./workbook hint M08T4
  unused(data, q, qd, at, Q_a);
  throw NotImplemented("M08T4 add_quadratic_velocity_vector");
}

void add_ffrf_forces(const FlexibleBodyData& data, const VecX& q, const VecX& qd, const Vec2& g, int at,
                     VecX& Q_a) {
  check_body_block(data, q, at, Q_a.size(), "add_ffrf_forces");
  check_body_block(data, qd, at, Q_a.size(), "add_ffrf_forces");
  // TODO(M08T5): Q_v in Q_a: your add_intuitive_forces of module 7 (gravity and -K_bar q_j, as
  //   before) plus your add_quadratic_velocity_vector of the body's (q_j, q_j_dot), README section 2,
  //   ffrf.hpp. Stuck? ./workbook hint M08T5
  unused(data, q, qd, g, at, Q_a);
  throw NotImplemented("M08T5 add_ffrf_forces");
}

}  // namespace fmbd
