// Given code of the geometric stiffening (declared in fmbd/geometric_stiffening.hpp): the element
// slope matrix, the tree of elements from the anchor, the recursion over it that calls your M08T7,
// and the stiffened body, whose rows are your M08T1 and M08T2 with your M08T8.
#include "fmbd/geometric_stiffening.hpp"

#include <cmath>
#include <deque>
#include <string>

#include "fmbd/errors.hpp"

namespace fmbd {

namespace {

// Transverse DOFs (v_a, psi_a, v_b, psi_b) of element e in the nodal DOFs: rows of T_e Phi_f.
MatX element_bending_rows(const FlexibleBodyData& data, int node_a, int node_b, const Vec2& normal) {
  MatX rows(4, data.num_modes());
  const int nodes[2] = {node_a, node_b};
  for (int i = 0; i < 2; ++i) {
    const int k = nodes[i];
    rows.row(2 * i) = normal.transpose() * data.Phi_f.middleRows(3 * k, 2);
    rows.row(2 * i + 1) = data.Phi_f.row(3 * k + 2);
  }
  return rows;
}

void check_elastic(const Foreshortening& fs, const VecX& v, const char* what) {
  const Eigen::Index n_f = fs.H.empty() ? 0 : fs.H.front().rows();
  if (v.size() != n_f)
    throw ModelError(std::string("node_shortening: ") + what + " has size " + std::to_string(v.size()) +
                     ", expected n_f = " + std::to_string(n_f));
}

}  // namespace

Mat4 hermite_slope_matrix(double length) {
  if (!(length > 0.0) || !std::isfinite(length))
    throw ModelError("hermite_slope_matrix: element length " + readable(length) + " m must be positive and finite");
  const double l = length;
  const double r = 0.5 * std::sqrt(0.6);
  const double xi[3] = {0.5 - r, 0.5, 0.5 + r};
  const double w[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};
  Mat4 G = Mat4::Zero();
  for (int i = 0; i < 3; ++i) {
    const double x = xi[i];
    // dN/ds of the Hermite functions N1 = 1 - 3x^2 + 2x^3, N2 = l (x - 2x^2 + x^3), N3, N4.
    const Eigen::Vector4d dN((-6 * x + 6 * x * x) / l, 1 - 4 * x + 3 * x * x, (6 * x - 6 * x * x) / l,
                             -2 * x + 3 * x * x);
    G += w[i] * l * dN * dN.transpose();
  }
  return G;
}

Foreshortening foreshortening(const FlexibleBodyData& data, int anchor) {
  const FeModel& fe = data.fe;
  const int N = fe.num_nodes();
  if (anchor < 0 || anchor >= N)
    throw ModelError("foreshortening: anchor node " + std::to_string(anchor) + " is not a node of the model (0 .. " +
                     std::to_string(N - 1) + ")");
  if (data.Phi_f.rows() != 3 * N)
    throw ModelError("foreshortening: Phi_f has " + std::to_string(data.Phi_f.rows()) + " rows, expected " +
                     std::to_string(3 * N) + " for " + std::to_string(N) + " nodes");
  if (fe.num_elements() != N - 1)
    throw ModelError("foreshortening: the elements must form a tree (" + std::to_string(N - 1) +
                     " elements for " + std::to_string(N) + " nodes), the model has " +
                     std::to_string(fe.num_elements()) + " elements");
  Foreshortening fs;
  fs.anchor = anchor;
  fs.tangent.assign(fe.num_elements(), Vec2::Zero());
  fs.H.assign(fe.num_elements(), MatX());
  fs.parent_element.assign(N, -1);
  fs.parent_node.assign(N, -1);
  std::vector<std::vector<int>> touching(N);
  for (int e = 0; e < fe.num_elements(); ++e) {
    touching[fe.elements()[e].node_a].push_back(e);
    touching[fe.elements()[e].node_b].push_back(e);
  }
  // Breadth-first from the anchor: each element is met once, from its node nearer the anchor.
  std::vector<bool> reached(N, false);
  std::deque<int> queue{anchor};
  reached[anchor] = true;
  while (!queue.empty()) {
    const int a = queue.front();
    queue.pop_front();
    fs.order.push_back(a);
    for (int e : touching[a]) {
      if (e == fs.parent_element[a]) continue;
      const BeamElement& el = fe.elements()[e];
      const int b = el.node_a == a ? el.node_b : el.node_a;
      if (reached[b])
        throw ModelError("foreshortening: element " + std::to_string(e) + " closes a loop at node " +
                         std::to_string(b) + "; the elements must form a tree");
      reached[b] = true;
      fs.parent_element[b] = e;
      fs.parent_node[b] = a;
      const Vec2 chord = fe.nodes()[b] - fe.nodes()[a];
      const double l = chord.norm();
      fs.tangent[e] = chord / l;
      const MatX rows = element_bending_rows(data, a, b, I_tilde() * fs.tangent[e]);
      fs.H[e] = rows.transpose() * hermite_slope_matrix(l) * rows;
      queue.push_back(b);
    }
  }
  for (int k = 0; k < N; ++k)
    if (!reached[k])
      throw ModelError("foreshortening: node " + std::to_string(k) + " is not connected to the anchor node " +
                       std::to_string(anchor));
  return fs;
}

std::vector<NodeShortening> node_shortening(const Foreshortening& fs, const VecX& q_f, const VecX& q_f_dot) {
  check_elastic(fs, q_f, "q_f");
  check_elastic(fs, q_f_dot, "q_f_dot");
  std::vector<NodeShortening> out(fs.parent_node.size());
  for (int k : fs.order) {
    const int e = fs.parent_element[k];
    if (e < 0) {
      out[k].J = MatX::Zero(2, q_f.size());
      continue;
    }
    out[k] = shortening_across_element(out[fs.parent_node[k]], fs.H[e], fs.tangent[e], q_f, q_f_dot);
    if (out[k].J.rows() != 2 || out[k].J.cols() != q_f.size())
      throw ModelError("shortening_across_element: J is " + std::to_string(out[k].J.rows()) + " x " +
                       std::to_string(out[k].J.cols()) + ", expected 2 x n_f = 2 x " + std::to_string(q_f.size()));
  }
  return out;
}

StiffenedFfrfBody::StiffenedFfrfBody(std::shared_ptr<const FlexibleBodyData> data, int anchor)
    : FfrfBody(data), fe_(std::move(data)), fs_(foreshortening(*fe_, anchor)) {}

void StiffenedFfrfBody::acceleration_terms(const VecX& q, const VecX& qd, MatX& L, VecX& b) const {
  check_state(q, "q", "acceleration_terms");
  check_state(qd, "q_dot", "acceleration_terms");
  const int n_f = num_modes();
  const std::vector<NodeShortening> s = node_shortening(fs_, q.tail(n_f), qd.tail(n_f));
  L.resize(3 * num_nodes(), 3 + n_f);
  b.resize(3 * num_nodes());
  for (int k = 0; k < num_nodes(); ++k) {
    const NodeModes& node = fe_->nodes[k];
    MatX L_k = node_acceleration_map(node, q);
    Vec3 b_k = node_acceleration_bias(node, q, qd);
    add_shortening_rows(s[k], qd, L_k, b_k);
    L.middleRows<3>(3 * k) = L_k;
    b.segment<3>(3 * k) = b_k;
  }
}

NodeMarker StiffenedFfrfBody::node_marker(int node, const VecX& q, const VecX& qd) const {
  check_state(q, "q", "node_marker");
  check_state(qd, "q_dot", "node_marker");
  if (node < 0 || node >= num_nodes())
    throw ModelError("StiffenedFfrfBody::node_marker: node " + std::to_string(node) + " is not a node of the body (0 .. " +
                     std::to_string(num_nodes() - 1) + ")");
  const int n_f = num_modes();
  const NodeModes& modes = fe_->nodes[node];
  const NodeShortening s = node_shortening(fs_, q.tail(n_f), qd.tail(n_f))[node];
  MatX L_k = node_acceleration_map(modes, q);
  Vec3 b_k = node_acceleration_bias(modes, q, qd);
  add_shortening_rows(s, qd, L_k, b_k);
  // L_k and b_k have frame-j components of the translation: turn them back with A.
  Eigen::Matrix3d to_global = Eigen::Matrix3d::Identity();
  to_global.topLeftCorner<2, 2>() = rotation(q(2));
  NodeMarker m;
  const Vec2 p = modes.x_bar + modes.Phi_t * q.tail(n_f) + s.f;  // position in frame j
  m.pose << q.head<2>() + rotation(q(2)) * p, q(2) + (modes.Phi_psi * q.tail(n_f))(0);
  m.G = to_global * L_k;
  m.velocity = m.G * qd;
  m.convective = to_global * b_k;
  return m;
}

MatX StiffenedFfrfBody::own_mass(const VecX& q) const {
  MatX L;
  VecX b;
  acceleration_terms(q, VecX::Zero(q.size()), L, b);
  return L.transpose() * (fe_->matrices.M * L);
}

void StiffenedFfrfBody::add_mass(const VecX& q, int at, MatX& M) const {
  check_body_block(*fe_, q, at, M.rows(), "StiffenedFfrfBody::add_mass");
  const int n = 3 + num_modes();
  M.block(at, at, n, n) += own_mass(q.segment(at, n));
}

void StiffenedFfrfBody::add_forces(const VecX& q, const VecX& qd, const Vec2& g, int at, VecX& Q_a) const {
  check_body_block(*fe_, q, at, Q_a.size(), "StiffenedFfrfBody::add_forces");
  check_body_block(*fe_, qd, at, Q_a.size(), "StiffenedFfrfBody::add_forces");
  const int n = 3 + num_modes();
  Q_a.segment(at, n) += own_forces(q.segment(at, n), qd.segment(at, n), g);
}

VecX StiffenedFfrfBody::own_forces(const VecX& q, const VecX& qd, const Vec2& g) const {
  MatX L;
  VecX b;
  acceleration_terms(q, qd, L, b);
  VecX field = -b;  // the inertia of the bias, with gravity below
  const Vec2 g_local = rotation(q(2)).transpose() * g;
  for (int k = 0; k < num_nodes(); ++k) field.segment<2>(3 * k) += g_local;
  VecX Q = L.transpose() * (fe_->matrices.M * field);
  Q.tail(num_modes()) -= fe_->K_ff * q.tail(num_modes());
  return Q;
}

double StiffenedFfrfBody::kinetic_energy(const VecX& q, const VecX& qd) const {
  check_state(qd, "q_dot", "kinetic_energy");
  return 0.5 * qd.dot(own_mass(q) * qd);
}

double StiffenedFfrfBody::potential_energy(const VecX& q, const Vec2& g) const {
  const double linear = IntuitiveBody::potential_energy(q, g);
  const int n_f = num_modes();
  const std::vector<NodeShortening> s = node_shortening(fs_, q.tail(n_f), VecX::Zero(n_f));
  VecX field = VecX::Zero(3 * num_nodes());
  const Vec2 g_local = rotation(q(2)).transpose() * g;
  for (int k = 0; k < num_nodes(); ++k) field.segment<2>(3 * k) = g_local;
  const VecX F = fe_->matrices.M * field;  // nodal gravity forces, frame j
  double work = 0.0;
  for (int k = 0; k < num_nodes(); ++k) work += F.segment<2>(3 * k).dot(s[k].f);
  return linear - work;
}

std::shared_ptr<const DeformableBody> make_stiffened_ffrf_body(std::shared_ptr<const FlexibleBodyData> data) {
  return std::make_shared<StiffenedFfrfBody>(std::move(data), 0);
}

}  // namespace fmbd
