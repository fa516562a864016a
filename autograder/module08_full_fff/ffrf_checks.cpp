// The module 8 checks declared in ffrf_checks.hpp (documented there), compiled once for all the
// module's test files. Helpers used only here, the node pose written out among them, are in the
// anonymous namespace.

#include "ffrf_checks.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace fmbd::testing::m08 {

namespace {

Mat2 tilde() {
  Mat2 T;
  T << 0.0, -1.0, 1.0, 0.0;
  return T;
}

/// q(t) = q0 + v t + a t^2 / 2.
VecX along(const VecX& q0, const VecX& v, const VecX& a, double t) { return q0 + v * t + 0.5 * t * t * a; }

/// (r_k, phi_k) = (R + A(theta) (x_bar + Phi_t q_f), theta + Phi_psi q_f).
Vec3 pose(const NodeModes& node, const VecX& q) {
  const VecX q_f = elastic_part(q);
  const Vec2 d = node.x_bar + node.Phi_t * q_f;
  const Vec2 r = q.head<2>() + rot(q(2)) * d;
  return Vec3(r.x(), r.y(), q(2) + (node.Phi_psi * q_f)(0));
}

/// Central differences with Richardson extrapolation (error O(h^4)) of f: R -> R^3 at t = 0.
Vec3 first_derivative(const std::function<Vec3(double)>& f, double h = 1e-3) {
  const Vec3 d1 = (f(h) - f(-h)) / (2 * h);
  const Vec3 d2 = (f(h / 2) - f(-h / 2)) / h;
  return (4 * d2 - d1) / 3;
}

Vec3 second_derivative(const std::function<Vec3(double)>& f, double h = 2e-3) {
  const Vec3 f0 = f(0.0);
  const Vec3 d1 = (f(h) - 2 * f0 + f(-h)) / (h * h);
  const Vec3 d2 = (f(h / 2) - 2 * f0 + f(-h / 2)) / (h * h / 4);
  return (4 * d2 - d1) / 3;
}

/// Global pose rates (r_dot, phi_dot) turned into frame j: (A^T r_dot, phi_dot).
Vec3 in_frame(double theta, const Vec3& global) {
  const Vec2 local = rot(theta).transpose() * global.head<2>();
  return Vec3(local.x(), local.y(), global(2));
}

/// W(q) with w = W(q) q_dot, from nodal_velocities column by column.
MatX velocity_map(const FlexibleBodyData& data, const VecX& q) {
  MatX W(3 * data.nodes.size(), q.size());
  for (Eigen::Index i = 0; i < q.size(); ++i) W.col(i) = nodal_velocities(data, q, VecX::Unit(q.size(), i));
  return W;
}

/// The rigid-body columns about the frame origin (the centroid of the body's data): node k gets
/// (1, 0, 0), (0, 1, 0), (-y_k, x_k, 1).
MatX rigid_columns(const FlexibleBodyData& data) {
  MatX R = MatX::Zero(3 * data.nodes.size(), 3);
  for (std::size_t k = 0; k < data.nodes.size(); ++k) {
    const Vec2 x = data.nodes[k].x_bar;
    R(3 * k, 0) = 1.0;
    R(3 * k + 1, 1) = 1.0;
    R(3 * k, 2) = -x.y();
    R(3 * k + 1, 2) = x.x();
    R(3 * k + 2, 2) = 1.0;
  }
  return R;
}

/// T(theta) = blockdiag(A^T, 1, I): at q_f = 0, L = Phi T(theta).
MatX frame_turn(double theta, int n_f) {
  MatX T = MatX::Identity(3 + n_f, 3 + n_f);
  T.block<2, 2>(0, 0) = rot(theta).transpose();
  return T;
}

/// blockdiag(A, A, ..., with 1 on psi): frame-j nodal vectors to global ones.
MatX stacked_rotation(int nodes, double theta) {
  MatX B = MatX::Identity(3 * nodes, 3 * nodes);
  for (int k = 0; k < nodes; ++k) B.block<2, 2>(3 * k, 3 * k) = rot(theta);
  return B;
}

/// The stacked velocity bias b written out, with a centripetal sign and a
/// Coriolis factor to build the typical wrong answers (right: -1 and 2).
VecX bias_variant(const FlexibleBodyData& data, const VecX& q, const VecX& qd, double centripetal = -1.0,
                  double coriolis = 2.0) {
  const double w = qd(2);
  VecX b = VecX::Zero(3 * data.nodes.size());
  for (std::size_t k = 0; k < data.nodes.size(); ++k) {
    const NodeModes& n = data.nodes[k];
    b.segment<2>(3 * k) = centripetal * w * w * (n.x_bar + n.Phi_t * elastic_part(q)) +
                          coriolis * w * tilde() * (n.Phi_t * elastic_part(qd));
  }
  return b;
}

/// Gravity on the nodes in the nodal form, L^T M_FE f with the field f = (a, 0) at every node.
VecX field_force(const FlexibleBodyData& data, const VecX& q, const Vec2& a) {
  VecX f = VecX::Zero(3 * data.nodes.size());
  for (std::size_t k = 0; k < data.nodes.size(); ++k) f.segment<2>(3 * k) = a;
  return velocity_map(data, q).transpose() * (data.matrices.M * f);
}

}  // namespace

