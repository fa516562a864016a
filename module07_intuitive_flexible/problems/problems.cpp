// Tutorial problems of module 7 (README.md in this folder): the global position of a deformed
// node, the node's Jacobian G_k, and the body forces of the intuitive form on theta and q_f
// (gravity on a body whose shape moves its mass centre, and the elastic force). Every answer and
// every named mistake is computed by the engine (node_pose, node_jacobian,
// flexible_gravity_force).
#include <string>
#include <vector>

#include "fmbd/intuitive_flexible.hpp"
#include "modules.hpp"

namespace fmbd::problems {

namespace {

// A node of a body with one elastic coordinate, and the body's frame coordinates.
struct NodeCase {
  double Rx = 0, Ry = 0;      // m
  double theta_deg = 0;       // never a multiple of 90
  double xbar_x = 0, xbar_y = 0;  // m
  double phi_x = 0, phi_y = 0;    // m per unit q_f
  double phi_psi = 0;             // rad per unit q_f
  double q_f = 0;                 // dimensionless
};

NodeCase draw_node(Parameters& r) {
  NodeCase c;
  c.Rx = r.grid(-1.0, 0.1, 21);
  c.Ry = r.grid(-1.0, 0.1, 21);
  c.theta_deg = r.grid(10, 5, 15) + 90 * r.integer(0, 3);
  c.xbar_x = r.grid(0.30, 0.05, 17);
  c.xbar_y = r.grid(-0.05, 0.01, 11);
  c.phi_x = r.grid(-0.10, 0.02, 11);
  c.phi_y = r.grid(0.5, 0.1, 11);
  c.phi_psi = r.grid(0.5, 0.1, 16);
  c.q_f = (r.integer(0, 1) ? 1 : -1) * r.grid(0.04, 0.01, 9);
  return c;
}

NodeModes node_of(const NodeCase& c) {
  NodeModes node;
  node.x_bar = Vec2(c.xbar_x, c.xbar_y);
  node.Phi_t = MatX(2, 1);
  node.Phi_t << c.phi_x, c.phi_y;
  node.Phi_psi = MatX(1, 1);
  node.Phi_psi << c.phi_psi;
  return node;
}

VecX coordinates(const NodeCase& c, double theta, double q_f) {
  VecX q(4);
  q << c.Rx, c.Ry, theta, q_f;
  return q;
}

std::string node_text(const NodeCase& c) {
  return "A flexible body has one elastic coordinate q_f (dimensionless), so q = (R_x, R_y, theta, q_f). Node k sits at "
         "x_bar_k = (" + format_value(c.xbar_x) + ", " + format_value(c.xbar_y) + ") m in the floating frame; its rows in "
         "the elastic basis are Phi_t,k = (" + format_value(c.phi_x) + ", " + format_value(c.phi_y) +
         ") m (translation, frame axes) and Phi_psi,k = " + format_value(c.phi_psi) + " rad (rotation). The body is at R = (" +
         format_value(c.Rx) + ", " + format_value(c.Ry) + ") m, theta = " + format_value(c.theta_deg) +
         " deg (counter-clockwise), q_f = " + format_value(c.q_f) + ".";
}

// ---- M07P1: the global position of a deformed node -----------------------------------------

Quantity position(const NodeModes& node, const VecX& q) {
  const Vec3 p = node_pose(node, q);
  return Quantity::vector({p.x(), p.y()});
}

Problem position_problem() {
  Problem p;
  p.id = "M07P1";
  p.title = "the global position of a deformed node";
  p.points = 2;
  p.tolerance = Tolerance(2e-3, 1e-4);
  p.kind = Kind::vector;
  p.rows = 2;
  p.unit = "m";
  p.make = [](Parameters& r) {
    const NodeCase c = draw_node(r);
    Variant v;
    v.statement = node_text(c) + "\nGive the global position r_k of node k, in m.";
    v.solve = [c] {
      const NodeModes node = node_of(c);
      const double theta = c.theta_deg * kDeg;
      const VecX q = coordinates(c, theta, c.q_f);
      // The deformation added in global axes, unrotated: Phi_t turned back by A^T first.
      NodeModes unrotated = node;
      unrotated.Phi_t = rotation(theta).transpose() * node.Phi_t;
      const Vec2 u_bar = node.Phi_t * VecX::Constant(1, c.q_f);
      Solution s;
      s.answer = position(node, q);
      s.mistakes.emplace_back("the deformation Phi_t,k q_f left out", position(node, coordinates(c, theta, 0.0)));
      s.mistakes.emplace_back("the deformation not turned by A(theta) (added in global axes)", position(unrotated, q));
      s.mistakes.emplace_back("A(theta)^T instead of A(theta) (the frame turned by -theta)",
                              position(node, coordinates(c, -theta, c.q_f)));
      s.mistakes.emplace_back("degrees against radians: theta in degrees put into cos and sin as radians",
                              position(node, coordinates(c, c.theta_deg, c.q_f)));
      s.steps.push_back("u_bar_k = Phi_t,k q_f = " + format_quantity(vec2(u_bar)) + " m");
      s.steps.push_back("x_bar_k + u_bar_k = " + format_quantity(vec2(Vec2(node.x_bar + u_bar))) + " m");
      s.steps.push_back("A(theta) (x_bar_k + u_bar_k) = " + format_quantity(vec2(Vec2(rotation(theta) * (node.x_bar + u_bar)))) + " m");
      s.steps.push_back("r_k = R + A(theta) (x_bar_k + u_bar_k) = " + format_quantity(s.answer) + " m");
      return s;
    };
    return v;
  };
  return p;
}

// ---- M07P2: the node's Jacobian G_k ----------------------------------------------------------

Quantity jacobian(const NodeModes& node, const VecX& q) {
  const MatX G = node_jacobian(node, q);
  std::vector<double> values;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) values.push_back(G(i, j));
  return Quantity::matrix(3, 4, values);
}

Problem jacobian_problem() {
  Problem p;
  p.id = "M07P2";
  p.title = "the Jacobian G_k of a node of a flexible body";
  p.points = 3;
  p.tolerance = Tolerance(2e-3, 1e-4);
  p.kind = Kind::matrix;
  p.rows = 3;
  p.cols = 4;
  p.unit = "";
  p.make = [](Parameters& r) {
    const NodeCase c = draw_node(r);
    Variant v;
    v.statement = node_text(c) + "\nGive the Jacobian G_k = d(r_k, phi_k)/dq of node k (3 x 4: rows r_x, r_y, phi_k; "
                                 "columns R_x, R_y, theta, q_f), entries in SI without a unit.";
    v.solve = [c] {
      const NodeModes node = node_of(c);
      const double theta = c.theta_deg * kDeg;
      const VecX q = coordinates(c, theta, c.q_f);
      NodeModes rigid_rotation = node;  // the node's rotation without its elastic part
      rigid_rotation.Phi_psi.setZero();
      const Vec2 u_bar = node.Phi_t * VecX::Constant(1, c.q_f);
      const Mat2 A = rotation(theta);
      Solution s;
      s.answer = jacobian(node, q);
      s.mistakes.emplace_back("the deformation left out of the theta column (A I~ x_bar_k only)",
                              jacobian(node, coordinates(c, theta, 0.0)));
      s.mistakes.emplace_back("A(theta) left out (the frame's components)", jacobian(node, coordinates(c, 0.0, c.q_f)));
      s.mistakes.emplace_back("Phi_psi,k left out of the row of phi_k", jacobian(rigid_rotation, q));
      s.mistakes.emplace_back("degrees against radians: theta in degrees put into cos and sin as radians",
                              jacobian(node, coordinates(c, c.theta_deg, c.q_f)));
      s.steps.push_back("columns R_x, R_y: (1, 0, 0) and (0, 1, 0)");
      s.steps.push_back("x_bar_k + Phi_t,k q_f = " + format_quantity(vec2(Vec2(node.x_bar + u_bar))) + " m");
      s.steps.push_back("column theta: (A I~ (x_bar_k + Phi_t,k q_f), 1) with A I~ = dA/dtheta: (" +
                        format_quantity(vec2(Vec2(A * I_tilde() * (node.x_bar + u_bar)))) + ", 1)");
      s.steps.push_back("column q_f: (A Phi_t,k, Phi_psi,k) = (" + format_quantity(vec2(Vec2(A * node.Phi_t))) + ", " +
                        format_value(c.phi_psi) + ")");
      s.steps.push_back("G_k = " + format_quantity(s.answer));
      return s;
    };
    return v;
  };
  return p;
}

// ---- M07P3: the body forces of the intuitive form on theta and q_f --------------------------

struct BodyCase {
  double S_x = 0, S_y = 0;  // kg m
  double k = 0;             // N m
  double theta_deg = 0;
  double q_f = 0;
};

Quantity theta_and_elastic_forces(const BodyCase& b, double theta, double k, const Vec2& g) {
  ModalBodyData data;
  data.Phi_f = MatX::Zero(3, 1);
  data.S_f = MatX(2, 1);
  data.S_f << b.S_x, b.S_y;
  data.K_ff = MatX::Constant(1, 1, k);
  VecX q(4);
  q << 0.0, 0.0, theta, b.q_f;
  const VecX Q = flexible_gravity_force(data, q, g);
  return Quantity::vector({Q(2), Q(3) - k * b.q_f});
}

Problem body_forces_problem() {
  Problem p;
  p.id = "M07P3";
  p.title = "the intuitive form's gravity and elastic forces on theta and q_f";
  p.points = 2;
  p.tolerance = Tolerance(2e-3, 1e-5);
  p.kind = Kind::vector;
  p.rows = 2;
  p.unit = "N m";
  p.make = [](Parameters& r) {
    BodyCase b;
    b.S_x = (r.integer(0, 1) ? 1 : -1) * r.grid(0.10, 0.05, 15);
    b.S_y = (r.integer(0, 1) ? 1 : -1) * r.grid(0.10, 0.05, 15);
    b.k = r.grid(20, 5, 17);
    b.theta_deg = r.grid(10, 5, 15) + 90 * r.integer(0, 3);
    b.q_f = (r.integer(0, 1) ? 1 : -1) * r.grid(0.02, 0.01, 9);
    Variant v;
    v.statement = "A flexible body has one elastic coordinate q_f (dimensionless): q = (R_x, R_y, theta, q_f). Its elastic "
                  "shape is not M-orthogonal to the rigid translations (a frame clamped at a node, say): its first moment "
                  "is S_f = T_xy^T M_FE Phi_f = (" + format_value(b.S_x) + ", " + format_value(b.S_y) +
                  ") kg m in the frame's axes, so the mass centre moves by S_f q_f / m. Its modal stiffness is K_ff = " +
                  format_value(b.k) + " N m. Gravity g = (0, -9.81) m/s^2 acts in global axes. The intuitive form's "
                  "potential is V = -g^T (m R + A(theta) S_f q_f) + 1/2 K_ff q_f^2.\nAt theta = " + format_value(b.theta_deg) +
                  " deg and q_f = " + format_value(b.q_f) + ", give the generalised forces Q = -(dV/dq)^T on theta and on q_f: "
                  "(Q_theta, Q_f), both in N m.";
    v.solve = [b] {
      const double theta = b.theta_deg * kDeg;
      const Vec2 g(0.0, -9.81);
      const Vec2 S(b.S_x, b.S_y);
      const Mat2 A = rotation(theta);
      Solution s;
      s.answer = theta_and_elastic_forces(b, theta, b.k, g);
      s.mistakes.emplace_back("the elastic force with the wrong sign (+K_ff q_f)", theta_and_elastic_forces(b, theta, -b.k, g));
      s.mistakes.emplace_back("gravity left out (the elastic force only)", theta_and_elastic_forces(b, theta, b.k, Vec2::Zero()));
      s.mistakes.emplace_back("the elastic force left out", theta_and_elastic_forces(b, theta, 0.0, g));
      s.mistakes.emplace_back("A(theta) left out (gravity taken in the frame's axes)", theta_and_elastic_forces(b, 0.0, b.k, g));
      s.mistakes.emplace_back("degrees against radians: theta in degrees put into cos and sin as radians",
                              theta_and_elastic_forces(b, b.theta_deg, b.k, g));
      s.steps.push_back("A(theta)^T g = " + format_quantity(vec2(Vec2(A.transpose() * g))) + " m/s^2 (gravity in the frame's axes)");
      s.steps.push_back("Q_theta = g^T A I~ S_f q_f = " + format_value(g.dot(A * I_tilde() * S) * b.q_f) + " N m");
      s.steps.push_back("Q_f = S_f^T A^T g - K_ff q_f = " + format_value(S.dot(A.transpose() * g)) + " - " +
                        format_value(b.k * b.q_f) + " = " + format_value(s.answer.values[1]) + " N m");
      return s;
    };
    return v;
  };
  return p;
}

}  // namespace

std::vector<Problem> module07_problems() { return {position_problem(), jacobian_problem(), body_forces_problem()}; }

}  // namespace fmbd::problems
