#pragma once
// Shared helpers of the module 4 graded tests: pendulum and double-pendulum builders with their
// closed forms, a linear test ODE with its exact solution, the complete elliptic integral K(k),
// an independent reference integrator for the pendulum in its one minimal coordinate,
// mass-weighted null-space checks, and hint diagnosis (which typical mistake matches a wrong
// answer). The mistake catalogue's `expect:` phrases start the hints; keep each phrase within
// the first ~100 characters of its hint (Catch wraps long lines).
//
// Every oracle here is independent of the student's module 4 code: plain formulas written out
// below, the model's data (masses, gravity), and the constraint values and Jacobians of module 1.
//
// The functions are defined in integration_checks.cpp, compiled once and linked into every
// graded program of the module.

#include <functional>
#include <string>
#include <vector>

#include "fmbd/applied_forces.hpp"
#include "fmbd/constraints.hpp"
#include "fmbd/drive_function.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/forward_dynamics.hpp"
#include "fmbd/gamma.hpp"
#include "fmbd/integrators.hpp"
#include "fmbd/model.hpp"
#include "fmbd/projection.hpp"
#include "fmbd/simulation.hpp"
#include "grading.hpp"

namespace fmbd::testing::m04 {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kG = 9.81;  ///< gravity of every test model [m/s^2], acting along -y

// ---- plain planar formulas (not the student's) ------------------------------------------

/// (cos phi, sin phi).
Vec2 unit(double phi);
/// I~ v: v turned by +90 degrees.
Vec2 perp(const Vec2& v);
/// A(phi) s, written out.
Vec2 rotate(double phi, const Vec2& s);

/// M = diag(m_k, m_k, J_k), written out from the model's bodies.
MatX mass_matrix_of(const Model& model);

/// T + V of a model whose only applied force is gravity, written out.
double gravity_energy_of(const Model& model, const VecX& q, const VecX& qd);

/// Orthonormal basis of the null space of C_q (n x (n - rank)), by SVD.
MatX null_space(const MatX& Cq);

// ---- pendulum: a uniform rod hinged to the ground at the origin ----------------------------
//
// The rod (mass m, length L, J = m L^2 / 12 about its centroid) turns about the ground point
// O = (0, 0); the hinge sits on the rod's axis at distance `hinge` from the centroid
// (hinge = L / 2: hinged at one end). With phi the rod angle, the centroid is at hinge (cos phi,
// sin phi) and, gravity g along -y and a motor torque T on the rod,
//   I_O phi_ddot = T - m g hinge cos(phi),   I_O = J + m hinge^2.

struct Pendulum {
  Model model;
  double mass = 1.0, length = 1.0, hinge = 0.5, torque = 0.0;
  double inertia() const { return mass * length * length / 12; }
  double pivot_inertia() const { return inertia() + mass * hinge * hinge; }
  VecX q(double phi) const;
  VecX qd(double phi, double w) const;
  double angular_acceleration(double phi) const;
  /// Centroid acceleration hinge (phi_ddot I~ u - phi_dot^2 u), u = (cos phi, sin phi).
  Vec2 centroid_acceleration(double phi, double w) const;
};

Pendulum rod_pendulum(double mass, double length, double hinge, double torque = 0.0);

/// (phi, phi_dot) at t_end from (phi0, w0) at 0: the pendulum's one minimal-coordinate ODE
/// integrated by the test's own RK4 with steps of at most 1e-4 s (error far below 1e-10).
Vec2 pendulum_reference(const Pendulum& p, double phi0, double w0, double t_end);

/// Complete elliptic integral of the first kind K(k) = int_0^{pi/2} dtheta / sqrt(1 - k^2 sin^2),
/// by the arithmetic-geometric mean: K(k) = pi / (2 AGM(1, sqrt(1 - k^2))).
double elliptic_K(double k);

/// Exact period of the pendulum swinging with amplitude theta0 about the hanging position:
/// 4 sqrt(I_O / (m g hinge)) K(sin(theta0 / 2)); its small-angle limit is 2 pi sqrt(I_O / (m g hinge)).
double pendulum_period(const Pendulum& p, double theta0);
double small_angle_period(const Pendulum& p);

/// Times at which coordinate k of a trajectory crosses `level` (either direction), by cubic
/// Hermite interpolation of (q_k, qd_k) between recorded points and bisection.
std::vector<double> crossing_times(const Trajectory& s, int k, double level);

// ---- double pendulum: two uniform rods hinged end to end -----------------------------------
//
// Rod 1 (m1, L1) turns about the ground point O = (0, 0) at its end; rod 2 (m2, L2) is hinged
// to the free end of rod 1. Angles phi1, phi2 are absolute. Centroids:
//   c1 = L1/2 u(phi1),  c2 = L1 u(phi1) + L2/2 u(phi2).

struct DoublePendulum {
  Model model;
  double m1 = 1.0, L1 = 1.0, m2 = 1.0, L2 = 1.0;
  VecX q(double phi1, double phi2) const;
  VecX qd(double phi1, double phi2, double w1, double w2) const;
};

DoublePendulum double_pendulum(double m1, double L1, double m2, double L2);

// ---- four-bar (examples::four_bar, undriven) at a closed-form configuration ------------------

examples::FourBarParameters four_bar_parameters(double a, double b, double c, double d);

/// Configuration of the four-bar at crank angle theta (open branch), centroids mid-link.
VecX four_bar_q(const examples::FourBarParameters& p, double theta);

// ---- linear test ODE y' = A y with a closed-form solution -----------------------------------
//
// A = [[-a, -w, 0], [w, -a, 0], [0, 0, -c]]: a damped rotation and a decay, so
// exp(A t) y0 = (e^{-a t} R(w t) y0_xy, e^{-c t} y0_z).

struct LinearOde {
  double a = 0.3, w = 2.0, c = 0.7;
  VecX y0 = vec({1.0, 0.5, -0.8});
  MatX A() const;
  OdeRhs rhs() const;
  VecX exact(double t, const VecX& y_start) const;
  VecX exact(double t) const { return exact(t, y0); }
};

/// A one-step method as a plain function: euler_step, rk4_step, or the y of dormand_prince_step.
using StepFunction = std::function<VecX(const OdeRhs&, double, const VecX&, double)>;

/// The student's euler_step and rk4_step, through their given forms that return y_new.
StepFunction euler_method();
StepFunction rk4_method();
StepFunction dormand_prince_solution();

/// One Dormand-Prince step written out from the tableau of integrators.hpp: both solutions.
struct TableauStep {
  VecX y5, y4;
};
TableauStep dormand_prince_by_tableau(const OdeRhs& f, double t, const VecX& y, double h);

/// N fixed steps of `step` from (t0, y0) to t_end.
VecX integrate(const StepFunction& step, const OdeRhs& f, double t0, const VecX& y0, double t_end, int N);

// ---- hints ----------------------------------------------------------------------------------

/// Ratio of successive errors e(h) / e(h/2) of a method of order p: about 2^p.
double ratio(double coarse, double fine);

// ---- T1: both rows of eq. (3) -------------------------------------------------------------

/// Checks both rows of eq. (3) for the result of forward_dynamics(model, q, qd, t).
void check_augmented_rows(const Model& model, const VecX& q, const VecX& qd, double t);

// ---- T4: projections ----------------------------------------------------------------------

/// Projects q = (a consistent point + a small random offset) and checks C = 0 and that the
/// correction is the minimum M-norm one (M-orthogonal to the null space of C_q, and no feasible
/// point nearby is closer to q in the M-norm).
void check_position_projection(const Model& model, const VecX& q_exact, double t, Random& rnd);

/// Projects arbitrary velocities qd at consistent positions q and checks C_q qd_proj + C_t = 0 and
/// that the correction is the minimum M-norm one.
void check_velocity_projection(const Model& model, const VecX& q, const VecX& qd, double t);

}  // namespace fmbd::testing::m04