// ---- small helpers ------------------------------------------------------------------------

std::string sci(double x) {
  std::ostringstream s;
  s.precision(3);
  s << std::scientific << x;
  return s.str();
}

// ---- the node pose, written out ------------------------------------------------------------

Vec3 fd_acceleration(const NodeModes& node, const VecX& q0, const VecX& v, const VecX& a) {
  const Vec3 global = second_derivative([&](double t) { return pose(node, along(q0, v, a, t)); });
  return in_frame(q0(2), global);
}

Vec3 fd_velocity(const NodeModes& node, const VecX& q0, const VecX& v) {
  const VecX zero = VecX::Zero(q0.size());
  const Vec3 global = first_derivative([&](double t) { return pose(node, along(q0, v, zero, t)); });
  return in_frame(q0(2), global);
}

MatX fd_map(const NodeModes& node, const VecX& q) {
  MatX L(3, q.size());
  for (Eigen::Index i = 0; i < q.size(); ++i) L.col(i) = fd_velocity(node, q, VecX::Unit(q.size(), i));
  return L;
}

MatX fd_stacked_map(const FlexibleBodyData& data, const VecX& q) {
  MatX W(3 * data.nodes.size(), q.size());
  for (std::size_t k = 0; k < data.nodes.size(); ++k) W.middleRows(3 * k, 3) = fd_map(data.nodes[k], q);
  return W;
}

VecX nodal_velocities(const FlexibleBodyData& data, const VecX& q, const VecX& qd) {
  const VecX q_f = elastic_part(q), qd_f = elastic_part(qd);
  const Mat2 At = rot(q(2)).transpose();
  VecX w(3 * data.nodes.size());
  for (std::size_t k = 0; k < data.nodes.size(); ++k) {
    const NodeModes& n = data.nodes[k];
    const Vec2 d = n.x_bar + n.Phi_t * q_f;
    w.segment<2>(3 * k) = At * qd.head<2>() + qd(2) * tilde() * d + n.Phi_t * qd_f;
    w(3 * k + 2) = qd(2) + (n.Phi_psi * qd_f)(0);
  }
  return w;
}

MatX mass_oracle(const FlexibleBodyData& data, const VecX& q) {
  const MatX W = velocity_map(data, q);
  return W.transpose() * data.matrices.M * W;
}

VecX lagrangian_qv(const FlexibleBodyData& data, const VecX& q, const VecX& qd, double h) {
  const Eigen::Index n = q.size();
  VecX grad(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    VecX qp = q, qm = q;
    qp(i) += h;
    qm(i) -= h;
    grad(i) = 0.5 * (qd.dot(mass_oracle(data, qp) * qd) - qd.dot(mass_oracle(data, qm) * qd)) / (2 * h);
  }
  const MatX M_dot = (mass_oracle(data, q + h * qd) - mass_oracle(data, q - h * qd)) / (2 * h);
  return grad - M_dot * qd;
}

VecX stacked_positions(const FlexibleBodyData& data) {
  VecX X = VecX::Zero(3 * data.nodes.size());
  for (std::size_t k = 0; k < data.nodes.size(); ++k) X.segment<2>(3 * k) = data.nodes[k].x_bar;
  return X;
}

MatX translations(int nodes) {
  MatX T = MatX::Zero(3 * nodes, 2);
  for (int k = 0; k < nodes; ++k) {
    T(3 * k, 0) = 1.0;
    T(3 * k + 1, 1) = 1.0;
  }
  return T;
}

MatX reduced_mass(const FlexibleBodyData& data) {
  MatX Phi(3 * data.nodes.size(), 3 + data.num_modes());
  Phi << rigid_columns(data), data.Phi_f;
  return Phi.transpose() * data.matrices.M * Phi;
}

MatX rotated_reduced_mass(const FlexibleBodyData& data, double theta) {
  const MatX T = frame_turn(theta, data.num_modes());
  return T.transpose() * reduced_mass(data) * T;
}

