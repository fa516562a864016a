// Exercise file of module 8, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory and the hints.
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
  // TODO(M08T1): the absolute acceleration of the node in frame j is A^T times the global one.
  //   Rows 0-1: A^T in columns 0-1 (R_ddot seen from the frame), I~ (x_bar + u_bar) in column 2,
  //   Phi_t in columns 3...  Row 2: 1 in column 2, Phi_psi in columns 3...
  //   Compare module 7's node_jacobian: the same shape, but in frame j (no A in front).
  unused(node, q);
  throw NotImplemented("M08T1 node_acceleration_map");
}

Vec3 node_acceleration_bias(const NodeModes& node, const VecX& q, const VecX& qd) {
  Model::check_size(q, 3 + static_cast<int>(node.Phi_t.cols()), "q", "node_acceleration_bias");
  Model::check_size(qd, 3 + static_cast<int>(node.Phi_t.cols()), "q_dot", "node_acceleration_bias");
  // TODO(M08T2): the velocity-dependent part of the node's acceleration in frame j:
  //   centripetal -theta_dot^2 (x_bar + u_bar) and Coriolis 2 theta_dot I~ Phi_t q_f_dot;
  //   the rotation row has none (0).
  unused(node, q, qd);
  throw NotImplemented("M08T2 node_acceleration_bias");
}

MatX ffrf_mass_matrix(const FlexibleBodyData& data, const VecX& q) {
  check_state(data, q, "q", "ffrf_mass_matrix");
  // TODO(M08T3): M(q) = L^T M_FE L with L = stacked_map(data, q) (given: the node maps stacked in the
  //   DOF order of the FE model) and M_FE = data.matrices.M.
  unused(data, q);
  throw NotImplemented("M08T3 ffrf_mass_matrix");
}

VecX quadratic_velocity_vector(const FlexibleBodyData& data, const VecX& q, const VecX& qd) {
  check_state(data, q, "q", "quadratic_velocity_vector");
  check_state(data, qd, "q_dot", "quadratic_velocity_vector");
  // TODO(M08T4): Q_v = -L^T M_FE g with g = stacked_bias(data, q, qd): the FE inertia forces of the
  //   velocity-dependent accelerations, on the right-hand side of M(q) q_ddot = Q_v + ... (README).
  unused(data, q, qd);
  throw NotImplemented("M08T4 quadratic_velocity_vector");
}

VecX ffrf_body_forces(const FlexibleBodyData& data, const VecX& q, const VecX& qd, const Vec2& g) {
  check_state(data, q, "q", "ffrf_body_forces");
  check_state(data, qd, "q_dot", "ffrf_body_forces");
  // TODO(M08T5): the sum of three forces:
  //   Q_v = quadratic_velocity_vector(data, q, qd);
  //   gravity L^T M_FE g^j, with g^j the nodal field (A^T g, 0) at every node (A^T g on the
  //     u_x, u_y DOFs, 0 on psi) and L = stacked_map(data, q);
  //   elastic -K_ff q_f on the elastic rows (3..), zero on (R, theta).
  unused(data, q, qd, g);
  throw NotImplemented("M08T5 ffrf_body_forces");
}

}  // namespace fmbd
