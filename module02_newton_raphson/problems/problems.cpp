// Tutorial problems of module 2 (README.md in this folder): one Newton-Raphson step of a position
// problem, the velocity of a driven slider-crank's slider, and gamma of a revolute joint. Every
// answer and every named mistake is computed by the engine on a model built here.
#include <cmath>
#include <string>
#include <vector>

#include "fmbd/constraints.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/gamma.hpp"
#include "fmbd/linear_solve.hpp"
#include "fmbd/model.hpp"
#include "fmbd/newton_raphson.hpp"
#include "fmbd/planar.hpp"
#include "fmbd/velocity_acceleration.hpp"
#include "modules.hpp"

namespace fmbd::problems {

namespace {

// ---- M02P1: one Newton-Raphson step ------------------------------------------------------

struct StepData {
  double L;          // m
  double phi0_deg;   // guess
  double x_d;        // m, the driven x of the tip
};

// A link of length L pinned to the ground at O = (0, 0) at its end A, its other end B driven to
// x_B = x_d (a point-coordinate driver). The guess has the pin closed at angle phi0.
Model step_model(const StepData& d, double phi0) {
  Model m;
  const BodyId link = m.add_body("link", 1.0, 0.1, Vec3(d.L / 2 * std::cos(phi0), d.L / 2 * std::sin(phi0), phi0));
  const PointId O = m.add_point(ground, Vec2::Zero(), "O");
  const PointId A = m.add_point(link, Vec2(-d.L / 2, 0), "A");
  const PointId B = m.add_point(link, Vec2(d.L / 2, 0), "B");
  m.add_revolute("pin", O, A);
  m.add_point_coordinate_driver("x of B", B, Axis::x, DriveFunction::constant(d.x_d));
  return m;
}

// q after one Newton step from the model's guess; sign -1 takes the step the wrong way.
VecX one_step(const Model& m, double sign) {
  const VecX q0 = m.initial_guess();
  const VecX C = constraints(m, q0, 0.0);
  const MatX Cq = constraint_jacobian(m, q0, 0.0);
  return q0 + sign * solve_square(m, Cq, -C, "Newton step");
}

Problem newton_problem() {
  Problem p;
  p.id = "M02P1";
  p.title = "one Newton-Raphson step of a position problem";
  p.points = 3;
  p.tolerance = Tolerance(1e-3, 1e-4);
  p.unit = "rad";
  p.unit_optional = true;
  p.make = [](Parameters& r) {
    StepData d{};
    d.L = r.grid(0.20, 0.05, 13);
    d.phi0_deg = r.grid(30, 5, 7);
    const double target = d.phi0_deg + (r.integer(0, 1) ? 1 : -1) * r.grid(8, 2, 5);  // 8..16 deg away
    d.x_d = std::round(d.L * std::cos(target * kDeg) * 1000) / 1000;
    Variant v;
    v.statement = "A link A-B of length L = " + format_value(d.L) + " m is pinned to the ground at A = O = (0, 0); its angle phi is "
                  "measured from the x axis, so B = (L cos phi, L sin phi). A driver holds the x coordinate of B at "
                  "x_B = " + format_value(d.x_d) + " m. In body coordinates q = (x, y, phi) of the link's centroid, "
                  "C(q) = [x - (L/2) cos phi; y - (L/2) sin phi; x + (L/2) cos phi - x_B] = 0.\n"
                  "Starting from the guess phi_0 = " + format_value(d.phi0_deg) + " deg with the pin closed (x_0 = (L/2) cos phi_0, "
                  "y_0 = (L/2) sin phi_0), take one Newton-Raphson step C_q dq = -C. Give phi_1.";
    v.solve = [d] {
      const Model m = step_model(d, d.phi0_deg * kDeg);
      const VecX q0 = m.initial_guess();
      const VecX q1 = one_step(m, 1);
      Solution s;
      s.answer = Quantity::number(q1(2));
      s.mistakes.emplace_back("the step taken the wrong way (C_q dq = +C)", Quantity::number(one_step(m, -1)(2)));
      s.mistakes.emplace_back("the converged solution, not one step",
                              Quantity::number(newton_raphson(m, q0, 0.0).q(2)));
      s.steps.push_back("q_0 = " + format_quantity(Quantity::vector({q0(0), q0(1), q0(2)})) + " (m, m, rad)");
      const VecX C = constraints(m, q0, 0.0);
      s.steps.push_back("C(q_0) = " + format_quantity(Quantity::vector({C(0), C(1), C(2)})) + " m");
      const VecX dq = q1 - q0;
      s.steps.push_back("dq = " + format_quantity(Quantity::vector({dq(0), dq(1), dq(2)})));
      s.steps.push_back("phi_1 = phi_0 + dphi = " + format_value(q1(2)) + " rad = " + format_value(q1(2) / kDeg) + " deg");
      return s;
    };
    return v;
  };
  return p;
}

// ---- M02P2: velocity of the slider of a driven slider-crank ------------------------------

struct CrankData {
  double r, l;    // m
  double A_deg;   // crank angle
  double rpm;     // crank speed
};

// The slider's velocity at crank angle A [rad] and crank speed omega [rad/s].
double slider_velocity(const CrankData& d, double l, double A, double omega) {
  examples::SliderCrankParameters p;
  p.r = d.r;
  p.l = l;
  p.A0 = A;
  p.omega = omega;
  const Model m = examples::slider_crank(p);
  const VecX q = examples::slider_crank_configuration(p, A);
  return solve_velocities(m, q, 0.0)(6);
}

Problem velocity_problem() {
  Problem p;
  p.id = "M02P2";
  p.title = "velocity of a driven slider-crank's slider";
  p.points = 3;
  p.tolerance = Tolerance(2e-3, 1e-5);
  p.unit = "m/s";
  p.make = [](Parameters& r) {
    CrankData d{};
    d.r = r.grid(0.05, 0.01, 11);
    d.l = r.grid(0.20, 0.02, 11);
    d.A_deg = r.grid(10, 10, 8) + 180 * r.integer(0, 1);  // never 0 or 180: the slider moves
    d.rpm = r.grid(60, 30, 9);
    Variant v;
    v.statement = "A slider-crank: the crank O-B (r = " + format_value(d.r) + " m) turns about the ground pivot O = (0, 0); the rod "
                  "B-C (l = " + format_value(d.l) + " m) drives the slider C along the x axis (C to the right of O). The crank "
                  "turns counter-clockwise at a constant " + format_value(d.rpm) + " rpm.\nAt the crank angle A = " + format_value(d.A_deg) +
                  " deg (from the x axis), give the slider's velocity dx_C/dt.";
    v.solve = [d] {
      const double A = d.A_deg * kDeg;
      const double omega = d.rpm * 2 * kPi / 60;
      Solution s;
      const double x_dot = slider_velocity(d, d.l, A, omega);
      s.answer = Quantity::number(x_dot);
      s.mistakes.emplace_back("rpm taken as rad/s (1 rpm = 2 pi / 60 rad/s)",
                              Quantity::number(slider_velocity(d, d.l, A, d.rpm)));
      s.mistakes.emplace_back("omega left out: dx_C/dA instead of dx_C/dt",
                              Quantity::number(slider_velocity(d, d.l, A, 1.0)));
      s.mistakes.emplace_back("the rod's swing left out (-r omega sin A, as for an infinitely long rod)",
                              Quantity::number(slider_velocity(d, 1e6 * d.l, A, omega)));
      s.mistakes.emplace_back("degrees against radians: A in degrees put into sin and cos as radians",
                              Quantity::number(slider_velocity(d, d.l, d.A_deg, omega)));
      s.steps.push_back("omega = " + format_value(omega) + " rad/s, A = " + format_value(A) + " rad");
      s.steps.push_back("dx_C/dA = " + format_value(x_dot / omega) + " m/rad");
      s.steps.push_back("dx_C/dt = (dx_C/dA) omega = " + format_value(x_dot) + " m/s");
      return s;
    };
    return v;
  };
  return p;
}

// ---- M02P3: gamma of a revolute joint between two bodies ---------------------------------

struct GammaData {
  double phi_i_deg, phi_j_deg;  // deg
  double w_i, w_j;              // rad/s
  double si_x, si_y, sj_x, sj_y;  // m
};

// gamma (2) of the revolute P_i (body i) - P_j (body j) at angles phi_i, phi_j and rates w_i, w_j.
Vec2 revolute_gamma_of(const GammaData& d, double phi_i, double phi_j, double w_i, double w_j) {
  const Vec2 s_i(d.si_x, d.si_y), s_j(d.sj_x, d.sj_y);
  Model m;
  const Vec2 R_i(0, 0);
  const Vec2 P = R_i + rotation(phi_i) * s_i;
  const Vec2 R_j = P - rotation(phi_j) * s_j;
  const BodyId i = m.add_body("i", 1.0, 0.1, Vec3(R_i.x(), R_i.y(), phi_i));
  const BodyId j = m.add_body("j", 1.0, 0.1, Vec3(R_j.x(), R_j.y(), phi_j));
  m.add_revolute("pin", m.add_point(i, s_i, "P_i"), m.add_point(j, s_j, "P_j"));
  VecX qd = VecX::Zero(6);
  qd(2) = w_i;
  qd(5) = w_j;
  const VecX g = constraint_gamma(m, m.initial_guess(), qd, 0.0);
  return Vec2(g(0), g(1));
}

Problem gamma_problem() {
  Problem p;
  p.id = "M02P3";
  p.title = "gamma of a revolute joint";
  p.points = 2;
  p.tolerance = Tolerance(2e-3, 1e-5);
  p.kind = Kind::vector;
  p.rows = 2;
  p.unit = "m/s^2";
  p.make = [](Parameters& r) {
    GammaData d{};
    d.phi_i_deg = r.grid(5, 5, 17) + 90 * r.integer(0, 3);
    d.phi_j_deg = r.grid(5, 5, 17) + 90 * r.integer(0, 3);
    d.w_i = (r.integer(0, 1) ? 1 : -1) * r.grid(1.0, 0.5, 9);
    d.w_j = (r.integer(0, 1) ? 1 : -1) * r.grid(1.0, 0.5, 9);
    d.si_x = r.grid(0.10, 0.02, 11);
    d.si_y = r.grid(-0.04, 0.02, 5);
    d.sj_x = -r.grid(0.10, 0.02, 11);
    d.sj_y = r.grid(-0.04, 0.02, 5);
    Variant v;
    v.statement = "Bodies i and j are joined by a revolute joint, C = r_Pi - r_Pj = 0, at the body-frame points s_i = (" +
                  format_value(d.si_x) + ", " + format_value(d.si_y) + ") m (on i) and s_j = (" + format_value(d.sj_x) + ", " + format_value(d.sj_y) +
                  ") m (on j). At this instant phi_i = " + format_value(d.phi_i_deg) + " deg, phi_j = " + format_value(d.phi_j_deg) +
                  " deg, phi_dot_i = " + format_value(d.w_i) + " rad/s and phi_dot_j = " + format_value(d.w_j) +
                  " rad/s.\nGive gamma of the joint, the right-hand side of C_q q_ddot = gamma (2 entries).";
    v.solve = [d] {
      const double pi = d.phi_i_deg * kDeg, pj = d.phi_j_deg * kDeg;
      const Vec2 g = revolute_gamma_of(d, pi, pj, d.w_i, d.w_j);
      // gamma is quadratic in the rates: its two terms from the engine at unit rates.
      const Vec2 term_i = revolute_gamma_of(d, pi, pj, 1, 0), term_j = revolute_gamma_of(d, pi, pj, 0, 1);
      Solution s;
      s.answer = vec2(g);
      s.mistakes.emplace_back("the angular velocities not squared", vec2(d.w_i * term_i + d.w_j * term_j));
      s.mistakes.emplace_back("the two bodies' terms added (body j's term has a minus sign)",
                              vec2(d.w_i * d.w_i * term_i - d.w_j * d.w_j * term_j));
      s.mistakes.emplace_back("degrees against radians: the angles in degrees put into A as radians",
                              vec2(revolute_gamma_of(d, d.phi_i_deg, d.phi_j_deg, d.w_i, d.w_j)));
      s.steps.push_back("A_i s_i phi_dot_i^2 = " + format_quantity(vec2(d.w_i * d.w_i * term_i)) + " m/s^2");
      s.steps.push_back("A_j s_j phi_dot_j^2 = " + format_quantity(vec2(-d.w_j * d.w_j * term_j)) + " m/s^2");
      s.steps.push_back("gamma = A_i s_i phi_dot_i^2 - A_j s_j phi_dot_j^2 = " + format_quantity(vec2(g)) + " m/s^2");
      return s;
    };
    return v;
  };
  return p;
}

}  // namespace

std::vector<Problem> module02_problems() { return {newton_problem(), velocity_problem(), gamma_problem()}; }

}  // namespace fmbd::problems
