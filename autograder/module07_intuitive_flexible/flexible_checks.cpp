// The module 7 checks declared in flexible_checks.hpp (documented there), compiled once for all
// the module's test files. Helpers used only here are in the anonymous namespace.

#include "flexible_checks.hpp"

#include "linear_algebra.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <variant>

namespace fmbd::testing::m07 {

namespace {

/// The ModalBodyData of a flexible body of the model (the intuitive body's data).
const ModalBodyData& data_of(const Model& model, BodyId body) {
  const auto* intuitive = dynamic_cast<const IntuitiveBody*>(model.body(body).deformable.get());
  REQUIRE(intuitive != nullptr);
  return intuitive->data();
}

/// Pose of FE node `node` of flexible body `body` at the model state q, by hand.
Vec3 model_node_pose(const Model& model, BodyId body, int node, const VecX& q) {
  const ModalBodyData& d = data_of(model, body);
  return pose_oracle(d.nodes.at(node), model.body_state(q, body));
}

/// Every node point of every flexible body sits at the hand-written pose (module 1's marker of
/// the point, which C(q, t) uses): the finite differences below rely on it. False if one does not.
bool check_node_points(const Model& model, const VecX& q) {
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
    CHECK_CLOSE_NAMED("the pose of a node point from your node_pose", got, expected, tol,
                      with_formula("your node_pose (M07T1) of a node point is wrong", kPose) +
                          "; fix it before C_q and gamma" + kNeedsT4);
  }
  return all;
}

/// Is row `r` of constraint c the angle row of a fixed joint or translational joint (uses phi_k)?
bool is_angle_row(const Constraint& c, int r) {
  if (std::holds_alternative<Fixed>(c.type)) return r == 2;
  if (std::holds_alternative<Translational>(c.type)) return r == 1;
  return std::holds_alternative<AbsoluteAngleDriver>(c.type) || std::holds_alternative<RelativeAngleDriver>(c.type);
}

/// The n x 3 rigid-body columns about point p: node k gets (1, 0, 0), (0, 1, 0), (-(y_k - p_y), x_k - p_x, 1).
MatX rigid_columns(const FeModel& fe, const Vec2& p) {
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
VecX uniform_field(const FeModel& fe, const Vec2& v) {
  VecX u = VecX::Zero(fe.num_dofs());
  for (int k = 0; k < fe.num_nodes(); ++k) u.segment<2>(3 * k) = v;
  return u;
}

}  // namespace

// ---- one node: the kinematics by hand ----------------------------------------------------

Vec3 pose_oracle(const NodeModes& node, const VecX& q) {
  const Vec2 r = q.head<2>() + rot(q(2)) * (node.x_bar + u_bar(node, q));
  return Vec3(r.x(), r.y(), q(2) + psi(node, q));
}

ConvectiveParts convective_parts(const NodeModes& node, const VecX& q, const VecX& qd) {
  const double w = qd(2);
  ConvectiveParts c;
  c.centripetal = -w * w * rot(q(2)) * (node.x_bar + u_bar(node, q));
  c.coriolis = 2.0 * w * rot(q(2)) * tilde() * (node.Phi_t * elastic_part(qd));
  return c;
}

NodeModes random_node(Random& rnd, int n_f) {
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

VecX random_node_state(Random& rnd, int n_f, double elastic) {
  VecX q(3 + n_f);
  q.head<2>() = rnd.vec2(-2.0, 2.0);
  q(2) = rnd.uniform(-3.0, 3.0);
  q.tail(n_f) = rnd.vector(n_f, -elastic, elastic);
  return q;
}

VecX second_derivative(const std::function<VecX(double)>& g, double h) {
  return (-g(2 * h) + 16.0 * g(h) - 30.0 * g(0.0) + 16.0 * g(-h) - g(-2 * h)) / (12.0 * h * h);
}

// ---- whole models --------------------------------------------------------------------------

VecX random_model_state(const Model& model, const VecX& q0, Random& rnd, double shift, double turn, double deflection) {
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

VecX random_model_rates(const Model& model, Random& rnd, double speed, double spin, double elastic_rate) {
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

void check_constraint_jacobian(const Model& model, const VecX& q, double t, const std::string& label) {
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
        CHECK_CLOSE_NAMED("the node's rows of your C_q, columns R and theta",
                          MatX(Cq.block(c.first_row, at, c.rows, 3)), MatX(fd.block(c.first_row, at, c.rows, 3)), tol,
                          "C_q columns of a rigid body in a model with a flexible body: check the flexible body's node "
                          "pose and Jacobian (the rigid kernels are module 1's)" +
                              kNeedsT4);
        continue;
      }
      const int n_f = body.num_coordinates() - 3;
      const MatX elastic = Cq.block(c.first_row, at + 3, c.rows, n_f), elastic_fd = fd.block(c.first_row, at + 3, c.rows, n_f);
      if (elastic.isZero(0.0) && !elastic_fd.isZero(tol.atol)) {
        CHECK_CLOSE_NAMED(
            "the node's rows of your C_q, columns q_f", elastic, elastic_fd, tol,
            "your C_q has nothing in the body's elastic columns: a block on a node's pose is chained with the "
            "node's G_k over all 3 + n_f columns of its body (add_node_block_columns, M07T2)" +
                kNeedsT4);
        continue;
      }
      CHECK_CLOSE_NAMED(
          "the node's rows of your C_q, columns R", MatX(Cq.block(c.first_row, at, c.rows, 2)),
          MatX(fd.block(c.first_row, at, c.rows, 2)), tol,
          "your columns 0-1 of G_k: the node's position moves one to one with R, its angle not at all" + kNeedsT4);
      CHECK_CLOSE_NAMED("the node's rows of your C_q, column theta", MatX(Cq.block(c.first_row, at + 2, c.rows, 1)),
                        MatX(fd.block(c.first_row, at + 2, c.rows, 1)), tol,
                        with_formula("your column 2 of G_k: the arm is the deformed position, and 1 in the angle row",
                                     "A I~ (x_bar + u_bar)") +
                            kNeedsT4);
      for (int r = 0; r < c.rows; ++r) {
        CAPTURE(r);
        const std::string hint =
            is_angle_row(c, r)
                ? with_formula("your G_k: Phi_psi row of the angle missing: a clamped node turns with psi",
                               "row 2 of G_k is (0, 0, 1, Phi_psi)") +
                      kNeedsT4
                : with_formula(
                      "your G_k: the elastic columns are missing or not turned into global axes (u_bar is "
                      "in the frame)",
                      "the elastic columns of G_k are A Phi_t") +
                      kNeedsT4;
        CHECK_CLOSE_NAMED("row r of the node's rows of your C_q, columns q_f",
                          MatX(Cq.block(c.first_row + r, at + 3, 1, n_f)),
                          MatX(fd.block(c.first_row + r, at + 3, 1, n_f)), tol, hint);
      }
    }
  }
}

void check_gamma(const Model& model, const VecX& q, const VecX& qd, double t, const std::string& label) {
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
    CHECK_CLOSE_NAMED(
        "the node's rows of your gamma", VecX(gamma.segment(c.first_row, c.rows)),
        VecX(expected.segment(c.first_row, c.rows)), tol,
        "your gamma differs in the rows of a joint on a flexible node: check your "
        "node_convective_acceleration (its centripetal and Coriolis terms: the T3 node tests name which) and "
        "your node_gamma_correction (which side of the equation the node's term goes to); the marker velocity "
        "needs node_jacobian (M07T2) too" +
            kNeedsT4);
  }
}

