#pragma once
// Shared helpers of the module 7 graded tests: the node kinematics written out by hand (pose,
// Jacobian, convective acceleration), random nodes and states, finite differences in time,
// whole-model checks of C_q and gamma against finite differences of C(q, t), the rigid-body and
// translation columns of a beam, a basis that is not M-orthogonal to the rigid modes, the
// potential energy of the intuitive body written out from the FE matrices, and the static
// Ritz solution of a clamped beam in a reduced basis. The mistake catalogue's `expect:` phrases
// open the hints (Catch wraps long lines, so each phrase stays at the start of its hint).
//
// Every oracle here is independent of the student's module 7 code: plain formulas, Eigen's
// solvers, the FE matrices of module 5 and the basis of module 6 (reference stages under the
// graded module 7 targets), and module 1's C(q, t), which sees a flexible body only through the
// node pose (task T1).

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "fmbd/constraints.hpp"
#include "fmbd/fe_assembly.hpp"
#include "fmbd/fe_model.hpp"
#include "fmbd/flexible_body.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/gamma.hpp"
#include "fmbd/intuitive_flexible.hpp"
#include "fmbd/marker.hpp"
#include "fmbd/model.hpp"
#include "fmbd/reduction.hpp"
#include "grading.hpp"

namespace fmbd::testing::m07 {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kSteelE = 2.1e11;
inline constexpr double kSteelRho = 7850.0;

/// Appended to the hints of tests on whole models: the intuitive body calls intuitive_mass_matrix
/// in its constructor, and module 1 evaluates the whole node marker (pose, G_k and c_k) for C.
inline const std::string kNeedsT4 = " (needs M07T4 for the model, and C(q, t) calls all of T1-T3)";

// ---- plain planar formulas (not the student's) ------------------------------------------

/// A(phi) = [[cos, -sin], [sin, cos]], written out.
inline Mat2 rot(double phi) {
  Mat2 A;
  A << std::cos(phi), -std::sin(phi), std::sin(phi), std::cos(phi);
  return A;
}
/// I~ = [[0, -1], [1, 0]]: turns a vector by +90 degrees.
inline Mat2 tilde() {
  Mat2 T;
  T << 0.0, -1.0, 1.0, 0.0;
  return T;
}

inline double max_abs(const MatX& A) { return A.size() == 0 ? 0.0 : A.cwiseAbs().maxCoeff(); }

// ---- one node: the kinematics by hand ----------------------------------------------------

inline int modes_of(const NodeModes& node) { return static_cast<int>(node.Phi_t.cols()); }
inline VecX elastic_part(const VecX& q) { return q.tail(q.size() - 3); }

/// u_bar_k = Phi_t,k q_f (frame), psi_k = Phi_psi,k q_f.
inline Vec2 u_bar(const NodeModes& node, const VecX& q) { return node.Phi_t * elastic_part(q); }
inline double psi(const NodeModes& node, const VecX& q) { return node.Phi_psi.row(0).dot(elastic_part(q)); }

/// p_k = (R + A (x_bar + u_bar), theta + psi).
inline Vec3 pose_oracle(const NodeModes& node, const VecX& q) {
  const Vec2 r = q.head<2>() + rot(q(2)) * (node.x_bar + u_bar(node, q));
  return Vec3(r.x(), r.y(), q(2) + psi(node, q));
}

/// G_k = dp_k/dq written out; the tests check it against finite differences of pose_oracle too.
inline MatX jacobian_oracle(const NodeModes& node, const VecX& q) {
  const int n_f = modes_of(node);
  MatX G = MatX::Zero(3, 3 + n_f);
  G(0, 0) = G(1, 1) = 1.0;
  G.block<2, 1>(0, 2) = rot(q(2)) * tilde() * (node.x_bar + u_bar(node, q));
  G.block(0, 3, 2, n_f) = rot(q(2)) * node.Phi_t;
  G(2, 2) = 1.0;
  G.block(2, 3, 1, n_f) = node.Phi_psi;
  return G;
}

/// The two parts of c_k (position rows): centripetal -theta_dot^2 A (x_bar + u_bar) and
/// Coriolis 2 theta_dot A I~ Phi_t q_f_dot.
struct ConvectiveParts {
  Vec2 centripetal = Vec2::Zero();
  Vec2 coriolis = Vec2::Zero();
};
inline ConvectiveParts convective_parts(const NodeModes& node, const VecX& q, const VecX& qd) {
  const double w = qd(2);
  ConvectiveParts c;
  c.centripetal = -w * w * rot(q(2)) * (node.x_bar + u_bar(node, q));
  c.coriolis = 2.0 * w * rot(q(2)) * tilde() * (node.Phi_t * elastic_part(qd));
  return c;
}

/// A random node with n_f modes: x_bar, Phi_t and Phi_psi of order one.
inline NodeModes random_node(Random& rnd, int n_f) {
  NodeModes node;
  node.x_bar = rnd.vec2(-1.5, 1.5);
  node.Phi_t = MatX(2, n_f);
  node.Phi_psi = MatX(1, n_f);
  for (int j = 0; j < n_f; ++j) {
    node.Phi_t(0, j) = rnd.uniform(-1.0, 1.0);
    node.Phi_t(1, j) = rnd.uniform(-1.0, 1.0);
    node.Phi_psi(0, j) = rnd.uniform(-2.0, 2.0);
  }
  return node;
}

/// A random q = (R, theta, q_f): R of order one, any angle, q_f of order `elastic`.
inline VecX random_node_state(Random& rnd, int n_f, double elastic = 0.3) {
  VecX q(3 + n_f);
  q.head<2>() = rnd.vec2(-2.0, 2.0);
  q(2) = rnd.uniform(-3.0, 3.0);
  q.tail(n_f) = rnd.vector(n_f, -elastic, elastic);
  return q;
}

/// Second derivative of g at 0 by the five-point stencil (error O(h^4)).
inline VecX second_derivative(const std::function<VecX(double)>& g, double h) {
  return (-g(2 * h) + 16.0 * g(h) - 30.0 * g(0.0) + 16.0 * g(-h) - g(-2 * h)) / (12.0 * h * h);
}

// ---- whole models --------------------------------------------------------------------------

/// A state near q0: every frame moved by up to `shift` [m] and turned by up to `turn` [rad], the
/// elastic coordinates of each flexible body of order `deflection` times its length scale
/// (mass-normalised modes: amplitude about 1/sqrt(m) per unit q_f).
inline VecX random_model_state(const Model& model, const VecX& q0, Random& rnd, double shift, double turn,
                               double deflection) {
  VecX q = q0;
  for (int b = 0; b < model.num_bodies(); ++b) {
    const Body& body = model.bodies()[b];
    const int at = model.offset(BodyId{b});
    q.segment<2>(at) += rnd.vec2(-shift, shift);
    q(at + 2) += rnd.uniform(-turn, turn);
    if (body.is_flexible()) {
      double size = 0.0;
      for (int k = 0; k < body.deformable->num_nodes(); ++k) size = std::max(size, body.deformable->node_position(k).norm());
      const int n_f = body.deformable->num_modes();
      q.segment(at + 3, n_f) = rnd.vector(n_f, -1.0, 1.0) * deflection * size * std::sqrt(body.deformable->mass());
    }
  }
  return q;
}

/// Random rates: frame velocities up to `speed` [m/s], angular rates up to `spin` [rad/s],
/// elastic rates `elastic_rate` times the elastic scale of random_model_state.
inline VecX random_model_rates(const Model& model, Random& rnd, double speed, double spin, double elastic_rate) {
  VecX qd = VecX::Zero(model.num_coordinates());
  for (int b = 0; b < model.num_bodies(); ++b) {
    const Body& body = model.bodies()[b];
    const int at = model.offset(BodyId{b});
    qd.segment<2>(at) = rnd.vec2(-speed, speed);
    qd(at + 2) = rnd.uniform(-spin, spin);
    if (body.is_flexible()) {
      double size = 0.0;
      for (int k = 0; k < body.deformable->num_nodes(); ++k) size = std::max(size, body.deformable->node_position(k).norm());
      const int n_f = body.deformable->num_modes();
      qd.segment(at + 3, n_f) = rnd.vector(n_f, -1.0, 1.0) * elastic_rate * size * std::sqrt(body.deformable->mass());
    }
  }
  return qd;
}

/// The FlexibleBodyData of a flexible body of the model (the intuitive body's data).
inline const FlexibleBodyData& data_of(const Model& model, BodyId body) {
  const auto* intuitive = dynamic_cast<const IntuitiveBody*>(model.body(body).deformable.get());
  REQUIRE(intuitive != nullptr);
  return intuitive->data();
}

/// Pose of FE node `node` of flexible body `body` at the model state q, by hand.
inline Vec3 model_node_pose(const Model& model, BodyId body, int node, const VecX& q) {
  const FlexibleBodyData& d = data_of(model, body);
  return pose_oracle(d.nodes.at(node), model.body_state(q, body));
}

/// Every node point of every flexible body sits at the hand-written pose (module 1's marker of
/// the point, which C(q, t) uses): the finite differences below rely on it. False if one does not.
inline bool check_node_points(const Model& model, const VecX& q) {
  const VecX zero = VecX::Zero(q.size());
  bool all = true;
  for (int k = 0; k < static_cast<int>(model.points().size()); ++k) {
    const Point& point = model.points()[k];
    if (point.node < 0) continue;
    CAPTURE(point.name);
    const Vec3 got = point_marker(model, PointId{k}, q, zero).q;
    const Vec3 expected = model_node_pose(model, point.body, point.node, q);
    const Tolerance tol{1e-12, 1e-12};
    all = all && compare(got, expected, tol).ok;
    CHECK_CLOSE(got, expected, tol,
                "node_pose (M07T1) of a node point: (R + A (x_bar + u_bar), theta + psi); fix it before C_q and "
                "gamma" + kNeedsT4);
  }
  return all;
}

/// Is row `r` of constraint c the angle row of a fixed joint or translational joint (uses phi_k)?
inline bool is_angle_row(const Constraint& c, int r) {
  if (std::holds_alternative<Fixed>(c.type)) return r == 2;
  if (std::holds_alternative<Translational>(c.type)) return r == 1;
  return std::holds_alternative<AbsoluteAngleDriver>(c.type) || std::holds_alternative<RelativeAngleDriver>(c.type);
}

/// C_q of the model at (q, t) against central differences of module 1's C(q, t), checked
/// block by block: rows of each constraint, and for each flexible body its frame translation,
/// its angle and its elastic columns, each with the hint of the slip that breaks it.
inline void check_constraint_jacobian(const Model& model, const VecX& q, double t, const std::string& label) {
  CAPTURE(label, t);
  if (!check_node_points(model, q)) return;
  const MatX fd = finite_difference_jacobian([&](const VecX& x) { return constraints(model, x, t); }, q, 1e-6);
  const MatX Cq = constraint_jacobian(model, q, t);
  {
    INFO("hint: C_q of the whole model is m x n" << kNeedsT4);
    REQUIRE(Cq.rows() == fd.rows());
    REQUIRE(Cq.cols() == fd.cols());
  }
  const Tolerance tol{1e-7 * std::max(1.0, max_abs(fd)), 1e-6};
  for (const Constraint& c : model.constraints()) {
    CAPTURE(c.name);
    for (int b = 0; b < model.num_bodies(); ++b) {
      const Body& body = model.bodies()[b];
      const int at = model.offset(BodyId{b});
      CAPTURE(body.name);
      if (!body.is_flexible()) {
        CHECK_CLOSE(MatX(Cq.block(c.first_row, at, c.rows, 3)), MatX(fd.block(c.first_row, at, c.rows, 3)), tol,
                    "C_q columns of a rigid body in a model with a flexible body: check the flexible body's node "
                    "pose and Jacobian (the rigid kernels are module 1's)" + kNeedsT4);
        continue;
      }
      const int n_f = body.num_coordinates() - 3;
      CHECK_CLOSE(MatX(Cq.block(c.first_row, at, c.rows, 2)), MatX(fd.block(c.first_row, at, c.rows, 2)), tol,
                  "columns 0-1 of G_k are [I_2; 0 0]: the node moves with R" + kNeedsT4);
      CHECK_CLOSE(MatX(Cq.block(c.first_row, at + 2, c.rows, 1)), MatX(fd.block(c.first_row, at + 2, c.rows, 1)),
                  tol,
                  "A I~ (x_bar + u_bar) in column 2 of G_k: the arm is the deformed position; and 1 in the angle "
                  "row" + kNeedsT4);
      for (int r = 0; r < c.rows; ++r) {
        CAPTURE(r);
        const std::string hint =
            is_angle_row(c, r)
                ? "Phi_psi row of the angle missing: a clamped node turns with psi, row 2 of G_k is (0, 0, 1, "
                  "Phi_psi)" + kNeedsT4
                : "A Phi_t columns missing or without A: the elastic columns of G_k are A Phi_t (u_bar is in the "
                  "frame)" + kNeedsT4;
        CHECK_CLOSE(MatX(Cq.block(c.first_row + r, at + 3, 1, n_f)), MatX(fd.block(c.first_row + r, at + 3, 1, n_f)),
                    tol, hint);
      }
    }
  }
}

/// gamma of the model at (q, q_dot, t) against the second time derivative of C along the
/// straight motion q(s) = q + s q_dot at time t + s (q_ddot = 0, so gamma = -d2C/ds2, driver
/// terms C_tt included).
inline void check_gamma(const Model& model, const VecX& q, const VecX& qd, double t, const std::string& label) {
  CAPTURE(label, t);
  if (!check_node_points(model, q)) return;
  const double rate = std::max(1.0, qd.cwiseAbs().maxCoeff());
  const double h = 2e-3 / rate;
  const VecX expected =
      -second_derivative([&](double s) { return VecX(constraints(model, VecX(q + s * qd), t + s)); }, h);
  const VecX gamma = constraint_gamma(model, q, qd, t);
  {
    INFO("hint: gamma has one entry per constraint row" << kNeedsT4);
    REQUIRE(gamma.size() == expected.size());
  }
  const Tolerance tol{1e-7 * std::max(1.0, expected.cwiseAbs().maxCoeff()), 1e-6};
  for (const Constraint& c : model.constraints()) {
    CAPTURE(c.name);
    CHECK_CLOSE(VecX(gamma.segment(c.first_row, c.rows)), VecX(expected.segment(c.first_row, c.rows)), tol,
                "convective acceleration c_k of the flexible nodes: centripetal term sign, Coriolis factor 2 and A "
                "I~ (c_k = (-theta_dot^2 A (x_bar + u_bar) + 2 theta_dot A I~ Phi_t q_f_dot, 0)); the marker "
                "velocity G_k q_dot needs node_jacobian (M07T2) too" + kNeedsT4);
  }
}

// ---- beams and bases ------------------------------------------------------------------------

inline Section steel(double side) { return square_section(kSteelE, kSteelRho, side); }

/// The n x 3 rigid-body columns about point p: node k gets (1, 0, 0), (0, 1, 0), (-(y_k - p_y), x_k - p_x, 1).
inline MatX rigid_columns(const FeModel& fe, const Vec2& p) {
  MatX Phi = MatX::Zero(fe.num_dofs(), 3);
  for (int k = 0; k < fe.num_nodes(); ++k) {
    const Vec2 d = fe.nodes()[k] - p;
    Phi(3 * k, 0) = 1.0;
    Phi(3 * k + 1, 1) = 1.0;
    Phi(3 * k, 2) = -d.y();
    Phi(3 * k + 1, 2) = d.x();
    Phi(3 * k + 2, 2) = 1.0;
  }
  return Phi;
}

/// The nodal field of a uniform vector v: (v_x, v_y, 0) at every node.
inline VecX uniform_field(const FeModel& fe, const Vec2& v) {
  VecX u = VecX::Zero(fe.num_dofs());
  for (int k = 0; k < fe.num_nodes(); ++k) u.segment<2>(3 * k) = v;
  return u;
}

/// A basis that is NOT M-orthogonal to the rigid modes: rigid columns, then the static shape of a
/// tip load of the beam clamped at node 0, then its `modes` lowest cantilever modes (zero at
/// node 0, so their mean displacement, S_f, does not vanish). M_bar and K_bar filled from Phi.
inline ReducedBasis cantilever_basis(const FeModel& fe, const FeMatrices& fm, int modes) {
  const int n = fe.num_dofs(), n_i = n - 3, tip = fe.num_nodes() - 1;
  const MatX K_ii = fm.K.bottomRightCorner(n_i, n_i), M_ii = fm.M.bottomRightCorner(n_i, n_i);
  ReducedBasis b;
  b.num_rigid = 3;
  b.Phi = MatX::Zero(n, 4 + modes);
  b.Phi.leftCols(3) = rigid_columns(fe, fe.nodes()[0]);
  VecX load = VecX::Zero(n_i);
  load(3 * tip + 1 - 3) = 1.0;
  VecX shape = Eigen::LLT<MatX>(K_ii).solve(load);
  shape /= shape.cwiseAbs().maxCoeff();
  b.Phi.col(3).tail(n_i) = shape;
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatX> es(K_ii, M_ii);
  for (int j = 0; j < modes; ++j) {
    VecX mode = es.eigenvectors().col(j);
    mode /= mode.cwiseAbs().maxCoeff();
    b.Phi.col(4 + j).tail(n_i) = mode;
  }
  b.M_bar = b.Phi.transpose() * fm.M * b.Phi;
  b.K_bar = b.Phi.transpose() * fm.K * b.Phi;
  return b;
}

/// The intuitive potential written out from the FE matrices of the body's data:
///   V(q) = -g^T (m R + A S_f q_f) + 1/2 q_f^T K_ff q_f,
/// m = t_x^T M t_x, S_f = [t_x t_y]^T M Phi_f, K_ff = Phi_f^T K Phi_f.
struct Potential {
  double mass = 0.0;
  MatX S_f, K_ff;
  Vec2 g = Vec2::Zero();
  double operator()(const VecX& q) const {
    const VecX q_f = elastic_part(q);
    return -g.dot(mass * Vec2(q.head<2>()) + rot(q(2)) * (S_f * q_f)) + 0.5 * q_f.dot(K_ff * q_f);
  }
};
inline Potential potential_of(const FlexibleBodyData& d, const Vec2& g) {
  const MatX& M = d.matrices.M;
  const int n_f = static_cast<int>(d.basis.Phi.cols()) - 3;
  const MatX Phi_f = d.basis.Phi.rightCols(n_f);
  MatX T(M.rows(), 2);
  T.col(0) = uniform_field(d.fe, Vec2::UnitX());
  T.col(1) = uniform_field(d.fe, Vec2::UnitY());
  Potential V;
  V.mass = T.col(0).dot(M * T.col(0));
  V.S_f = T.transpose() * M * Phi_f;
  V.K_ff = Phi_f.transpose() * d.matrices.K * Phi_f;
  V.g = g;
  return V;
}

// ---- static Ritz solution of a clamped beam ------------------------------------------------

/// The nodal displacements u = Phi p (FE frame of the data) that minimise
/// 1/2 p^T K_bar p - p^T Phi^T F over p subject to (Phi p) = 0 at the three DOFs of `clamped`,
/// F = M_FE times the uniform gravity field g: the static solution of the FE model in the
/// body's own reduced basis, by its KKT system.
inline VecX ritz_static_clamped(const FlexibleBodyData& d, int clamped, const Vec2& g) {
  const MatX& Phi = d.basis.Phi;
  const int m = static_cast<int>(Phi.cols());
  const MatX K_bar = Phi.transpose() * d.matrices.K * Phi;
  const VecX F = d.matrices.M * uniform_field(d.fe, g);
  const MatX B = Phi.middleRows(3 * clamped, 3);
  MatX KKT = MatX::Zero(m + 3, m + 3);
  KKT.topLeftCorner(m, m) = K_bar;
  KKT.topRightCorner(m, 3) = B.transpose();
  KKT.bottomLeftCorner(3, m) = B;
  VecX rhs = VecX::Zero(m + 3);
  rhs.head(m) = Phi.transpose() * F;
  const VecX x = Eigen::FullPivLU<MatX>(KKT).solve(rhs);
  return Phi * x.head(m);
}

/// Checks node_pose at every node against the FE field u = Phi_f q_f placed by the frame:
/// p_k = (R + A (x_k + u_k), theta + psi_k), with the hints of the likely slips.
inline void check_poses_follow_fe_field(const FlexibleBodyData& d, const VecX& q, double tolerance) {
  const VecX u = d.Phi_f * q.tail(d.num_modes());
  for (int k = 0; k < d.fe.num_nodes(); ++k) {
    CAPTURE(k);
    const Vec2 r = q.head<2>() + rot(q(2)) * (d.fe.nodes()[k] + Vec2(u.segment<2>(3 * k)));
    const Vec3 expected(r.x(), r.y(), q(2) + u(3 * k + 2));
    const Vec2 r0 = q.head<2>() + rot(q(2)) * d.fe.nodes()[k];
    const Vec3 p = node_pose(d.nodes[k], q);
    CHECK_CLOSE(p, expected, (Tolerance{tolerance, tolerance}),
                diagnose(p, expected,
                         {{"r_k misses u_bar: r_k = R + A (x_bar + u_bar) with u_bar = Phi_t q_f",
                           Vec3(r0.x(), r0.y(), expected(2))},
                          {"u_bar not rotated: r_k = R + A (x_bar + u_bar), u_bar = Phi_t q_f is in the frame",
                           Vec3(r0.x() + u(3 * k), r0.y() + u(3 * k + 1), expected(2))},
                          {"pose angle misses psi: phi_k = theta + Phi_psi q_f, the section turns with psi",
                           Vec3(r.x(), r.y(), q(2))}},
                         "p_k = (R + A (x_bar_k + u_bar_k), theta + psi_k) with the node's rows of Phi_f"));
  }
}

}  // namespace fmbd::testing::m07
