// Geometric stiffening of the full FFRF body by the foreshortening of its beam axis
// (declared and derived in fmbd/geometric_stiffening.hpp).
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
  const std::size_t N = fs.parent_node.size();
  std::vector<NodeShortening> out(N);
  for (int k : fs.order) {
    NodeShortening& s = out[k];
    const int e = fs.parent_element[k];
    if (e < 0) {
      s.J = MatX::Zero(2, q_f.size());
      continue;
    }
    const NodeShortening& parent = out[fs.parent_node[k]];
    const VecX Hq = fs.H[e] * q_f;
    const Vec2& t = fs.tangent[e];
    s.f = parent.f - 0.5 * q_f.dot(Hq) * t;
    s.J = parent.J - t * Hq.transpose();
    s.c = parent.c - q_f_dot.dot(fs.H[e] * q_f_dot) * t;
  }
  return out;
}

StiffenedFfrfBody::StiffenedFfrfBody(std::shared_ptr<const FlexibleBodyData> data, int anchor)
    : FfrfBody(data), fe_(std::move(data)), fs_(foreshortening(*fe_, anchor)) {}

MatX StiffenedFfrfBody::acceleration_map(const VecX& q) const {
  check_state(q, "q", "acceleration_map");
  const int n_f = num_modes();
  const std::vector<NodeShortening> s = node_shortening(fs_, q.tail(n_f), VecX::Zero(n_f));
  MatX L = stacked_map(*fe_, q);
  for (std::size_t k = 0; k < s.size(); ++k) {
    L.block<2, 1>(3 * k, 2) += I_tilde() * s[k].f;
    L.block(3 * k, 3, 2, n_f) += s[k].J;
  }
  return L;
}

VecX StiffenedFfrfBody::acceleration_bias(const VecX& q, const VecX& qd) const {
  check_state(q, "q", "acceleration_bias");
  check_state(qd, "q_dot", "acceleration_bias");
  const int n_f = num_modes();
  const VecX qd_f = qd.tail(n_f);
  const std::vector<NodeShortening> s = node_shortening(fs_, q.tail(n_f), qd_f);
  const double w = qd(2);
  VecX b = stacked_bias(*fe_, q, qd);
  for (std::size_t k = 0; k < s.size(); ++k)
    b.segment<2>(3 * k) += -w * w * s[k].f + 2 * w * I_tilde() * (s[k].J * qd_f) + s[k].c;
  return b;
}

NodeMarker StiffenedFfrfBody::node_marker(int node, const VecX& q, const VecX& qd) const {
  check_state(q, "q", "node_marker");
  check_state(qd, "q_dot", "node_marker");
  if (node < 0 || node >= num_nodes())
    throw ModelError("StiffenedFfrfBody::node_marker: node " + std::to_string(node) + " is not a node of the body (0 .. " +
                     std::to_string(num_nodes() - 1) + ")");
  const int n_f = num_modes();
  const VecX q_f = q.tail(n_f), qd_f = qd.tail(n_f);
  const NodeModes& modes = fe_->nodes[node];
  const NodeShortening s = node_shortening(fs_, q_f, qd_f)[node];
  const Mat2 A = rotation(q(2));
  const Vec2 p = modes.x_bar + modes.Phi_t * q_f + s.f;  // position in frame j
  const MatX D = modes.Phi_t + s.J;                       // dp/dq_f
  NodeMarker m;
  m.pose << q.head<2>() + A * p, q(2) + (modes.Phi_psi * q_f)(0);
  m.G = MatX::Zero(3, 3 + n_f);
  m.G.block<2, 2>(0, 0).setIdentity();
  m.G.block<2, 1>(0, 2) = A * I_tilde() * p;
  m.G.block(0, 3, 2, n_f) = A * D;
  m.G(2, 2) = 1.0;
  m.G.block(2, 3, 1, n_f) = modes.Phi_psi;
  m.velocity = m.G * qd;
  const double w = qd(2);
  const Vec2 pd = D * qd_f;
  m.convective.head<2>() = A * (-w * w * p + 2 * w * I_tilde() * pd + s.c);
  m.convective(2) = 0.0;
  return m;
}

MatX StiffenedFfrfBody::own_mass(const VecX& q) const {
  const MatX L = acceleration_map(q);
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
  const MatX L = acceleration_map(q);
  VecX field = -acceleration_bias(q, qd);  // the inertia of the bias, with gravity below
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
