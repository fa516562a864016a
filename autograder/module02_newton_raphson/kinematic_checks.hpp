#pragma once
// Shared helpers of the module 2 graded tests: exact configurations of the example
// mechanisms, finite differences along configuration paths (with angle wrap), a gamma oracle
// from the second time derivative of C along a smooth trajectory, and hint diagnosis (which
// typical mistake matches a wrong answer). Helpers of the hidden tests only are in
// hidden/kinematic_hidden_checks.hpp.
//
// Every oracle here is independent of the student's module 2 code: it uses module 1
// functions (constraint values only), the given closed forms of examples.hpp, or plain
// formulas written out below.
//
// The functions are defined in kinematic_checks.cpp, compiled once and linked into every
// graded program of the module.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fmbd/constraints.hpp"
#include "fmbd/drive_function.hpp"
#include "fmbd/drivers.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/gamma.hpp"
#include "fmbd/joints.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/model.hpp"
#include "fmbd/newton_raphson.hpp"
#include "grading.hpp"

namespace fmbd::testing::m02 {

inline constexpr double kPi = 3.14159265358979323846;

// ---- plain planar formulas (not the student's) ------------------------------------------

/// r_P = R + A(phi) s of a point with body-frame coordinates s on body `body` of q.
Vec2 body_point(const VecX& q, int body, const Vec2& s);

/// Shifts the angle entries of `expected` by multiples of 2 pi to the branch of `actual`
/// (closed forms use atan2, the solvers keep angles continuous).
VecX align_angles(VecX expected, const VecX& actual);

/// Central first and second time derivatives of a configuration path q(t); the angle
/// entries of differences are wrapped to (-pi, pi], so atan2 jumps do not matter.
VecX path_rate(const std::function<VecX(double)>& q_of_t, double t, double h = 1e-5);
VecX path_acceleration(const std::function<VecX(double)>& q_of_t, double t, double h = 1e-4);

// ---- example mechanisms ------------------------------------------------------------------

/// Slider-crank parameters with the crank angle A(t) = A0 + omega t.
examples::SliderCrankParameters slider_crank_parameters(double r, double l, double A0, double omega);

/// Slider-crank configuration at crank angle A (given closed form), with the crank angle
/// itself rather than its atan2 value, so that the driver equation phi - A(t) holds exactly.
VecX slider_crank_exact(const examples::SliderCrankParameters& p, double A);

/// Four-bar configuration on the open branch at crank angle theta, from the given closed
/// form of joint C; centroids mid-link, angles by atan2.
VecX four_bar_configuration(const examples::FourBarParameters& p, double theta);

examples::FourBarParameters four_bar_parameters(double a, double b, double c, double d, double theta0,
                                                double omega);

/// Loop-closure defects of a four-bar configuration q, from the link geometry alone:
/// (O2 on crank - (0,0), B on crank - B on coupler, C on coupler - C on rocker,
///  O4 on rocker - (d, 0)), 8 entries that must all vanish.
VecX four_bar_closure(const examples::FourBarParameters& p, const VecX& q);

// ---- gamma oracle ---------------------------------------------------------------------------

/// A smooth trajectory of one body, q(tau) = q0 + a tau + b sin(w tau + psi) entrywise; at
/// tau = 0 its velocity and acceleration are both non-zero. A ground side stays at zero.
struct Motion {
  Vec3 q0 = Vec3::Zero(), a = Vec3::Zero(), b = Vec3::Zero(), w = Vec3::Zero(), psi = Vec3::Zero();
  Vec3 at(double tau) const;
  Vec3 q() const { return at(0.0); }
  Vec3 qd() const;
  Vec3 qdd() const;
};

// ---- hints ----------------------------------------------------------------------------------

/// Hint for a wrong q_dot of solve_velocities.
std::string velocity_hint(const VecX& actual, const VecX& expected);

/// Hint for a wrong q_ddot of solve_accelerations at (q, qd, t); `expected` is the oracle.
/// A q_ddot of the opposite sign is told apart: sign flipped in the solve, or in gamma itself.
std::string acceleration_hint(const Model& model, const VecX& q, const VecX& qd, double t, const VecX& actual,
                              const VecX& expected);

// ---- gamma of the whole model (T5) ------------------------------------------------------------

/// A rigid two-body model with a joint of each type (the ground on both sides) and a driver of
/// each type, its drives all with non-zero f, f' and f''.
Model every_constraint_model();

/// Checks the student's constraint_gamma into `out` (whatever it held) at (q, q_dot, t): each
/// constraint's rows against its kernel gamma at the markers' velocities, stacked by the test,
/// and the whole against the oracle gamma = -d2/ds2 C(q + s q_dot, t + s) at s = 0 (central
/// differences of the module 1 constraints). The hint names the likely mistake (rows, the
/// markers' velocities left out, a row not written). Returns false if anything differs.
bool check_gamma_assembly(const Model& model, const VecX& q, const VecX& qd, double t, VecX& out,
                          const std::string& label);

/// newton_raphson with a hint instead of an unexplained exception when it fails on a
/// problem it should solve. NotImplemented and other logic errors pass through.
std::optional<NewtonResult> newton_or_fail(const Model& model, const VecX& guess, double t,
                                           const NewtonOptions& options = {});

// ---- gamma of each constraint type against the oracle ---------------------------------------
//
// Each check draws a random configuration and motion of the two bodies (ground sides stay at
// zero), random points, and for drivers a harmonic drive f(t) (f, f', f'' all non-zero), then
// compares the student's gamma with gamma = C_q q_ddot - d2C/dt2 of the module 1 constraint
// value along the motions, both by central differences (accurate to about 1e-7).
// On failure the hint names the typical mistake whose wrong answer matches.

struct GammaCase {
  Motion mi, mj;
  Vec2 si, sj;
  double t0 = 0.0;
  DriveFunction f = DriveFunction::constant(0.0);
  Vec3 qi() const { return mi.q(); }
  Vec3 qj() const { return mj.q(); }
  Vec3 qdi() const { return mi.qd(); }
  Vec3 qdj() const { return mj.qd(); }
  DriveValue fv() const { return f(t0); }
};

/// A random case: motions with |phi_dot| between 0.6 and 2.5 rad/s at tau = 0 (a ground side
/// stays at zero), points in [-0.6, 0.6]^2, t0 in [0, 2] and a harmonic drive.
GammaCase random_gamma_case(Random& rnd, bool ground_i, bool ground_j);

void check_revolute_gamma(const GammaCase& c);
void check_translational_gamma(const GammaCase& c);
void check_fixed_gamma(const GammaCase& c);
void check_absolute_angle_gamma(const GammaCase& c);
void check_relative_angle_gamma(const GammaCase& c);
void check_point_coordinate_gamma(const GammaCase& c, Axis axis);
void check_distance_gamma(const GammaCase& c);

}  // namespace fmbd::testing::m02
