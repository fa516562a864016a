// Tutorial problems of module 8 (README.md in this folder), on a flexible body of two point
// masses with one elastic shape: the centrifugal part of the quadratic velocity vector Q_v, the
// rotation's entries (M_theta_theta, M_theta_f) of the mass matrix M(q) = L^T M_FE L of the
// deformed body, and the Coriolis moment on the frame. Every answer and every named mistake is
// computed by the engine (quadratic_velocity_vector, ffrf_mass_matrix).
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "fmbd/ffrf.hpp"
#include "modules.hpp"

namespace fmbd::problems {

namespace {

// Two point masses m at x_bar_1 = (-d, 0) and x_bar_2 = (d, 0) in the floating frame, and one
// elastic shape Phi_t,1 = (-a, b1), Phi_t,2 = (a, b2) [m per unit q_f].
struct Dumbbell {
  double m = 1;  // kg
  double d = 0.3, a = 0.02, b1 = 0.05, b2 = 0.15;  // m
};

Dumbbell draw_dumbbell(Parameters& r) {
  Dumbbell body;
  body.m = r.grid(0.5, 0.1, 16);
  body.d = r.grid(0.20, 0.05, 13);
  body.a = r.grid(0.010, 0.005, 9);
  body.b1 = r.grid(0.02, 0.01, 9);
  body.b2 = r.grid(0.12, 0.01, 9);
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
    const double q_f = r.grid(0.10, 0.05, 9);
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
    const double q_f = r.grid(0.4, 0.1, 12);
    Variant v;
    v.statement = dumbbell_text(body) + "\nAt q_f = " + format_value(q_f) + " give the entries (M[theta, theta], M[theta, q_f]) "
                  "of the mass matrix M(q), in kg m^2 (they do not depend on R and theta).";
    v.solve = [body, q_f] {
      const Quantity deformed = rotation_row(body, q_f);
      const Quantity undeformed = rotation_row(body, 0.0);
      // The mean of q_f and -q_f: what is left without the cross term 2 q_f sum m x_bar_k . Phi_t,k.
      const Quantity mirrored = rotation_row(body, -q_f);
      std::vector<double> no_cross;
      for (std::size_t i = 0; i < deformed.values.size(); ++i) no_cross.push_back((deformed.values[i] + mirrored.values[i]) / 2);
      Solution s;
      s.answer = deformed;
      s.mistakes.emplace_back("the deformation left out (the undeformed M_bar of the intuitive form)", undeformed);
      s.mistakes.emplace_back("|x_bar_k + u_bar_k|^2 taken as |x_bar_k|^2 + |u_bar_k|^2 (the cross term left out)",
                              Quantity::vector(no_cross));
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
    const double q_f = r.grid(0.10, 0.05, 9);
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

}  // namespace

std::vector<Problem> module08_problems() { return {centrifugal_problem(), mass_coupling_problem(), coriolis_problem()}; }

}  // namespace fmbd::problems
