#pragma once
// Shared helpers of the module 2 graded tests: exact configurations of the example
// mechanisms, finite differences along configuration paths (with angle wrap), a gamma oracle
// from the second time derivative of C along a smooth trajectory, a custom arm-and-collar
// model with a closed form, and hint diagnosis (which typical mistake matches a wrong answer).
//
// Every oracle here is independent of the student's module 2 code: it uses module 1
// functions (constraint values only), the given closed forms of examples.hpp, or plain
// formulas written out below.

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fmbd/constraints.hpp"
#include "fmbd/drive_function.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/model.hpp"
#include "fmbd/newton_raphson.hpp"
#include "grading.hpp"

namespace fmbd::testing::m02 {

inline constexpr double kPi = 3.14159265358979323846;

// ---- plain planar formulas (not the student's) ------------------------------------------

/// A(phi) s, written out.
inline Vec2 rotate(double phi, const Vec2& s) {
  const double c = std::cos(phi), n = std::sin(phi);
  return Vec2(c * s.x() - n * s.y(), n * s.x() + c * s.y());
}

/// r_P = R + A(phi) s of a point with body-frame coordinates s on body `body` of q.
inline Vec2 body_point(const VecX& q, int body, const Vec2& s) {
  return q.segment<2>(3 * body) + rotate(q(3 * body + 2), s);
}

/// Velocity R_dot + phi_dot A I~ s of that point.
inline Vec2 body_point_velocity(const VecX& q, const VecX& qd, int body, const Vec2& s) {
  const Vec2 As = rotate(q(3 * body + 2), s);
  return qd.segment<2>(3 * body) + qd(3 * body + 2) * Vec2(-As.y(), As.x());
}

inline bool is_angle_entry(Eigen::Index k) { return k % 3 == 2; }

/// Shifts the angle entries of `expected` by multiples of 2 pi to the branch of `actual`
/// (closed forms use atan2, the solvers keep angles continuous).
inline VecX align_angles(VecX expected, const VecX& actual) {
  if (expected.size() != actual.size()) return expected;
  for (Eigen::Index k = 0; k < expected.size(); ++k) {
    if (is_angle_entry(k) && std::isfinite(actual(k)))
      expected(k) += 2 * kPi * std::round((actual(k) - expected(k)) / (2 * kPi));
  }
  return expected;
}

/// Central first and second time derivatives of a configuration path q(t); the angle
/// entries of differences are wrapped to (-pi, pi], so atan2 jumps do not matter.
inline VecX path_rate(const std::function<VecX(double)>& q_of_t, double t, double h = 1e-5) {
  VecX dq = q_of_t(t + h) - q_of_t(t - h);
  for (Eigen::Index k = 0; k < dq.size(); ++k)
    if (is_angle_entry(k)) dq(k) = std::remainder(dq(k), 2 * kPi);
  return dq / (2 * h);
}
inline VecX path_acceleration(const std::function<VecX(double)>& q_of_t, double t, double h = 1e-4) {
  const VecX q0 = q_of_t(t);
  VecX dp = q_of_t(t + h) - q0, dm = q_of_t(t - h) - q0;
  for (Eigen::Index k = 0; k < dp.size(); ++k) {
    if (is_angle_entry(k)) {
      dp(k) = std::remainder(dp(k), 2 * kPi);
      dm(k) = std::remainder(dm(k), 2 * kPi);
    }
  }
  return (dp + dm) / (h * h);
}

// ---- example mechanisms ------------------------------------------------------------------

/// Slider-crank parameters with the crank angle A(t) = A0 + omega t.
inline examples::SliderCrankParameters slider_crank_parameters(double r, double l, double A0, double omega) {
  examples::SliderCrankParameters p;
  p.r = r;
  p.l = l;
  p.A0 = A0;
  p.omega = omega;
  return p;
}

/// Four-bar configuration on the open branch at crank angle theta, from the given closed
/// form of joint C; centroids mid-link, angles by atan2.
inline VecX four_bar_configuration(const examples::FourBarParameters& p, double theta) {
  Vec2 C;
  if (!examples::four_bar_joint_C(p, theta, C)) return VecX::Constant(9, std::nan(""));
  const Vec2 O2 = Vec2::Zero(), O4(p.d, 0.0), B(p.a * std::cos(theta), p.a * std::sin(theta));
  auto link = [](const Vec2& a, const Vec2& b) {
    const Vec2 m = 0.5 * (a + b), d = b - a;
    return Vec3(m.x(), m.y(), std::atan2(d.y(), d.x()));
  };
  VecX q(9);
  q << link(O2, B), link(B, C), link(C, O4);
  return q;
}

inline examples::FourBarParameters four_bar_parameters(double a, double b, double c, double d,
                                                       double theta0, double omega) {
  examples::FourBarParameters p;
  p.a = a;
  p.b = b;
  p.c = c;
  p.d = d;
  p.theta0 = theta0;
  p.omega = omega;
  return p;
}

/// Loop-closure defects of a four-bar configuration q, from the link geometry alone:
/// (O2 on crank - (0,0), B on crank - B on coupler, C on coupler - C on rocker,
///  O4 on rocker - (d, 0)), 8 entries that must all vanish.
inline VecX four_bar_closure(const examples::FourBarParameters& p, const VecX& q) {
  VecX e(8);
  e.segment<2>(0) = body_point(q, 0, Vec2(-p.a / 2, 0));
  e.segment<2>(2) = body_point(q, 0, Vec2(p.a / 2, 0)) - body_point(q, 1, Vec2(-p.b / 2, 0));
  e.segment<2>(4) = body_point(q, 1, Vec2(p.b / 2, 0)) - body_point(q, 2, Vec2(-p.c / 2, 0));
  e.segment<2>(6) = body_point(q, 2, Vec2(p.c / 2, 0)) - Vec2(p.d, 0.0);
  return e;
}

// ---- arm and collar: a custom model with a distance and a point-coordinate driver ---------
//
// An arm (pivot-to-tip length 2 h, centroid mid-arm) turns about the ground point O = (0, 0);
// a collar slides along it (translational joint, no relative rotation). The y coordinate of
// the arm tip is driven by f_y(t), the distance from O to the collar by f_d(t). Closed form:
//   phi(t) = asin(f_y / 2h),  arm centroid h (cos phi, sin phi),  collar f_d (cos phi, sin phi).

struct ArmCollar {
  Model model;
  double h = 0.2;
  DriveFunction tip_y = DriveFunction::constant(0.0);
  DriveFunction radius = DriveFunction::constant(0.0);