std::string mass_hint(const MatX& got, const MatX& expected, const FlexibleBodyData& data, const VecX& q) {
  const int n = 3 + data.num_modes();
  if (got.rows() != n || got.cols() != n) return "M(q) is (3 + n_f) x (3 + n_f): L^T M_FE L with L 3N x (3 + n_f)";
  const MatX W = velocity_map(data, q);
  const MatX Wg = stacked_rotation(static_cast<int>(data.nodes.size()), q(2)) * W;
  return diagnose(flat(got), flat(expected),
                  {{"mass matrix is L^T M_FE L, not M_bar: it depends on q_f (the deformed arm in column 2)",
                    flat(data.basis.M_bar)},
                   {"mass matrix is L^T M_FE L, not M_bar: it depends on q_f (the deformed arm in column 2)",
                    flat(rotated_reduced_mass(data, q(2)))},
                   {"mass matrix in frame j: L^T M_FE L with L_k = A^T G_k, not G^T M_FE G",
                    flat(MatX(Wg.transpose() * data.matrices.M * Wg))},
                   {"mass matrix is L^T M_FE L (M_FE in the middle), not L^T L", flat(MatX(W.transpose() * W))}},
                  "M(q) = L^T M_FE L with L stacked from node_acceleration_map over all nodes in the DOF order of "
                  "the FE model: 1/2 q_dot^T M q_dot is the FE kinetic energy of the nodal velocities",
                  Tolerance{1e-7, 1e-7});
}

std::string qv_hint(const VecX& got, const VecX& expected, const FlexibleBodyData& data, const VecX& q,
                    const VecX& qd) {
  const MatX W = velocity_map(data, q);
  const MatX& M = data.matrices.M;
  const VecX right = -W.transpose() * (M * bias_variant(data, q, qd));
  return diagnose(got, expected,
                  {{"Q_v sign: yours is the opposite of the right one (the inertia forces move to the right-hand side)", VecX(-expected)},
                   {"Q_v sign: yours is the opposite of the right one (the inertia forces move to the right-hand side)", VecX(-right)},
                   {"Coriolis factor 2 missing in your b: its Coriolis term is half the right one",
                    VecX(-W.transpose() * (M * bias_variant(data, q, qd, -1.0, 1.0)))},
                   {"centripetal sign in your b: its centripetal term points away from the frame origin",
                    VecX(-W.transpose() * (M * bias_variant(data, q, qd, 1.0, 2.0)))},
                   {"Q_v = -L^T M_FE b: M_FE in the middle, not -L^T b", VecX(-W.transpose() * bias_variant(data, q, qd))}},
                  "Q_v = -L^T M_FE b with L and b stacked from node_acceleration_map and node_acceleration_bias "
                  "over all nodes",
                  Tolerance{1e-6, 1e-6});
}

VecX elastic_rows(const FlexibleBodyData& data, const VecX& q) {
  VecX e = VecX::Zero(q.size());
  e.tail(data.num_modes()) = data.K_ff * elastic_part(q);
  return e;
}

std::string rest_force_hint(const VecX& got, const VecX& expected, const FlexibleBodyData& data, const VecX& q,
                            const Vec2& g) {
  const VecX elastic = elastic_rows(data, q), gravity = expected + elastic;
  return diagnose(got, expected,
                  {{"gravity as in module 7: flexible_gravity_force, the gradient of -g^T (m R + A S_f q_f); not "
                    "the FE load L^T M_FE (A^T g, 0)",
                    VecX(field_force(data, q, g) - elastic)},
                   {"elastic force -K_ff q_f: it pulls q_f back to zero", VecX(gravity + elastic)},
                   {"elastic force -K_ff q_f missing on the elastic rows", gravity},
                   {"gravity missing: module 7's flexible_gravity_force", VecX(-elastic)}},
                  "at rest the body forces are module 7's: flexible_gravity_force and the elastic force "
                  "-K_bar q = -(0, 0, 0, K_ff q_f)",
                  Tolerance{1e-6, 1e-6});
}

// ---- energy and momentum of one flexible body from its nodes -------------------------------

double fe_kinetic_energy(const FlexibleBodyData& data, const VecX& q, const VecX& qd) {
  const VecX w = nodal_velocities(data, q, qd);
  return 0.5 * w.dot(data.matrices.M * w);
}

