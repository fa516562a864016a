// Tutorial problems of module 8 (README.md in this folder). On a flexible body of two point masses
// with one elastic shape: the centrifugal part of the quadratic velocity vector Q_v, the rotation's
// entries (M_theta_theta, M_theta_f) of the mass matrix M(q) = L^T M_FE L of the deformed body, the
// Coriolis moment on the frame, and the steady stretch of module 7's spinning body. On a tip mass
// on a spinning arm: the rate at which linear FFRF loses the transverse stiffness, and the
// foreshortening that gives it back. Every answer and every named mistake is computed by the
// engine (quadratic_velocity_vector, ffrf_mass_matrix, beam_stiffness for the arm).
#include <Eigen/LU>
#include <Eigen/SparseCore>
#include <cmath>
#include <utility>
#include <string>
#include <vector>

#include "fmbd/beam_element.hpp"
#include "fmbd/ffrf.hpp"
#include "modules.hpp"

namespace fmbd::problems {

namespace {

// Two point masses m at x_bar_1 = (-d, 0) and x_bar_2 = (d, 0) in the floating frame, and one
// elastic shape Phi_t,1 = (-a, b1), Phi_t,2 = (a, b2) [m per unit q_f]. The drawn q_f (0.04 to
// 0.08) moves a mass by at most 4.5 % of d.
struct Dumbbell {
  double m = 1;  // kg
  double d = 0.3, a = 0.02, b1 = 0.05, b2 = 0.15;  // m
};

Dumbbell draw_dumbbell(Parameters& r) {
  Dumbbell body;
  body.m = r.grid(0.5, 0.1, 16);
  body.d = r.grid(0.25, 0.05, 6);
  body.a = r.grid(0.05, 0.01, 6);
  body.b1 = r.grid(0.01, 0.01, 5);
  body.b2 = r.grid(0.06, 0.01, 5);
  return body;
}

// The body's data as the FFRF reads it: the nodes and the FE mass matrix (no rotary inertia).
FlexibleBodyData body_data(const Dumbbell& body) {
  FlexibleBodyData data;
  const Vec2 x_bar[2] = {Vec2(-body.d, 0), Vec2(body.d, 0)};
  const Vec2 shape[2] = {Vec2(-body.a, body.b1), Vec2(body.a, body.b2)};
  data.Phi_f = MatX::Zero(6, 1);
  for (int k = 0; k < 2; ++k) {
    NodeModes node;
    node.x_bar = x_bar[k];
    node.Phi_t = MatX(2, 1);
    node.Phi_t << shape[k].x(), shape[k].y();
    node.Phi_psi = MatX::Zero(1, 1);
    data.nodes.push_back(node);
    data.Phi_f.block<2, 1>(3 * k, 0) = shape[k];
  }
  std::vector<Eigen::Triplet<double>> masses;
  for (int dof : {0, 1, 3, 4}) masses.emplace_back(dof, dof, body.m);
  data.matrices.M.resize(6, 6);
  data.matrices.M.setFromTriplets(masses.begin(), masses.end());
  data.mass = 2 * body.m;
  return data;
}

std::string dumbbell_text(const Dumbbell& body) {
  return "A flexible body is modelled by two point masses m = " + format_value(body.m) + " kg (no rotary inertia) at x_bar_1 = (-d, 0) and "
         "x_bar_2 = (d, 0) in its floating frame, d = " + format_value(body.d) + " m; the frame's origin is the undeformed "
         "mass centre. One elastic shape moves them by u_bar_k = Phi_t,k q_f (frame axes, q_f dimensionless) with Phi_t,1 = (" +
         format_value(-body.a) + ", " + format_value(body.b1) + ") m and Phi_t,2 = (" + format_value(body.a) + ", " +
         format_value(body.b2) + ") m. The coordinates are q = (R_x, R_y, theta, q_f); the full FFRF gives "
         "M(q) q_ddot = Q_v + Q_e + Q_a with M(q) = L^T M_FE L and Q_v = -L^T M_FE b.";
}

VecX state(double theta, double q_f) {
  VecX q(4);
  q << 0.0, 0.0, theta, q_f;
  return q;
}

VecX rates(double theta_dot, double q_f_dot) {
  VecX qd(4);
  qd << 0.0, 0.0, theta_dot, q_f_dot;
  return qd;
}

// ---- M08P1: the centrifugal quadratic velocity vector --------------------------------------

Quantity centrifugal(const Dumbbell& body, double theta, double omega, double q_f) {
  const VecX Q = quadratic_velocity_vector(body_data(body), state(theta, q_f), rates(omega, 0.0));
  return Quantity::vector({Q(0), Q(1), Q(2), Q(3)});
}

Problem centrifugal_problem() {
  Problem p;
  p.id = "M08P1";
  p.title = "the centrifugal quadratic velocity vector of a spinning flexible body";
  p.points = 3;
  p.tolerance = Tolerance(2e-3, 1e-6);
  p.kind = Kind::vector;
  p.rows = 4;
  p.unit = "";
  p.make = [](Parameters& r) {
    const Dumbbell body = draw_dumbbell(r);
    const double theta_deg = r.grid(10, 5, 15) + 90 * r.integer(0, 3);
    const double omega = r.grid(2.0, 0.5, 17);
    const double q_f = r.grid(0.04, 0.005, 9);
    Variant v;
    v.statement = dumbbell_text(body) + "\nThe body spins at theta_dot = " + format_value(omega) + " rad/s with theta = " +
                  format_value(theta_deg) + " deg, R_dot = 0, q_f = " + format_value(q_f) +
                  " and q_f_dot = 0. Give the quadratic velocity vector Q_v = (Q_Rx, Q_Ry, Q_theta, Q_f) in SI (N, N, N m, "
                  "N m), without a unit.";
    v.solve = [body, theta_deg, omega, q_f] {
      const double theta = theta_deg * kDeg;
      const FlexibleBodyData data = body_data(body);
      const Vec3 b1 = node_acceleration_bias(data.nodes[0], state(theta, q_f), rates(omega, 0.0));
      const Vec3 b2 = node_acceleration_bias(data.nodes[1], state(theta, q_f), rates(omega, 0.0));
      Solution s;
      s.answer = centrifugal(body, theta, omega, q_f);
      s.mistakes.emplace_back("the deformation left out of the nodes' positions (q_f = 0 in b and L)",
                              centrifugal(body, theta, omega, 0.0));
      s.mistakes.emplace_back("A(theta) left out of the rows of R (the frame's components)", centrifugal(body, 0.0, omega, q_f));
      s.mistakes.emplace_back("degrees against radians: theta in degrees put into cos and sin as radians",
                              centrifugal(body, theta_deg, omega, q_f));
      s.steps.push_back("b_k = -theta_dot^2 (x_bar_k + Phi_t,k q_f) (frame axes): b_1 = (" + format_value(b1.x()) + ", " +
                        format_value(b1.y()) + ") m/s^2, b_2 = (" + format_value(b2.x()) + ", " + format_value(b2.y()) + ") m/s^2");
      s.steps.push_back("Q_R = -A(theta) sum m b_k = theta_dot^2 A(theta) m (Phi_t,1 + Phi_t,2) q_f = (" +
                        format_value(s.answer.values[0]) + ", " + format_value(s.answer.values[1]) + ") N");
      s.steps.push_back("Q_theta = -sum m (I~ (x_bar_k + u_bar_k))^T b_k = 0: the centrifugal forces point away from the origin");
      s.steps.push_back("Q_f = -sum m Phi_t,k^T b_k = theta_dot^2 m sum Phi_t,k^T (x_bar_k + Phi_t,k q_f) = " +
                        format_value(s.answer.values[3]) + " N m");
      return s;
    };
    return v;
  };
  return p;
}

// ---- M08P2: the rotation's entries of the mass matrix of the deformed body -------------------

Quantity rotation_row(const Dumbbell& body, double q_f) {
  const MatX M = ffrf_mass_matrix(body_data(body), state(0.0, q_f));
  return Quantity::vector({M(2, 2), M(2, 3)});
}

Problem mass_coupling_problem() {
  Problem p;
  p.id = "M08P2";
  p.title = "the rotation's entries of the FFRF mass matrix of a deformed body";
  p.points = 2;
  p.tolerance = Tolerance(2e-3, 1e-7);
  p.kind = Kind::vector;
  p.rows = 2;
  p.unit = "kg m^2";
  p.make = [](Parameters& r) {
    const Dumbbell body = draw_dumbbell(r);
    const double q_f = r.grid(0.04, 0.005, 9);
    Variant v;
    v.statement = dumbbell_text(body) + "\nAt q_f = " + format_value(q_f) + " give the entries (M[theta, theta], M[theta, q_f]) "
                  "of the mass matrix M(q), in kg m^2 (they do not depend on R and theta).";
    v.solve = [body, q_f] {
      const Quantity deformed = rotation_row(body, q_f);
      const Quantity undeformed = rotation_row(body, 0.0);
      Solution s;
      s.answer = deformed;
      s.mistakes.emplace_back("the deformation left out (the undeformed M_bar of the intuitive form)", undeformed);
      s.steps.push_back("the rows of node k in L (theta and q_f columns): translation I~ (x_bar_k + u_bar_k) and Phi_t,k");
      s.steps.push_back("undeformed: sum m |x_bar_k|^2 = 2 m d^2 = " + format_value(undeformed.values[0]) + " kg m^2");
      s.steps.push_back("M[theta, theta] = sum m |x_bar_k + Phi_t,k q_f|^2 = " + format_value(deformed.values[0]) + " kg m^2");
      s.steps.push_back("M[theta, q_f] = sum m (I~ (x_bar_k + u_bar_k))^T Phi_t,k = sum m (x_bar_k x Phi_t,k) = m d (b2 - b1) = " +
                        format_value(deformed.values[1]) + " kg m^2 (u_bar_k x Phi_t,k = 0 with one shape)");
      return s;
    };
    return v;
  };
  return p;
}

// ---- M08P3: the Coriolis moment on the frame ---------------------------------------------------

double theta_force(const Dumbbell& body, double omega, double q_f, double q_f_dot) {
  return quadratic_velocity_vector(body_data(body), state(0.0, q_f), rates(omega, q_f_dot))(2);
}

Problem coriolis_problem() {
  Problem p;
  p.id = "M08P3";
  p.title = "the Coriolis moment on the frame of a deforming, spinning body";
  p.points = 2;
  p.tolerance = Tolerance(2e-3, 1e-6);
  p.unit = "N m";
  p.make = [](Parameters& r) {
    const Dumbbell body = draw_dumbbell(r);
    const double omega = (r.integer(0, 1) ? 1 : -1) * r.grid(2.0, 0.5, 17);
    const double q_f = r.grid(0.04, 0.005, 9);
    const double q_f_dot = (r.integer(0, 1) ? 1 : -1) * r.grid(0.5, 0.1, 16);
    Variant v;
    v.statement = dumbbell_text(body) + "\nThe body spins at theta_dot = " + format_value(omega) + " rad/s with R_dot = 0, "
                  "while its shape changes: q_f = " + format_value(q_f) + ", q_f_dot = " + format_value(q_f_dot) +
                  " 1/s. Give the entry Q_theta of the quadratic velocity vector Q_v (the moment on the frame's rotation), in N m.";
    v.solve = [body, omega, q_f, q_f_dot] {
      const double Q = theta_force(body, omega, q_f, q_f_dot);
      Solution s;
      s.answer = Quantity::number(Q);
      s.mistakes.emplace_back("the deformation left out of the nodes' positions (q_f = 0)",
                              Quantity::number(theta_force(body, omega, 0.0, q_f_dot)));
      s.mistakes.emplace_back("the Coriolis term left out (only the centrifugal one, which gives no moment)",
                              Quantity::number(theta_force(body, omega, q_f, 0.0)));
      const double sum = -Q / (2 * omega * q_f_dot);
      s.steps.push_back("b_k = -theta_dot^2 (x_bar_k + u_bar_k) + 2 theta_dot I~ Phi_t,k q_f_dot; the first term has no moment");
      s.steps.push_back("Q_theta = -sum m (I~ (x_bar_k + u_bar_k))^T 2 theta_dot I~ Phi_t,k q_f_dot = -2 theta_dot q_f_dot sum m "
                        "(x_bar_k + Phi_t,k q_f) . Phi_t,k (I~^T I~ = I)");
      s.steps.push_back("sum m (x_bar_k + Phi_t,k q_f) . Phi_t,k = m (2 a d + q_f (2 a^2 + b1^2 + b2^2)) = " + format_value(sum) +
                        " kg m^2");
      s.steps.push_back("Q_theta = " + format_value(Q) + " N m");
      return s;
    };
    return v;
  };
  return p;
}

// ---- M08P4: the steady stretch of a spinning body in the full FFRF ------------------------------

// Module 7's M07P1 body: point masses m at (-d, 0), (d, 0) on a spring k, the stretch mode
// Phi_t,1 = (-1, 0), Phi_t,2 = (1, 0) (q_f in m), K_ff = 4k, spun at Omega about the mass centre.
struct Spring {
  Dumbbell body;
  double k = 0, Omega = 0;
};

// The q_f row of the full FFRF at rest in the spinning frame (theta_ddot = 0, R_ddot = 0 since
// S_f = 0): Q_v,f(q_f) - K q_f = 0, with Q_v,f linear in q_f. Returns (Q_v,f(0), dQ_v,f/dq_f).
std::pair<double, double> centrifugal_row(const Spring& c) {
  const FlexibleBodyData data = body_data(c.body);
  const double at0 = quadratic_velocity_vector(data, state(0.0, 0.0), rates(c.Omega, 0.0))(3);
  const double at1 = quadratic_velocity_vector(data, state(0.0, 1.0), rates(c.Omega, 0.0))(3);
  return {at0, at1 - at0};
}

Problem spin_stretch_problem() {
  Problem p;
  p.id = "M08P4";
  p.title = "the steady stretch of a spinning body in the full FFRF";
  p.points = 2;
  p.tolerance = Tolerance(2e-3, 1e-8);
  p.unit = "m";
  p.make = [](Parameters& r) {
    Spring c;
    c.body.m = r.grid(0.5, 0.1, 16);
    c.body.d = r.grid(0.30, 0.05, 11);
    c.k = r.grid(1500, 250, 17);
    c.Omega = r.grid(2.0, 0.5, 13);
    c.body.a = 1.0;
    c.body.b1 = c.body.b2 = 0.0;
    Variant v;
    v.statement = "The body of module 7's M07P1: two point masses m = " + format_value(c.body.m) + " kg at x_bar_1 = (-d, 0) "
                  "and x_bar_2 = (d, 0), d = " + format_value(c.body.d) + " m, joined by a spring k = " + format_value(c.k) +
                  " N/m along the axis; the stretch mode Phi_t,1 = (-1, 0), Phi_t,2 = (1, 0) moves each mass outwards by q_f "
                  "(in m), so K_ff = 4k. A motor turns the frame at a steady theta_dot = Omega = " + format_value(c.Omega) +
                  " rad/s about the mass centre; no gravity.\nIn the full FFRF, M(q) q_ddot = Q_v + Q_e + Q_a, give the "
                  "steady stretch q_f (q_f_dot = q_f_ddot = 0), in m. (Module 7's equations gave 0.)";
    v.solve = [c] {
      const auto [Q0, slope] = centrifugal_row(c);
      const double K = 4 * c.k;
      const double u = Q0 / (K - slope);
      Solution s;
      s.answer = Quantity::number(u);
      s.mistakes.emplace_back("the intuitive equations' answer (no Q_v: no stretch)", Quantity::number(0.0));
      s.mistakes.emplace_back("the centrifugal force taken at the undeformed radius (Q_v at q_f = 0 only)",
                              Quantity::number(Q0 / K));
      s.mistakes.emplace_back("K_ff taken as the spring's k (the spring stretches by 2 q_f)", Quantity::number(Q0 / (c.k - slope)));
      s.steps.push_back("b_k = -Omega^2 (x_bar_k + Phi_t,k q_f) in the frame; Q_v,f = -sum m Phi_t,k^T b_k = 2 m Omega^2 (d + "
                        "q_f) = " + format_value(Q0) + " + " + format_value(slope) + " q_f N");
      s.steps.push_back("at rest: Q_v,f = K_ff q_f with K_ff = 4k = " + format_value(K) + " N/m: q_f = 2 m Omega^2 d / (4k - 2 m "
                        "Omega^2) = " + format_value(u) + " m, " + format_value(100 * u / c.body.d, 3) + " % of d");
      s.steps.push_back("the stiffness 4k - 2 m Omega^2 left to the stretch vanishes at Omega = sqrt(2k/m) = " +
                        format_value(c.Omega * std::sqrt(K / slope)) + " rad/s, the stretch mode's own frequency");
      return s;
    };
    return v;
  };
  return p;
}

// ---- M08P5: the foreshortening gives a spinning arm its stiffness back -------------------------

// A tip mass m on a massless arm of length L and bending stiffness EI, clamped to a hub of radius
// r_h turning at Omega; one elastic coordinate, the tip's transverse displacement (frame y).
struct Arm {
  double m = 1, L = 1, r_h = 0, EI = 1, Omega = 1;
};

double three_significant(double x) {
  const double scale = std::pow(10.0, std::floor(std::log10(x)) - 2);
  return std::round(x / scale) * scale;
}

// The arm's tip stiffness k and int_0^L v'^2 dx per v_tip^2 of its static tip-load shape, from
// one beam element (beam_stiffness) clamped at its root; the integral by 3-point Gauss of the
// cubic Hermite slopes (exact: v'^2 is of degree 4).
std::pair<double, double> arm_stiffness(const Arm& c, bool curved) {
  const Section section{c.EI, 0.0, 1.0, 1.0};  // E I = EI with I = 1
  const Mat6 K = beam_stiffness(section, c.L);
  const Eigen::Vector2d tip = K.block<2, 2>(4, 4).inverse().col(0);  // (v_b, psi_b) under a unit tip force
  const double k = 1 / tip(0);
  const double v = 1.0, psi = curved ? tip(1) / tip(0) : 0.0;  // psi = 0 with the chord: a straight link
  const double nodes[3] = {0.5 - std::sqrt(0.15), 0.5, 0.5 + std::sqrt(0.15)}, weights[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};
  double integral = 0;
  for (int i = 0; i < 3; ++i) {
    const double xi = nodes[i];
    const double slope = curved ? (6 * xi - 6 * xi * xi) / c.L * v + (-2 * xi + 3 * xi * xi) * psi : v / c.L;
    integral += weights[i] * c.L * slope * slope;
  }
  return {k, integral};
}

// (Omega_c of the linear FFRF, omega at Omega with the foreshortening) [rad/s]. The linear FFRF's
// stiffness k - dQ_v,f/dq_f from quadratic_velocity_vector (`softening` times); the foreshortening
// adds `scale` N int v'^2 with the tension N = m Omega^2 (hub r_h + L). The factors 0, 1 and 2
// make the named mistakes.
Quantity arm_frequencies(const Arm& c, double softening, double hub, bool curved, double scale) {
  const auto [k, integral] = arm_stiffness(c, curved);
  FlexibleBodyData data;  // one node: the tip mass at (r_h + L, 0), its shape (0, 1)
  NodeModes node;
  node.x_bar = Vec2(c.r_h + c.L, 0.0);
  node.Phi_t = (MatX(2, 1) << 0.0, 1.0).finished();
  node.Phi_psi = MatX::Zero(1, 1);
  data.nodes.push_back(node);
  data.Phi_f = (MatX(3, 1) << 0.0, 1.0, 0.0).finished();
  std::vector<Eigen::Triplet<double>> masses = {{0, 0, c.m}, {1, 1, c.m}};
  data.matrices.M.resize(3, 3);
  data.matrices.M.setFromTriplets(masses.begin(), masses.end());
  data.mass = c.m;
  const double M_ff = ffrf_mass_matrix(data, state(0.0, 0.0))(3, 3);
  const double softening_rate = quadratic_velocity_vector(data, state(0.0, 1.0), rates(c.Omega, 0.0))(3) -
                                quadratic_velocity_vector(data, state(0.0, 0.0), rates(c.Omega, 0.0))(3);
  const double tension = c.m * c.Omega * c.Omega * (hub * c.r_h + c.L);
  const double critical = c.Omega * std::sqrt(k / softening_rate);
  const double stiffened = k - softening * softening_rate + scale * tension * integral;
  return Quantity::vector({critical, std::sqrt(stiffened / M_ff)});
}

Problem foreshortening_problem() {
  Problem p;
  p.id = "M08P5";
  p.title = "the foreshortening gives a spinning arm its stiffness back";
  p.points = 3;
  p.tolerance = Tolerance(2e-3, 1e-6);
  p.kind = Kind::vector;
  p.rows = 2;
  p.unit = "rad/s";
  p.make = [](Parameters& r) {
    Arm c;
    c.m = r.grid(0.5, 0.1, 16);
    c.L = r.grid(0.5, 0.1, 11);
    c.r_h = r.grid(0.0, 0.05, 7);
    c.Omega = r.grid(2.0, 0.5, 13);
    const double ratio = r.grid(0.30, 0.05, 13);  // Omega / omega_1
    c.EI = three_significant(c.m * std::pow(c.Omega / ratio, 2) * std::pow(c.L, 3) / 3);
    Variant v;
    v.statement = "A tip mass m = " + format_value(c.m) + " kg sits on a massless arm of length L = " + format_value(c.L) +
                  " m and bending stiffness EI = " + format_value(c.EI) + " N m^2, clamped radially to a hub of radius r_h = " +
                  format_value(c.r_h) + " m. The floating frame is the hub's (origin at its centre), and the one elastic "
                  "coordinate q_f is the tip's transverse displacement, with the arm's static tip-load shape. The hub turns "
                  "at a steady Omega = " + format_value(c.Omega) + " rad/s; no gravity.\nGive (1) the spin rate at which the "
                  "linear full FFRF of this module leaves the transverse motion no stiffness, and (2) the frequency of small "
                  "transverse vibrations at Omega when the arm's axis keeps its length, so that the tip moves inwards by "
                  "the foreshortening (1/2 the integral of v'^2 along it) and the tension m Omega^2 (r_h + L) does work on it. Both in rad/s.";
    v.solve = [c] {
      const auto [k, integral] = arm_stiffness(c, true);
      Solution s;
      s.answer = arm_frequencies(c, 1.0, 1.0, true, 1.0);
      s.mistakes.emplace_back("the -Omega^2 stiffness of the centrifugal terms left out", arm_frequencies(c, 0.0, 1.0, true, 1.0));
      s.mistakes.emplace_back("the hub radius left out of the tension", arm_frequencies(c, 1.0, 0.0, true, 1.0));
      s.mistakes.emplace_back("a straight arm (the slope v/L of a rigid link, not the bent shape's)",
                              arm_frequencies(c, 1.0, 1.0, false, 1.0));
      s.mistakes.emplace_back("the 1/2 of the foreshortening dropped (twice the tension's stiffness)",
                              arm_frequencies(c, 1.0, 1.0, true, 2.0));
      s.mistakes.emplace_back("the linear FFRF's frequency at Omega given for (2) (no foreshortening)",
                              arm_frequencies(c, 1.0, 1.0, true, 0.0));
      Quantity in_hertz = s.answer;
      for (double& x : in_hertz.values) x /= 2 * kPi;
      s.mistakes.emplace_back("frequencies in Hz (cycles per second), not rad/s", in_hertz);
      const double w1 = std::sqrt(k / c.m), alpha = (c.r_h + c.L) * integral;
      s.steps.push_back("k = 3 EI / L^3 = " + format_value(k) + " N/m, omega_1 = sqrt(k/m) = " + format_value(w1) + " rad/s");
      s.steps.push_back("linear FFRF: Q_v,f = m Omega^2 q_f (the tip's radius grows by q_f^2 / 2r only to second order, "
                        "which it drops): stiffness k - m Omega^2, zero at Omega = omega_1 = " +
                        format_value(s.answer.values[0]) + " rad/s");
      s.steps.push_back("foreshortening: v = v_tip (3 L x^2 - x^3) / (2 L^3), the integral of v'^2 along the arm is 6/5 v_tip^2 / L = " +
                        format_value(integral) + " v_tip^2 per m; the tension adds m Omega^2 (r_h + L) 6 / (5 L) = " +
                        format_value(c.m * c.Omega * c.Omega * alpha) + " N/m");
      s.steps.push_back("omega^2 = omega_1^2 + (alpha - 1) Omega^2 with the Southwell coefficient alpha = 6 (r_h + L) / (5 L) = " +
                        format_value(alpha) + ": omega = " + format_value(s.answer.values[1]) + " rad/s");
      return s;
    };
    return v;
  };
  return p;
}

}  // namespace

std::vector<Problem> module08_problems() {
  return {centrifugal_problem(), mass_coupling_problem(), coriolis_problem(), spin_stretch_problem(), foreshortening_problem()};
}

}  // namespace fmbd::problems