// ---- beams and bases ------------------------------------------------------------------------

ReducedBasis cantilever_basis(const FeModel& fe, const FeMatrices& fm, int modes) {
  const int n = fe.num_dofs(), n_i = n - 3, tip = fe.num_nodes() - 1;
  const MatX K_ii = fm.K.bottomRightCorner(n_i, n_i), M_ii = fm.M.bottomRightCorner(n_i, n_i);
  ReducedBasis b;
  b.num_rigid = 3;
  b.Phi = MatX::Zero(n, 4 + modes);
  b.Phi.leftCols(3) = rigid_columns(fe, fe.nodes()[0]);
  VecX load = VecX::Zero(n_i);
  load(3 * tip + 1 - 3) = 1.0;
  VecX shape = solve_spd(K_ii, load);
  shape /= shape.cwiseAbs().maxCoeff();
  b.Phi.col(3).tail(n_i) = shape;
  const MatX eigenvectors = generalized_eigen(K_ii, M_ii).vectors;
  for (int j = 0; j < modes; ++j) {
    VecX mode = eigenvectors.col(j);
    mode /= mode.cwiseAbs().maxCoeff();
    b.Phi.col(4 + j).tail(n_i) = mode;
  }
  b.M_bar = b.Phi.transpose() * fm.M * b.Phi;
  b.K_bar = b.Phi.transpose() * fm.K * b.Phi;
  return b;
}

double Potential::operator()(const VecX& q) const {
  const VecX q_f = elastic_part(q);
  return -g.dot(mass * Vec2(q.head<2>()) + rot(q(2)) * (S_f * q_f)) + 0.5 * q_f.dot(K_ff * q_f);
}

Potential potential_of(const FlexibleBodyData& d, const Vec2& g) {
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

VecX ritz_static_clamped(const FlexibleBodyData& d, int clamped, const Vec2& g) {
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
  const VecX x = solve_general(KKT, rhs);
  return Phi * x.head(m);
}

void check_poses_follow_fe_field(const FlexibleBodyData& d, const VecX& q, double tolerance) {
  const VecX u = d.Phi_f * q.tail(d.num_modes());
  for (int k = 0; k < d.fe.num_nodes(); ++k) {
    CAPTURE(k);
    const Vec2 r = q.head<2>() + rot(q(2)) * (d.fe.nodes()[k] + Vec2(u.segment<2>(3 * k)));
    const Vec3 expected(r.x(), r.y(), q(2) + u(3 * k + 2));
    const Vec2 r0 = q.head<2>() + rot(q(2)) * d.fe.nodes()[k];
    const Vec3 p = node_pose(d.nodes[k], q);
    CHECK_CLOSE_NAMED(
        "your node pose p_k", p, expected, (Tolerance{tolerance, tolerance}),
        diagnose(
            p, expected,
            {{with_formula("your r_k misses u_bar: the node sits at its deformed position", kPose),
              Vec3(r0.x(), r0.y(), expected(2))},
             {with_formula("your r_k: u_bar not rotated: u_bar is in the frame", kPose),
              Vec3(r0.x() + u(3 * k), r0.y() + u(3 * k + 1), expected(2))},
             {with_formula("your pose angle misses psi: the section turns with psi", kPose), Vec3(r.x(), r.y(), q(2))}},
            with_formula("your node pose is not the deformed node in the frame, with the node's rows of "
                         "Phi_f",
                         kPose)));
  }
}

}  // namespace fmbd::testing::m07