double fe_potential_energy(const FlexibleBodyData& data, const VecX& q, const Vec2& g) {
  const int N = static_cast<int>(data.nodes.size());
  VecX u = VecX::Zero(3 * N);
  for (int k = 0; k < N; ++k) {
    u.segment<2>(3 * k) = data.nodes[k].Phi_t * elastic_part(q);
    u(3 * k + 2) = (data.nodes[k].Phi_psi * elastic_part(q))(0);
  }
  const MatX T = translations(N);
  const double m = (T.col(0).transpose() * data.matrices.M * T.col(0))(0);
  const Vec2 moment = m * q.head<2>() + rot(q(2)) * (T.transpose() * data.matrices.M * (stacked_positions(data) + u));
  return -g.dot(moment) + 0.5 * u.dot(data.matrices.K * u);
}

double lumped_angular_momentum(const FlexibleBodyData& data, const VecX& q, const VecX& qd) {
  const MatX& M = data.matrices.M;
  double m = 0;
  Vec2 first = Vec2::Zero();
  std::vector<Vec2> r(data.nodes.size()), v(data.nodes.size());
  std::vector<double> phi_dot(data.nodes.size());
  for (std::size_t k = 0; k < data.nodes.size(); ++k) {
    const Vec3 p = pose(data.nodes[k], q);
    const VecX zero = VecX::Zero(q.size());
    const Vec3 pd = first_derivative([&](double t) { return pose(data.nodes[k], along(q, qd, zero, t)); });
    r[k] = p.head<2>();
    v[k] = pd.head<2>();
    phi_dot[k] = pd(2);
    m += M(3 * k, 3 * k);
    first += M(3 * k, 3 * k) * r[k];
  }
  const Vec2 rc = first / m;
  double H = 0;
  for (std::size_t k = 0; k < data.nodes.size(); ++k) {
    const double mk = M(3 * k, 3 * k), Jk = M(3 * k + 2, 3 * k + 2);
    const Vec2 d = r[k] - rc;
    H += mk * (d.x() * v[k].y() - d.y() * v[k].x()) + Jk * phi_dot[k];
  }
  return H;
}

bool isotropic_lumped(const MatX& M) {
  const double scale = max_abs(M);
  if (max_abs(MatX(M - MatX(M.diagonal().asDiagonal()))) > 1e-14 * scale) return false;
  for (Eigen::Index k = 0; k + 2 < M.rows(); k += 3)
    if (std::abs(M(k, k) - M(k + 1, k + 1)) > 1e-14 * scale) return false;
  return true;
}

// ---- random data ---------------------------------------------------------------------------

NodeModes random_node(Random& rnd, int n_f) {
  NodeModes n;
  n.x_bar = rnd.vec2(-1.5, 1.5);
  n.Phi_t = MatX(2, n_f);
  n.Phi_psi = MatX(1, n_f);
  for (int c = 0; c < n_f; ++c) {
    n.Phi_t(0, c) = rnd.uniform(-1, 1);
    n.Phi_t(1, c) = rnd.uniform(-1, 1);
    n.Phi_psi(0, c) = rnd.uniform(-2, 2);
  }
  return n;
}

VecX random_q(Random& rnd, int n_f, double f) {
  VecX q(3 + n_f);
  q.head<2>() = rnd.vec2(-2, 2);
  q(2) = rnd.uniform(-kPi, kPi);
  q.tail(n_f) = rnd.vector(n_f, -f, f);
  return q;
}

double modal_scale(const FlexibleBodyData& data, double fraction) {
  double size = 0;
  for (const NodeModes& n : data.nodes) size = std::max(size, n.x_bar.norm());
  const double phi = std::max(max_abs(data.Phi_f), 1e-12);
  return fraction * size / phi;
}

// ---- bodies ----------------------------------------------------------------------------------

FeModel l_frame(const Vec2& start) {
  FeModel fe;
  const Section a = square_section(2e9, 1200.0, 0.02), b = square_section(2e9, 1200.0, 0.015);
  int previous = fe.add_node(start);
  for (int e = 1; e <= 6; ++e) {
    const int next = fe.add_node(start + Vec2(0.9 * e / 6, 0.0));
    fe.add_element(previous, next, a);
    previous = next;
  }
  for (int e = 1; e <= 4; ++e) {
    const int next = fe.add_node(start + Vec2(0.9, 0.6 * e / 4));
    fe.add_element(previous, next, b);
    previous = next;
  }
  return fe;
}

std::shared_ptr<const FlexibleBodyData> shared(FlexibleBodyData d) {
  return std::make_shared<const FlexibleBodyData>(std::move(d));
}

// ---- hints -----------------------------------------------------------------------------------

