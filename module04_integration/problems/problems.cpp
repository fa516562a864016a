// Tutorial problems of module 4 (README.md in this folder): the accelerations of a pendulum
// released at an angle (forward dynamics), one classical Runge-Kutta step of a slider on a spring
// and a damper, and the constraint drift after one explicit Euler step. Every answer and every
// named mistake is computed by the engine on a model built here.
#include <cmath>
#include <string>
#include <vector>

#include "fmbd/constraints.hpp"
#include "fmbd/forward_dynamics.hpp"
#include "fmbd/integrators.hpp"
#include "fmbd/model.hpp"
#include "fmbd/planar.hpp"
#include "modules.hpp"

namespace fmbd::problems {

namespace {

Quantity vec(const VecX& v) { return Quantity::vector(std::vector<double>(v.data(), v.data() + v.size())); }

// y' = (q_dot, q_ddot) of a model, q_ddot from forward dynamics (eq. (3)).
OdeRhs rhs_of(const Model& m) {
  return [&m](double t, const VecX& y) {
    const int n = m.num_coordinates();
    VecX dy(2 * n);
    dy.head(n) = y.tail(n);
    dy.tail(n) = forward_dynamics(m, y.head(n), y.tail(n), t).qdd;
    return dy;
  };
}

// ---- a free pendulum: a uniform rod pinned at one end, under gravity ----------------------

struct Rod {
  double m = 1, L = 1, g = 9.81;  // kg, m, m/s^2 (gravity along -y)
  double phi_deg = 0;             // rod angle from the x axis, counter-clockwise
  double omega = 0;               // rad/s
};

// The rod O-B (centroid at mid-length, J = m L^2 / 12) pinned at O = (0, 0) by the revolute
// C = r_O - r_P (the ground first), no driver, and its state at the angle phi: q = (x, y, phi)
// of the centroid, q_dot of a rotation about O at omega.
struct RodModel {
  Model model;
  VecX q, qd;
};

RodModel rod_model(const Rod& d, double phi) {
  RodModel r;
  const double c = std::cos(phi), s = std::sin(phi);
  const BodyId rod = r.model.add_body("rod", d.m, d.m * d.L * d.L / 12, Vec3(d.L / 2 * c, d.L / 2 * s, phi));
  const PointId O = r.model.add_point(ground, Vec2::Zero(), "O");
  r.model.add_revolute("pivot", O, r.model.add_point(rod, Vec2(-d.L / 2, 0), "rod O"));
  r.model.set_gravity(Vec2(0, -d.g));
  r.q = r.model.initial_guess();
  r.qd = VecX(3);
  r.qd << -d.L / 2 * s * d.omega, d.L / 2 * c * d.omega, d.omega;
  return r;
}

// m, L, phi (5 + 5 k deg), its quadrant, the sign of omega and |omega| = omega_lo + 0.5 k.
Rod draw_rod(Parameters& r, double omega_lo, int omega_n) {
  Rod d;
  d.m = r.grid(0.5, 0.1, 46);
  d.L = r.grid(0.20, 0.05, 17);
  d.phi_deg = r.grid(5, 5, 17) + 90 * r.integer(0, 3);
  d.omega = (r.integer(0, 1) ? 1 : -1) * r.grid(omega_lo, 0.5, omega_n);
  return d;
}

std::string rod_text(const Rod& d) {
  return "A uniform rod of mass m = " + format_value(d.m) + " kg and length L = " + format_value(d.L) +
         " m is pinned to the ground at its end O = (0, 0) and swings freely in the vertical plane (gravity g = " +
         format_value(d.g) + " m/s^2 along -y; no motor, no friction). Its coordinates are q = (x, y, phi): the centroid G at "
         "mid-length and the angle phi of the rod from the x axis, counter-clockwise (J = m L^2 / 12 about G). At "
         "this instant phi = " + format_value(d.phi_deg) + " deg and phi_dot = " + format_value(d.omega) + " rad/s.";
}

// ---- M04P1: forward dynamics of the released rod ------------------------------------------

Quantity rod_accelerations(const Rod& d, double phi) {
  const RodModel r = rod_model(d, phi);
  return vec(forward_dynamics(r.model, r.q, r.qd, 0.0).qdd);
}

Problem acceleration_problem() {
  Problem p;
  p.id = "M04P1";
  p.title = "accelerations of a free pendulum";
  p.points = 3;
  p.tolerance = Tolerance(2e-3, 1e-4);
  p.kind = Kind::vector;
  p.rows = 3;
  p.make = [](Parameters& r) {
    const Rod d = draw_rod(r, 1.0, 11);
    Variant v;
    v.statement = rod_text(d) + "\nGive q_ddot = (x_ddot, y_ddot, phi_ddot) (entries in SI: m/s^2, m/s^2, rad/s^2; "
                                "no unit).";
    v.solve = [d] {
      const double phi = d.phi_deg * kDeg;
      const Quantity a = rod_accelerations(d, phi);
      // J about the centroid in the moment balance about O: phi_ddot four times too large, as
      // the rod would turn under four times the gravity (phi_ddot is proportional to g).
      Rod heavy = d;
      heavy.g = 4 * d.g;
      Rod still = d;
      still.omega = 0;
      Rod upside_down = d;
      upside_down.g = -d.g;
      Solution s;
      s.answer = a;
      s.mistakes.emplace_back("J about the centroid (m L^2 / 12) instead of the pivot (m L^2 / 3)",
                              rod_accelerations(heavy, phi));
      s.mistakes.emplace_back("the centripetal term -(L/2) phi_dot^2 (cos phi, sin phi) left out",
                              rod_accelerations(still, phi));
      s.mistakes.emplace_back("the moment of the weight with the wrong sign", rod_accelerations(upside_down, phi));
      s.mistakes.emplace_back("degrees against radians: phi in degrees put into cos and sin as radians",
                              rod_accelerations(d, d.phi_deg));
      const double alpha = a.values[2];
      s.steps.push_back("phi = " + format_value(phi) + " rad; J_O = m L^2 / 3 = " + format_value(d.m * d.L * d.L / 3) + " kg m^2");
      s.steps.push_back("phi_ddot = -m g (L/2) cos phi / J_O = -3 g cos phi / (2 L) = " + format_value(alpha) + " rad/s^2");
      s.steps.push_back("a_G = (L/2) phi_ddot (-sin phi, cos phi) - (L/2) phi_dot^2 (cos phi, sin phi) = (" +
                        format_value(a.values[0]) + ", " + format_value(a.values[1]) + ") m/s^2");
      s.steps.push_back("q_ddot = " + format_quantity(a));
      return s;
    };
    return v;
  };
  return p;
}

// ---- M04P2: one RK4 step of a slider on a spring and a damper -----------------------------

struct Oscillator {
  double m, k, c;      // kg, N/m, N s/m
  double x0_mm, v0;    // mm, m/s
  double h_ms;         // ms
};

// The slider (a body on a horizontal guide, a translational joint to the ground) with a spring
// and a damper (a TSDA, unstretched length 0.5 m) from the ground point (-0.5, 0): x is the
// slider's displacement from the spring's unstretched position. One step of `step` from
// (x0, v0) at t = 0; returns the slider's velocity after it.
double slider_velocity(const Oscillator& d, double c,
                       VecX (*step)(const OdeRhs&, double, const VecX&, double)) {
  Model m;
  const BodyId slider = m.add_body("slider", d.m, 1e-3, Vec3(d.x0_mm * 1e-3, 0, 0));
  const PointId S = m.add_point(slider, Vec2::Zero(), "slider S");
  m.add_translational("guide", m.add_point(ground, Vec2::Zero(), "guide"), S, Vec2::UnitX());
  m.add_tsda("spring and damper", m.add_point(ground, Vec2(-0.5, 0), "anchor"), S, d.k, 0.5, c);
  VecX y = VecX::Zero(6);
  y.head(3) = m.initial_guess();
  y(3) = d.v0;
  const VecX y1 = step(rhs_of(m), 0.0, y, d.h_ms * 1e-3);
  return y1(3);
}

Problem rk4_problem() {
  Problem p;
  p.id = "M04P2";
  p.title = "one Runge-Kutta step of a slider on a spring";
  p.points = 3;
  p.tolerance = Tolerance(1e-3, 1e-6);
  p.unit = "m/s";
  p.make = [](Parameters& r) {
    Oscillator d{};
    d.m = r.grid(0.5, 0.1, 26);
    d.k = r.grid(20, 10, 19);
    d.c = r.grid(1.0, 0.5, 19);
    d.x0_mm = r.grid(10, 2, 21);
    d.v0 = r.grid(0.10, 0.02, 21);
    d.h_ms = r.grid(10, 2, 16);
    Variant v;
    v.statement = "A slider of mass m = " + format_value(d.m) + " kg moves on a horizontal guide (no friction, no gravity along "
                  "it), held by a linear spring k = " + format_value(d.k) + " N/m and a viscous damper c = " + format_value(d.c) +
                  " N s/m in parallel: m x_ddot = -k x - c x_dot, x measured from the unstretched position. At t = 0 "
                  "x = " + format_value(d.x0_mm) + " mm and x_dot = " + format_value(d.v0) + " m/s.\nTake one step of the classical "
                  "Runge-Kutta method (RK4) of size h = " + format_value(d.h_ms) + " ms on y = (x, x_dot) and give the slider's "
                  "velocity x_dot_1 after it.";
    v.solve = [d] {
      const double v1 = slider_velocity(d, d.c, rk4_step);
      Solution s;
      s.answer = Quantity::number(v1);
      s.mistakes.emplace_back("an explicit Euler step instead of RK4", Quantity::number(slider_velocity(d, d.c, euler_step)));
      s.mistakes.emplace_back("the damper left out", Quantity::number(slider_velocity(d, 0.0, rk4_step)));
      const double h = d.h_ms * 1e-3, x0 = d.x0_mm * 1e-3;
      s.steps.push_back("h = " + format_value(h) + " s, y_0 = (x_0, x_dot_0) = (" + format_value(x0) + " m, " + format_value(d.v0) + " m/s)");
      s.steps.push_back("k_1 = f(y_0) = (x_dot_0, -(k x_0 + c x_dot_0) / m) = (" + format_value(d.v0) + " m/s, " +
                        format_value(-(d.k * x0 + d.c * d.v0) / d.m) + " m/s^2)");
      s.steps.push_back("an Euler step would give x_dot_1 = " + format_value(s.mistakes.front().value.values[0]) +
                        " m/s; RK4 evaluates f three more times, at y_0 + (h/2) k_1, y_0 + (h/2) k_2, y_0 + h k_3");
      s.steps.push_back("x_dot_1 = " + format_value(v1) + " m/s (the engine: one RK4 step of the slider's model)");
      return s;
    };
    return v;
  };
  return p;
}

// ---- M04P3: the drift of the pivot after one explicit Euler step ---------------------------

struct DriftData {
  Rod rod;
  double h_ms;
};

// C(q_1) of the pivot after one Euler step of forward dynamics from the consistent state of the
// rod at phi; `keep_R`, `keep_phi`: that part of q left at q_0 (the mistakes).
Quantity drift(const DriftData& d, double phi, bool keep_R = false, bool keep_phi = false) {
  const RodModel r = rod_model(d.rod, phi);
  VecX y(6);
  y << r.q, r.qd;
  const double h = d.h_ms * 1e-3;
  VecX q1 = euler_step(rhs_of(r.model), 0.0, y, h).head(3);
  if (keep_R) q1.head(2) = r.q.head(2);
  if (keep_phi) q1(2) = r.q(2);
  return vec(constraints(r.model, q1, h));
}

Problem drift_problem() {
  Problem p;
  p.id = "M04P3";
  p.title = "constraint drift after one Euler step";
  p.points = 2;
  p.tolerance = Tolerance(2e-3, 1e-7);
  p.kind = Kind::vector;
  p.rows = 2;
  p.unit = "m";
  p.make = [](Parameters& r) {
    DriftData d{draw_rod(r, 2.0, 9), 0};
    d.h_ms = r.grid(20, 5, 17);
    Variant v;
    v.statement = rod_text(d.rod) + " The state is consistent: C = 0 and C_dot = 0.\nThe pivot is the revolute joint "
                  "C = r_O - r_P = 0, P the rod's end at O (the ground first). Forward dynamics is integrated with one "
                  "explicit Euler step of h = " + format_value(d.h_ms) + " ms on y = (q, q_dot), no stabilisation, no projection. "
                  "Give the constraint violation C(q_1) after the step.";
    v.solve = [d] {
      const double phi = d.rod.phi_deg * kDeg;
      const Quantity C = drift(d, phi);
      Solution s;
      s.answer = C;
      s.mistakes.emplace_back("the centroid not moved (only phi updated)", drift(d, phi, true, false));
      s.mistakes.emplace_back("the angle not updated (only the centroid moved)", drift(d, phi, false, true));
      s.mistakes.emplace_back("degrees against radians: phi in degrees put into cos and sin as radians",
                              drift(d, d.rod.phi_deg));
      const double h = d.h_ms * 1e-3, w = d.rod.omega, L = d.rod.L;
      s.steps.push_back("phi_0 = " + format_value(phi) + " rad, h phi_dot = " + format_value(h * w) + " rad");
      s.steps.push_back("R_1 = R_0 + h R_dot_0 = (L/2) [(cos phi_0, sin phi_0) + h phi_dot (-sin phi_0, cos phi_0)] = (" +
                        format_value(L / 2 * (std::cos(phi) - h * w * std::sin(phi))) + ", " +
                        format_value(L / 2 * (std::sin(phi) + h * w * std::cos(phi))) + ") m (q_ddot does not enter q_1)");
      s.steps.push_back("phi_1 = phi_0 + h phi_dot = " + format_value(phi + h * w) + " rad");
      s.steps.push_back("C(q_1) = -(R_1 + A(phi_1) s_P), s_P = (-L/2, 0): " + format_quantity(C) + " m");
      return s;
    };
    return v;
  };
  return p;
}

}  // namespace

std::vector<Problem> module04_problems() { return {acceleration_problem(), rk4_problem(), drift_problem()}; }

}  // namespace fmbd::problems
