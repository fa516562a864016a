// Tutorial problems of module 7 (README.md in this folder): what the intuitive equations say a
// spinning body does, its steady stretch and its kinetic energy against the true ones, and the
// generalised forces of a node load on a free-free body. The intuitive answers and the node load
// are computed by the engine (add_intuitive_forces, add_intuitive_mass, node_jacobian,
// flexible_gravity_force); the true stretch by the radial force balance of one mass.
#include <string>
#include <vector>

#include "fmbd/intuitive_flexible.hpp"
#include "modules.hpp"

namespace fmbd::problems {

namespace {

// ---- The spinning dumbbell of M07P1 and M07P2 -------------------------------------------------

// Two point masses m at x_bar_1 = (-d, 0), x_bar_2 = (d, 0), joined by a spring of stiffness k
// along the axis, spun at theta_dot = Omega about the mass centre. Its free-free stretch mode moves
// each mass outwards by q_f [m]: Phi_t,1 = (-1, 0), Phi_t,2 = (1, 0) (S_f = 0), so that
// M_bar = diag(2m, 2m, 2m d^2, 2m) and K_bar_ff = 4k (the spring stretches by 2 q_f).
struct Dumbbell {
  double m = 1, d = 0.5, k = 2000, Omega = 4;  // kg, m, N/m, rad/s
};

Dumbbell draw_dumbbell(Parameters& r) {
  Dumbbell b;
  b.m = r.grid(0.5, 0.1, 16);
  b.d = r.grid(0.30, 0.05, 11);
  b.k = r.grid(1500, 250, 17);
  b.Omega = r.grid(2.0, 0.5, 13);
  return b;
}

ModalBodyData dumbbell_data(const Dumbbell& b) {
  ModalBodyData data;
  data.mass = 2 * b.m;
  data.inertia = 2 * b.m * b.d * b.d;
  data.Phi_f = MatX::Zero(6, 1);
  data.Phi_f(0, 0) = -1;
  data.Phi_f(3, 0) = 1;
  for (int side : {-1, 1}) {
    NodeModes node;
    node.x_bar = Vec2(side * b.d, 0);
    node.Phi_t = MatX::Zero(2, 1);
    node.Phi_t(0, 0) = side;
    node.Phi_psi = MatX::Zero(1, 1);
    data.nodes.push_back(node);
  }
  data.M_ff = MatX::Constant(1, 1, 2 * b.m);
  data.K_ff = MatX::Constant(1, 1, 4 * b.k);
  data.S_f = MatX::Zero(2, 1);
  data.basis.num_rigid = 3;
  data.basis.M_bar = VecX((VecX(4) << 2 * b.m, 2 * b.m, data.inertia, 2 * b.m).finished()).asDiagonal();
  data.basis.K_bar = MatX::Zero(4, 4);
  data.basis.K_bar(3, 3) = 4 * b.k;
  return data;
}

std::string dumbbell_text(const Dumbbell& b) {
  return "A body is two point masses m = " + format_value(b.m) + " kg (no rotary inertia) at x_bar_1 = (-d, 0) and "
         "x_bar_2 = (d, 0) in its floating frame, d = " + format_value(b.d) + " m, joined by a spring of stiffness k = " +
         format_value(b.k) + " N/m along the axis, unstretched at this length. Its free-free stretch mode moves each mass "
         "outwards by q_f (in m): Phi_t,1 = (-1, 0), Phi_t,2 = (1, 0), so q = (R_x, R_y, theta, q_f) and M_bar = "
         "diag(2m, 2m, 2m d^2, 2m), K_bar = diag(0, 0, 0, 4k) (the spring stretches by 2 q_f). A motor turns the frame "
         "at a steady theta_dot = Omega = " + format_value(b.Omega) + " rad/s about the mass centre; no gravity.";
}

// ---- M07P1: the steady stretch of the spinning dumbbell ---------------------------------------

// The stretch at which the q_f row of the intuitive equations is at rest (q_f_ddot = 0 with
// theta_ddot = 0): the root of its Q_a entry, linear in q_f.
double intuitive_stretch(const Dumbbell& b) {
  const ModalBodyData data = dumbbell_data(b);
  auto Q_f = [&](double q_f) {
    VecX q(4), qd(4), Q = VecX::Zero(4);
    q << 0, 0, 0, q_f;
    qd << 0, 0, b.Omega, 0;
    add_intuitive_forces(data, q, qd, Vec2::Zero(), 0, Q);
    return Q(3);
  };
  return -Q_f(0.0) / (Q_f(1.0) - Q_f(0.0));
}

// The true stretch: one mass on its circle of radius d + u, m Omega^2 (d + u) = k_spring u_spring.
double true_stretch(double m, double d, double Omega, double spring_per_u) {
  return m * Omega * Omega * d / (spring_per_u - m * Omega * Omega);
}

Problem stretch_problem() {
  Problem p;
  p.id = "M07P1";
  p.title = "the steady stretch of a spinning body: the intuitive equations against the true one";
  p.points = 2;
  p.tolerance = Tolerance(2e-3, 1e-8);
  p.kind = Kind::vector;
  p.rows = 2;
  p.unit = "m";
  p.make = [](Parameters& r) {
    const Dumbbell b = draw_dumbbell(r);
    Variant v;
    v.statement = dumbbell_text(b) + "\nGive the steady stretch q_f (q_f_dot = q_f_ddot = 0) (1) of the intuitive "
                  "equations M_bar q_ddot = Q_a - K_bar q of this module and (2) of the true body (Newton's law for one "
                  "mass on its circle), as a vector in m.";
    v.solve = [b] {
      const double intuitive = intuitive_stretch(b);
      const double u = true_stretch(b.m, b.d, b.Omega, 2 * b.k);
      const double w2 = b.Omega * b.Omega;
      Solution s;
      s.answer = Quantity::vector({intuitive, u});
      s.mistakes.emplace_back("the intuitive equations given the centrifugal stretch (they have no velocity terms)",
                              Quantity::vector({u, u}));
      s.mistakes.emplace_back("the true body taken as unstretched too (the centrifugal force left out)",
                              Quantity::vector({intuitive, 0.0}));
      s.mistakes.emplace_back("the centrifugal force taken at the undeformed radius d",
                              Quantity::vector({intuitive, b.m * w2 * b.d / (2 * b.k)}));
      s.mistakes.emplace_back("the spring stretched by u, not 2u (both masses move)",
                              Quantity::vector({intuitive, true_stretch(b.m, b.d, b.Omega, b.k)}));
      s.steps.push_back("intuitive: the q_f row is 2m q_f_ddot = -4k q_f at every spin rate (no term in theta_dot), so at "
                        "rest q_f = " + format_value(intuitive) + " m");
      s.steps.push_back("true: m Omega^2 (d + u) = 2k u for one mass (the spring's tension k (2u)), u = m Omega^2 d / (2k - "
                        "m Omega^2) = " + format_value(u) + " m, " + format_value(100 * u / b.d, 3) + " % of d");
      return s;
    };
    return v;
  };
  return p;
}

// ---- M07P2: the kinetic energy of the spinning, stretched dumbbell ----------------------------

struct EnergyCase {
  Dumbbell b;
  double q_f = 0, q_f_dot = 0;  // m, m/s
};

// 1/2 q_dot^T M_bar q_dot of the intuitive form, and 1/2 sum m |r_k_dot|^2 of the two masses with
// r_k_dot = G_k q_dot.
Quantity energies(const EnergyCase& c) {
  const ModalBodyData data = dumbbell_data(c.b);
  VecX q(4), qd(4);
  q << 0, 0, 0, c.q_f;
  qd << 0, 0, c.b.Omega, c.q_f_dot;
  MatX M = MatX::Zero(4, 4);
  add_intuitive_mass(data, q, 0, M);
  double true_energy = 0;
  for (const NodeModes& node : data.nodes) true_energy += 0.5 * c.b.m * (node_jacobian(node, q).topRows(2) * qd).squaredNorm();
  return Quantity::vector({0.5 * qd.dot(M * qd), true_energy});
}

Problem energy_problem() {
  Problem p;
  p.id = "M07P2";
  p.title = "the kinetic energy of a spinning, stretched body: M_bar against the true one";
  p.points = 2;
  p.tolerance = Tolerance(2e-3, 1e-6);
  p.kind = Kind::vector;
  p.rows = 2;
  p.unit = "J";
  p.make = [](Parameters& r) {
    EnergyCase c;
    c.b = draw_dumbbell(r);
    c.q_f = r.grid(0.005, 0.001, 11);
    c.q_f_dot = (r.integer(0, 1) ? 1 : -1) * r.grid(0.10, 0.05, 9);
    Variant v;
    v.statement = dumbbell_text(c.b) + "\nAt this instant R_dot = 0, the stretch is q_f = " + format_value(c.q_f) +
                  " m and it grows at q_f_dot = " + format_value(c.q_f_dot) + " m/s. Give the kinetic energy (1) of the "
                  "intuitive form, 1/2 q_dot^T M_bar q_dot, and (2) of the two masses, 1/2 sum m |r_k_dot|^2, as a vector in J.";
    v.solve = [c] {
      Solution s;
      s.answer = energies(c);
      const double intuitive = s.answer.values[0];
      EnergyCase still = c;
      still.q_f_dot = 0;
      s.mistakes.emplace_back("the true energy at the undeformed radius d (the intuitive one twice)",
                              Quantity::vector({intuitive, intuitive}));
      s.mistakes.emplace_back("the stretch rate q_f_dot left out", energies(still));
      s.mistakes.emplace_back("the two energies swapped", Quantity::vector({s.answer.values[1], intuitive}));
      s.steps.push_back("intuitive: 1/2 (2m d^2 Omega^2 + 2m q_f_dot^2) = " + format_value(intuitive) + " J");
      s.steps.push_back("true: r_k_dot = A (theta_dot I~ (x_bar_k + u_bar_k) + Phi_t,k q_f_dot), two orthogonal parts, "
                        "|r_k_dot|^2 = Omega^2 (d + q_f)^2 + q_f_dot^2");
      s.steps.push_back("true: m (Omega^2 (d + q_f)^2 + q_f_dot^2) = " + format_value(s.answer.values[1]) + " J, " +
                        format_value(s.answer.values[1] - intuitive) + " J more: the inertia 2m (d + q_f)^2 that M_bar "
                        "keeps at 2m d^2");
      return s;
    };
    return v;
  };
  return p;
}

// ---- M07P3: a force at a node of a free-free body, with gravity and the elastic force -------

// Node k of a body with one free-free elastic shape (S_f = 0), q_f dimensionless, and the load.
struct NodeLoad {
  double theta_deg = 0;           // never a multiple of 90
  double xbar_x = 0, xbar_y = 0;  // m
  double phi_x = 0, phi_y = 0;    // m per unit q_f
  double q_f = 0;
  double F_x = 0, F_y = 0;  // N, global axes
  double k = 0;             // K_bar_ff, N m
  double m = 0;             // kg
};

NodeLoad draw_node_load(Parameters& r) {
  NodeLoad c;
  c.theta_deg = r.grid(10, 5, 15) + 90 * r.integer(0, 3);
  c.xbar_x = r.grid(0.40, 0.05, 17);
  c.xbar_y = r.grid(-0.05, 0.01, 11);
  c.phi_x = r.grid(-0.10, 0.02, 11);
  c.phi_y = r.grid(0.8, 0.1, 5);
  c.q_f = (r.integer(0, 1) ? 1 : -1) * r.grid(0.005, 0.001, 11);
  c.F_x = (r.integer(0, 1) ? 1 : -1) * r.grid(5, 5, 10);
  c.F_y = (r.integer(0, 1) ? 1 : -1) * r.grid(5, 5, 10);
  c.k = r.grid(500, 100, 16);
  c.m = r.grid(1.0, 0.5, 9);
  return c;
}

// (Q_theta, Q_f) of gravity (flexible_gravity_force), the force F at the node (G_k^T F) and the
// elastic force -K_bar q_f, at frame angle theta; the moment arm's deformation only if `arm`.
Quantity node_load_forces(const NodeLoad& c, double theta, double k, bool arm) {
  ModalBodyData data;
  data.mass = c.m;
  data.Phi_f = MatX::Zero(3, 1);
  data.S_f = MatX::Zero(2, 1);  // free-free: the shape does not move the mass centre
  NodeModes node;
  node.x_bar = Vec2(c.xbar_x, c.xbar_y);
  node.Phi_t = MatX(2, 1);
  node.Phi_t << c.phi_x, c.phi_y;
  node.Phi_psi = MatX::Zero(1, 1);
  VecX q(4);
  q << 0.0, 0.0, theta, c.q_f;
  VecX Q = flexible_gravity_force(data, q, Vec2(0.0, -9.81));
  Q += node_jacobian(node, q).topRows(2).transpose() * Vec2(c.F_x, c.F_y);
  if (!arm) {  // the theta column of G_k with the undeformed arm x_bar_k
    VecX undeformed = q;
    undeformed(3) = 0;
    Q(2) = node_jacobian(node, undeformed).col(2).head(2).dot(Vec2(c.F_x, c.F_y));
  }
  return Quantity::vector({Q(2), Q(3) - k * c.q_f});
}

Problem node_load_problem() {
  Problem p;
  p.id = "M07P3";
  p.title = "a force at a node of a free-free body: the generalised forces on theta and q_f";
  p.points = 2;
  p.tolerance = Tolerance(2e-3, 1e-5);
  p.kind = Kind::vector;
  p.rows = 2;
  p.unit = "N m";
  p.make = [](Parameters& r) {
    const NodeLoad c = draw_node_load(r);
    Variant v;
    v.statement = "A flexible body of mass m = " + format_value(c.m) + " kg has one free-free elastic shape (M-orthogonal to "
                  "the rigid motions, so its first moment S_f is 0) and the elastic coordinate q_f (dimensionless): q = (R_x, "
                  "R_y, theta, q_f), K_bar_ff = " + format_value(c.k) + " N m. Node k sits at x_bar_k = (" +
                  format_value(c.xbar_x) + ", " + format_value(c.xbar_y) + ") m in the floating frame and moves by "
                  "Phi_t,k q_f with Phi_t,k = (" + format_value(c.phi_x) + ", " + format_value(c.phi_y) + ") m. At theta = " +
                  format_value(c.theta_deg) + " deg and q_f = " + format_value(c.q_f) + " a force F = (" + format_value(c.F_x) +
                  ", " + format_value(c.F_y) + ") N (global axes) acts at node k, and gravity g = (0, -9.81) m/s^2 on the "
                  "body.\nGive the generalised forces on theta and on q_f of gravity, F and the elastic force together: "
                  "(Q_theta, Q_f), both in N m.";
    v.solve = [c] {
      const double theta = c.theta_deg * kDeg;
      const Mat2 A = rotation(theta);
      const Vec2 F(c.F_x, c.F_y), phi(c.phi_x, c.phi_y);
      const Vec2 arm = Vec2(c.xbar_x, c.xbar_y) + phi * c.q_f;
      Solution s;
      s.answer = node_load_forces(c, theta, c.k, true);
      s.mistakes.emplace_back("the deformation left out of the moment arm (x_bar_k only in the theta column of G_k)",
                              node_load_forces(c, theta, c.k, false));
      s.mistakes.emplace_back("A(theta) left out (F taken in the frame's axes)", node_load_forces(c, 0.0, c.k, true));
      s.mistakes.emplace_back("the elastic force left out", node_load_forces(c, theta, 0.0, true));
      s.mistakes.emplace_back("the elastic force with the wrong sign (+K_bar_ff q_f)", node_load_forces(c, theta, -c.k, true));
      s.mistakes.emplace_back("degrees against radians: theta in degrees put into cos and sin as radians",
                              node_load_forces(c, c.theta_deg, c.k, true));
      s.steps.push_back("gravity: -g^T (m R + A S_f q_f) with S_f = 0 acts on R only (m g), not on theta or q_f");
      s.steps.push_back("x_bar_k + Phi_t,k q_f = " + format_quantity(vec2(arm)) + " m; A I~ (x_bar_k + Phi_t,k q_f) = " +
                        format_quantity(vec2(Vec2(A * I_tilde() * arm))) + " m");
      s.steps.push_back("F: Q = G_k^T F, Q_theta = F . A I~ (x_bar_k + Phi_t,k q_f) = " + format_value(s.answer.values[0]) + " N m");
      s.steps.push_back("Q_f = F . A Phi_t,k - K_bar_ff q_f = " + format_value(F.dot(A * phi)) + " - " +
                        format_value(c.k * c.q_f) + " = " + format_value(s.answer.values[1]) + " N m");
      return s;
    };
    return v;
  };
  return p;
}

}  // namespace

std::vector<Problem> module07_problems() { return {stretch_problem(), energy_problem(), node_load_problem()}; }

}  // namespace fmbd::problems