std::string map_hint(const MatX& got, const MatX& expected, const NodeModes& node, const VecX& q) {
  if (got.rows() != 3 || got.cols() != expected.cols())
    return "L_k is 3 x (3 + n_f): rows (u_x, u_y, psi) of the node, columns (R_x, R_y, theta, q_f)";
  const Mat2 A = rot(q(2));
  const Vec2 d = node.x_bar + node.Phi_t * elastic_part(q);
  auto with_R = [&](const Mat2& B) {
    MatX L = expected;
    L.block<2, 2>(0, 0) = B;
    return flat(L);
  };
  auto with_arm = [&](const Vec2& c) {
    MatX L = expected;
    L.block<2, 1>(0, 2) = c;
    return flat(L);
  };
  MatX module7 = expected;
  module7.block<2, 2>(0, 0).setIdentity();
  module7.block<2, 1>(0, 2) = A * tilde() * d;
  module7.block(0, 3, 2, expected.cols() - 3) = A * node.Phi_t;
  MatX a_phi = expected;
  a_phi.block(0, 3, 2, expected.cols() - 3) = A * node.Phi_t;
  return diagnose(
      flat(got), flat(expected),
      {{with_formula("your R columns of L_k give R_ddot in global axes, not in frame j (turned by the "
                     "frame's angle the wrong way)",
                     "columns 0-1 of L_k are A^T, not A"),
        with_R(A)},
       {with_formula("your R columns of L_k give R_ddot in global axes, not in frame j (not turned at all)",
                     "columns 0-1 of L_k are A^T, not I"),
        with_R(Mat2::Identity())},
       {with_formula("your theta column turns the undeformed node, not the deformed arm",
                     "I~ (x_bar + u_bar), u_bar = Phi_t q_f"),
        with_arm(tilde() * node.x_bar)},
       {with_formula("your theta column is the arm itself, not the arm turned a quarter turn",
                     "theta_ddot turns the arm: I~ (x_bar + u_bar)"),
        with_arm(d)},
       {with_formula("your theta column turns the arm the wrong way (a quarter turn counterclockwise is right)",
                     "I~ = [[0, -1], [1, 0]]"),
        with_arm(-tilde() * d)},
       {with_formula("not seen from frame j: your L_k is module 7's G_k in global axes",
                     "L_k = A^T G_k in the translation rows: columns 2.. without A"),
        flat(module7)},
       {with_formula("not seen from frame j: your q_f columns of L_k are turned into global axes",
                     "the q_f columns of L_k are Phi_t,k, not A Phi_t,k"),
        flat(a_phi)}},
      with_formula("your L_k: the node's absolute acceleration in frame j is L_k q_ddot + b_k "
                   "(README section 1)",
                   "L_k = [A^T, I~ (x_bar_k + u_bar_k), Phi_t,k; 0 0, 1, Phi_psi,k]"),
      Tolerance{1e-6, 1e-6});
}

std::string bias_hint(const Vec3& got, const Vec3& expected, const NodeModes& node, const VecX& q, const VecX& qd) {
  const double w = qd(2);
  const Vec2 d = node.x_bar + node.Phi_t * elastic_part(q);
  const Vec2 centripetal = -w * w * d;
  const Vec2 coriolis = expected.head<2>() - centripetal;
  auto v3 = [](const Vec2& a) { return VecX(Vec3(a.x(), a.y(), 0.0)); };
  const Mat2 A = rot(q(2));
  return diagnose(
      VecX(got), VecX(expected),
      {{"Coriolis factor 2 missing: your Coriolis term is half the right one (the product rule gives the cross term "
        "twice)",
        v3(centripetal + 0.5 * coriolis)},
       {"Coriolis term missing: yours has none, but the elastic velocity turns with the frame", v3(centripetal)},
       {"Coriolis sign: your Coriolis term has the opposite sign", v3(centripetal - coriolis)},
       {"centripetal sign: your centripetal term points away from the frame origin", v3(-centripetal + coriolis)},
       {"centripetal term missing: yours has none, but a node on a turning frame accelerates towards its origin",
        v3(coriolis)},
       {"centripetal on the deformed arm: yours uses the undeformed x_bar, but the node turns at its deformed position",
        v3(-w * w * node.x_bar + coriolis)},
       {with_formula("not seen from frame j: your b_k is module 7's c_k in global axes", "b_k = A^T c_k"),
        v3(A * (centripetal + coriolis))}},
      with_formula("your b_k: the velocity terms of the node's absolute acceleration in frame j "
                   "(README section 1)",
                   "b_k = (-theta_dot^2 (x_bar_k + u_bar_k) + 2 theta_dot I~ Phi_t,k q_f_dot, 0)"),
      Tolerance{1e-6, 1e-6});
}

}  // namespace fmbd::testing::m08