  VecX exact(double t) const {
    const double phi = std::asin(tip_y(t).f / (2 * h)), rho = radius(t).f;
    VecX q(6);
    q << h * std::cos(phi), h * std::sin(phi), phi, rho * std::cos(phi), rho * std::sin(phi), phi;
    return q;
  }
};

inline ArmCollar arm_collar(double h, DriveFunction tip_y, DriveFunction radius, double t_guess = 0.0) {
  ArmCollar a{Model{}, h, tip_y, radius};
  const VecX q0 = a.exact(t_guess);
  Model& m = a.model;
  const BodyId arm = m.add_body("arm", 1.0, 0.02, q0.segment<3>(0));
  const BodyId collar = m.add_body("collar", 0.5, 0.001, q0.segment<3>(3));
  const PointId O = m.add_point(ground, Vec2::Zero(), "O");
  const PointId arm_O = m.add_point(arm, Vec2(-h, 0.0), "arm pivot");
  const PointId arm_tip = m.add_point(arm, Vec2(h, 0.0), "arm tip");
  const PointId collar_c = m.add_point(collar, Vec2::Zero(), "collar centre");
  m.add_revolute("pivot", O, arm_O);
  m.add_translational("collar guide", arm_O, collar_c, Vec2::UnitX());
  m.add_point_coordinate_driver("tip height", arm_tip, Axis::y, tip_y);
  m.add_distance_driver("collar radius", O, collar_c, radius);
  return a;
}

// ---- gamma oracle ---------------------------------------------------------------------------

/// A smooth trajectory of one body, q(tau) = q0 + a tau + b sin(w tau + psi) entrywise; at
/// tau = 0 its velocity and acceleration are both non-zero. A ground side stays at zero.
struct Motion {
  Vec3 q0 = Vec3::Zero(), a = Vec3::Zero(), b = Vec3::Zero(), w = Vec3::Zero(), psi = Vec3::Zero();
  Vec3 at(double tau) const {
    Vec3 q;
    for (int k = 0; k < 3; ++k) q(k) = q0(k) + a(k) * tau + b(k) * std::sin(w(k) * tau + psi(k));
    return q;
  }
  Vec3 q() const { return at(0.0); }
  Vec3 qd() const {
    Vec3 v;
    for (int k = 0; k < 3; ++k) v(k) = a(k) + b(k) * w(k) * std::cos(psi(k));
    return v;
  }
  Vec3 qdd() const {
    Vec3 v;
    for (int k = 0; k < 3; ++k) v(k) = -b(k) * w(k) * w(k) * std::sin(psi(k));
    return v;
  }
};

/// A random motion with |phi_dot| between 0.6 and 2.5 rad/s (either sign) at tau = 0.
inline Motion random_motion(Random& rnd) {
  Motion m;
  m.q0 = Vec3(rnd.uniform(-1, 1), rnd.uniform(-1, 1), rnd.uniform(-kPi, kPi));
  m.a = rnd.vec3(-1, 1);
  m.b = rnd.vec3(0.2, 0.6);
  m.w = rnd.vec3(1.0, 3.0);
  m.psi = rnd.vec3(0.3, 1.2);  // sin and cos both clearly non-zero
  const double spin = rnd.uniform(0.6, 2.5) * (rnd.uniform(0, 1) < 0.5 ? -1.0 : 1.0);
  m.a(2) = spin - m.b(2) * m.w(2) * std::cos(m.psi(2));  // phi_dot(0) = spin
  return m;
}

inline Motion ground_motion() { return Motion{}; }

/// C of one constraint block as a function of the two bodies' coordinates and of tau.
using BlockFunction = std::function<VecX(const Vec3& q_i, const Vec3& q_j, double tau)>;

/// gamma = C_q q_ddot - d2C/dt2 along the motions, at tau = 0: C_q q_ddot as a directional
/// central difference, d2C/dt2 as a central second difference. Accurate to about 1e-7.
inline VecX gamma_by_differences(const BlockFunction& C, const Motion& mi, const Motion& mj) {
  const double hs = 1e-6, ht = 2e-4;
  const Vec3 qi = mi.q(), qj = mj.q(), ai = mi.qdd(), aj = mj.qdd();
  const VecX Cq_qdd = (C(qi + hs * ai, qj + hs * aj, 0.0) - C(qi - hs * ai, qj - hs * aj, 0.0)) / (2 * hs);
  const VecX d2C = (C(mi.at(ht), mj.at(ht), ht) - 2 * C(qi, qj, 0.0) + C(mi.at(-ht), mj.at(-ht), -ht)) / (ht * ht);
  return Cq_qdd - d2C;
}

inline VecX as_vector(const RowVector& r) { return VecX(r); }

inline Tolerance gamma_tolerance() { return Tolerance{2e-6, 1e-6}; }

// ---- hints ----------------------------------------------------------------------------------

/// A typical wrong answer and the mistake that produces it.
struct Suspect {
  std::string mistake;
  VecX value;
};

/// The mistake whose wrong answer `actual` matches (and the right answer does not), or
/// `otherwise`. Used to give a failing check a hint that names the likely mistake.
inline std::string diagnose(const VecX& actual, const VecX& expected, const std::vector<Suspect>& suspects,
                            const std::string& otherwise, Tolerance tol) {
  if (actual.size() != expected.size())
    return "wrong size: got " + std::to_string(actual.size()) + " entries, expected " +
           std::to_string(expected.size()) + " (one per constraint equation or coordinate). " + otherwise;
  for (const Suspect& s : suspects) {
    if (s.value.size() != actual.size()) continue;
    if (compare(actual, s.value, tol).ok && !compare(expected, s.value, tol).ok) return s.mistake;
  }
  return otherwise;
}

/// newton_raphson with a hint instead of an unexplained exception when it fails on a
/// problem it should solve. NotImplemented and other logic errors pass through.
inline std::optional<NewtonResult> newton_or_fail(const Model& model, const VecX& guess, double t,
                                                  const NewtonOptions& options = {}) {
  try {
    return newton_raphson(model, guess, t, options);
  } catch (const KinematicsError& e) {
    INFO("hint: newton_raphson failed from a good guess: each step must come from the Jacobian solve "
         "C_q dq = -C (solve_min_norm) with C_q re-evaluated at the current iterate, then q += dq");
    FAIL_CHECK("newton_raphson threw: " << e.what());
    return std::nullopt;
  }
}

}  // namespace fmbd::testing::m02
