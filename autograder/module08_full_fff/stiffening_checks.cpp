// The module 8 checks of the geometric stiffening declared in stiffening_checks.hpp.

#include "stiffening_checks.hpp"

#include <functional>

namespace fmbd::testing::m08 {

namespace {

VecX motion_at(const VecX& q0, const VecX& v, const VecX& a, double t) { return q0 + v * t + 0.5 * t * t * a; }

/// Richardson-extrapolated central differences at t = 0 of f: R -> R^n.
VecX first_rate(const std::function<VecX(double)>& f, double h) {
  const VecX d1 = (f(h) - f(-h)) / (2 * h);
  const VecX d2 = (f(h / 2) - f(-h / 2)) / h;
  return (4 * d2 - d1) / 3;
}
VecX second_rate(const std::function<VecX(double)>& f, double h) {
  const VecX f0 = f(0.0);
  const VecX d1 = (f(h) - 2 * f0 + f(-h)) / (h * h);
  const VecX d2 = (f(h / 2) - 2 * f0 + f(-h / 2)) / (h * h / 4);
  return (4 * d2 - d1) / 3;
}

/// (r, phi) of the node at x_bar + Phi_t q_f + f(q_f), frame j turned by theta; with `frozen`,
/// f stays at *frozen (a constant offset in frame j: it turns with the frame, but q_f does not
/// move it).
VecX stiffened_pose(const NodeModes& node, const Chain& chain, const VecX& q, const Vec2* frozen = nullptr) {
  const VecX q_f = elastic_part(q);
  const Vec2 f = frozen ? *frozen : chain_shortening(chain, q_f);
  const Vec2 r = q.head<2>() + rot(q(2)) * (node.x_bar + node.Phi_t * q_f + f);
  return Vec3(r.x(), r.y(), q(2) + (node.Phi_psi * q_f)(0));
}

VecX to_frame_j(double theta, const VecX& global) {
  Vec3 local = global;
  local.head<2>() = rot(theta).transpose() * global.head<2>();
  return local;
}

Chain parent_part(const Chain& chain) {
  return Chain{{chain.H.begin(), chain.H.end() - 1}, {chain.t.begin(), chain.t.end() - 1}};
}
Chain element_part(const Chain& chain) { return Chain{{chain.H.back()}, {chain.t.back()}}; }

VecX shortening_entries(const MatX& J, const Vec2& c) {
  VecX v(J.size() + 2);
  v << flat(J), c;
  return v;
}

}  // namespace

Chain random_chain(Random& rnd, int elements, int n_f) {
  Chain chain;
  for (int e = 0; e < elements; ++e) {
    const MatX B = MatX::NullaryExpr(4, n_f, [&] { return rnd.uniform(-1, 1); });
    chain.H.push_back(B.transpose() * B);
    const double angle = rnd.uniform(-kPi, kPi);
    chain.t.push_back(Vec2(std::cos(angle), std::sin(angle)));
  }
  return chain;
}

Vec2 chain_shortening(const Chain& chain, const VecX& q_f) {
  Vec2 f = Vec2::Zero();
  for (std::size_t e = 0; e < chain.H.size(); ++e) f -= 0.5 * q_f.dot(chain.H[e] * q_f) * chain.t[e];
  return f;
}

NodeShortening chained(const Chain& chain, const VecX& q_f, const VecX& q_f_dot) {
  NodeShortening s;
  s.J = MatX::Zero(2, q_f.size());
  for (std::size_t e = 0; e < chain.H.size(); ++e)
    s = shortening_across_element(s, chain.H[e], chain.t[e], q_f, q_f_dot);
  return s;
}

NodeShortening fd_shortening(const Chain& chain, const VecX& q_f, const VecX& q_f_dot) {
  NodeShortening s;
  s.f = chain_shortening(chain, q_f);
  s.J = MatX(2, q_f.size());
  for (Eigen::Index i = 0; i < q_f.size(); ++i)
    s.J.col(i) = first_rate([&](double t) { return VecX(chain_shortening(chain, q_f + t * VecX::Unit(q_f.size(), i))); },
                            1e-3);
  s.c = second_rate([&](double t) { return VecX(chain_shortening(chain, q_f + t * q_f_dot)); }, 1e-3);
  return s;
}

std::string shortening_hint(const NodeShortening& got, const Chain& chain, const VecX& q_f, const VecX& q_f_dot) {
  if (got.J.rows() != 2 || got.J.cols() != q_f.size()) return "J_k is 2 x n_f: d f_k / d q_f";
  const NodeShortening parent = fd_shortening(parent_part(chain), q_f, q_f_dot);
  const NodeShortening own = fd_shortening(element_part(chain), q_f, q_f_dot);
  const VecX expected = shortening_entries(parent.J + own.J, parent.c + own.c);
  const VecX actual = shortening_entries(got.J, got.c);
  auto with = [&](const MatX& J, const Vec2& c) { return shortening_entries(J, c); };
  return diagnose(actual, expected,
                  {{"your J_k leaves out the parent's J: the foreshortening adds up from the anchor",
                    with(own.J, parent.c + own.c)},
                   {"your J_k has half the derivative of the element's shortening: differentiate the "
                    "quadratic form once more carefully",
                    with(parent.J + 0.5 * own.J, parent.c + own.c)},
                   {"your J_k has the element's term with the wrong sign: the node moves back along t_e",
                    with(parent.J - own.J, parent.c + own.c)},
                   {"your c_k leaves out the element's term: the shortening's second derivative has a "
                    "part in q_f_dot alone",
                    with(parent.J + own.J, parent.c)},
                   {"your c_k has half the element's term", with(parent.J + own.J, parent.c + 0.5 * own.c)},
                   {"your c_k has twice the element's term", with(parent.J + own.J, parent.c + 2 * own.c)},
                   {"your c_k leaves out the parent's c", with(parent.J + own.J, own.c)}},
                  "compare with README section 6; ./workbook hint M08T7 opens the next hint");
}

Vec3 fd_stiffened_acceleration(const NodeModes& node, const Chain& chain, const VecX& q0, const VecX& v,
                               const VecX& a) {
  return to_frame_j(q0(2), second_rate([&](double t) { return stiffened_pose(node, chain, motion_at(q0, v, a, t)); }, 2e-3));
}

MatX fd_stiffened_map(const NodeModes& node, const Chain& chain, const VecX& q) {
  MatX L(3, q.size());
  const VecX zero = VecX::Zero(q.size());
  for (Eigen::Index i = 0; i < q.size(); ++i)
    L.col(i) = to_frame_j(q(2), first_rate([&](double t) {
                          return stiffened_pose(node, chain, motion_at(q, VecX::Unit(q.size(), i), zero, t));
                        },
                                         1e-3));
  return L;
}

std::string stiffened_rows_hint(const MatX& L, const Vec3& b, const MatX& L_before, const Vec3& b_before,
                                const NodeModes& node, const Chain& chain, const VecX& q, const VecX& qd,
                                const NodeShortening& s) {
  const MatX L_expected = fd_stiffened_map(node, chain, q);
  if (L.rows() != 3 || L.cols() != L_expected.cols()) return "L_k keeps its size 3 x (3 + n_f)";
  const Eigen::Index n_f = L.cols() - 3;
  const VecX rest = VecX::Zero(q.size());
  const Vec3 b_expected = fd_stiffened_acceleration(node, chain, q, qd, rest);
  // The parts of b's change, each by finite differences: the spin on the frozen offset f_k, c_k,
  // and what remains (the spin on the foreshortening's velocity).
  const Vec2 f0 = chain_shortening(chain, elastic_part(q));
  const Vec3 frozen = to_frame_j(
      q(2), second_rate([&](double t) { return stiffened_pose(node, chain, motion_at(q, qd, rest, t), &f0); }, 2e-3));
  const Vec3 centripetal = frozen - b_before;
  const Vec3 c3(s.c.x(), s.c.y(), 0.0);
  const Vec3 coriolis = b_expected - b_before - centripetal - c3;
  auto rows = [](const MatX& M, const Vec3& v) {
    VecX e(M.size() + 3);
    e << flat(M), v;
    return e;
  };
  MatX no_J = L_expected;
  no_J.block(0, 3, 2, n_f) -= s.J;
  MatX theta_unchanged = L_expected;
  theta_unchanged.col(2) = L_before.col(2);
  const VecX right_L_with = rows(L_expected, b_expected);
  auto with_b = [&](const Vec3& v) { return rows(L_expected, v); };
  return diagnose(
      rows(L, b), right_L_with,
      {{"your add_shortening_rows adds nothing: the node's position now has f_k in it", rows(L_before, b_before)},
       {"your L_k misses J_k in the q_f columns: f_k moves with q_f", rows(no_J, b_expected)},
       {"your theta column misses f_k: theta_ddot turns the whole arm, foreshortening included",
        rows(theta_unchanged, b_expected)},
       {"your b_k gets nothing but c_k: the spin also acts on f_k and on its velocity, as on the arm in "
        "section 1",
        with_b(b_before + c3)},
       {"your b_k misses c_k", with_b(b_expected - c3)},
       {"your b_k misses the centripetal term of f_k: the spin pulls on the whole arm, foreshortening "
        "included",
        with_b(b_expected - centripetal)},
       {"your centripetal term of f_k has the wrong sign", with_b(b_expected - 2 * centripetal)},
       {"your b_k misses the Coriolis term of the foreshortening's velocity (J_k q_f_dot)",
        with_b(b_expected - coriolis)},
       {"your Coriolis term of the foreshortening's velocity lacks its factor 2", with_b(b_expected - 0.5 * coriolis)}},
      "compare with README sections 1 and 6; ./workbook hint M08T8 opens the next hint");
}

MatX spin_stiffness(const DeformableBody& body, const FlexibleBodyData& data, double Omega) {
  const int n_f = data.num_modes();
  auto force = [&](const VecX& q_f) -> VecX {
    VecX q = VecX::Zero(3 + n_f), qd = VecX::Zero(3 + n_f), qdd = VecX::Zero(3 + n_f);
    q.head<2>() = -data.nodes[0].x_bar;  // the root node at the origin, theta = 0
    q.tail(n_f) = q_f;
    qd.head<2>() = Omega * Vec2(-q(1), q(0));
    qd(2) = Omega;
    qdd.head<2>() = -Omega * Omega * q.head<2>();
    return (body.body_forces(q, qd, Vec2::Zero()) - body.mass_matrix(q) * qdd).tail(n_f);
  };
  MatX K(n_f, n_f);
  const double h = 1e-5;
  for (int i = 0; i < n_f; ++i) {
    const VecX e = h * VecX::Unit(n_f, i);
    K.col(i) = -(force(e) - force(-e)) / (2 * h);
  }
  return K;
}

}  // namespace fmbd::testing::m08
