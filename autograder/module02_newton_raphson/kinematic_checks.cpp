// Definitions of the module 2 checks (see kinematic_checks.hpp), compiled once per build.
#include "kinematic_checks.hpp"

#include <cmath>
#include <initializer_list>

namespace fmbd::testing::m02 {

namespace {

// A(phi) s, written out.
Vec2 rotate(double phi, const Vec2& s) {
  const double c = std::cos(phi), n = std::sin(phi);
  return Vec2(c * s.x() - n * s.y(), n * s.x() + c * s.y());
}

bool is_angle_entry(Eigen::Index k) { return k % 3 == 2; }

// A random motion with |phi_dot| between 0.6 and 2.5 rad/s (either sign) at tau = 0.
Motion random_motion(Random& rnd) {
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

Motion ground_motion() { return Motion{}; }

// C of one constraint block as a function of the two bodies' coordinates and of tau.
using BlockFunction = std::function<VecX(const Vec3& q_i, const Vec3& q_j, double tau)>;

// gamma = C_q q_ddot - d2C/dt2 along the motions at tau = 0, both by central differences.
VecX gamma_by_differences(const BlockFunction& C, const Motion& mi, const Motion& mj) {
  const double hs = 1e-6, ht = 2e-4;
  const Vec3 qi = mi.q(), qj = mj.q(), ai = mi.qdd(), aj = mj.qdd();
  const VecX Cq_qdd = (C(qi + hs * ai, qj + hs * aj, 0.0) - C(qi - hs * ai, qj - hs * aj, 0.0)) / (2 * hs);
  const VecX d2C = (C(mi.at(ht), mj.at(ht), ht) - 2 * C(qi, qj, 0.0) + C(mi.at(-ht), mj.at(-ht), -ht)) / (ht * ht);
  return Cq_qdd - d2C;
}

VecX as_vector(const RowVector& r) { return VecX(r); }

Tolerance gamma_tolerance() { return Tolerance{2e-6, 1e-6}; }

Vec2 centripetal_term(const Vec3& q, const Vec3& qd, const Vec2& s) {
  return rotate(q(2), s) * qd(2) * qd(2);
}
Vec2 point_velocity_of(const Vec3& q, const Vec3& qd, const Vec2& s) {
  const Vec2 As = rotate(q(2), s);
  return qd.head<2>() + qd(2) * Vec2(-As.y(), As.x());
}
Vec2 perp(const Vec2& v) { return Vec2(-v.y(), v.x()); }  // I~ v

// Typical wrong driver gammas; `rest` is gamma without the drive term.
std::vector<Suspect> drive_suspects(const DriveValue& f, double rest) {
  return {{"the drive's second derivative is missing: your gamma has no term of it, but C contains the drive, so C's "
           "second time derivative does not vanish",
           vec({rest})},
          {"wrong sign of the drive's second derivative (or of gamma): your drive term has the opposite sign", vec({rest - f.fdd})},
          {"the drive's first derivative instead of its second in your gamma: the second time derivative of C has the "
           "drive's second derivative (f.fdd)", vec({rest + f.fd})}};
}

}  // namespace

// ---- plain planar formulas --------------------------------------------------------------

Vec2 body_point(const VecX& q, int body, const Vec2& s) {
  return q.segment<2>(3 * body) + rotate(q(3 * body + 2), s);
}

VecX align_angles(VecX expected, const VecX& actual) {
  if (expected.size() != actual.size()) return expected;
  for (Eigen::Index k = 0; k < expected.size(); ++k) {
    if (is_angle_entry(k) && std::isfinite(actual(k)))
      expected(k) += 2 * kPi * std::round((actual(k) - expected(k)) / (2 * kPi));
  }
  return expected;
}

VecX path_rate(const std::function<VecX(double)>& q_of_t, double t, double h) {
  VecX dq = q_of_t(t + h) - q_of_t(t - h);
  for (Eigen::Index k = 0; k < dq.size(); ++k)
    if (is_angle_entry(k)) dq(k) = std::remainder(dq(k), 2 * kPi);
  return dq / (2 * h);
}
VecX path_acceleration(const std::function<VecX(double)>& q_of_t, double t, double h) {
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

examples::SliderCrankParameters slider_crank_parameters(double r, double l, double A0, double omega) {
  examples::SliderCrankParameters p;
  p.r = r;
  p.l = l;
  p.A0 = A0;
  p.omega = omega;
  return p;
}

VecX slider_crank_exact(const examples::SliderCrankParameters& p, double A) {
  VecX q = examples::slider_crank_configuration(p, A);
  q(2) = A;
  return q;
}

VecX four_bar_configuration(const examples::FourBarParameters& p, double theta) {
  Vec2 C;
  if (!examples::four_bar_joint_C(p, theta, C)) return VecX::Constant(9, std::nan(""));
  const Vec2 O2 = Vec2::Zero(), O4(p.d, 0.0), B(p.a * std::cos(theta), p.a * std::sin(theta));
  auto link = [](const Vec2& a, const Vec2& b) {
    const Vec2 m = 0.5 * (a + b), d = b - a;
    return Vec3(m.x(), m.y(), std::atan2(d.y(), d.x()));
  };
  VecX q(9);
  q << link(O2, B), link(B, C), link(C, O4);
  q(2) = theta;  // the crank angle as the driver sees it, not wrapped
  return q;
}

examples::FourBarParameters four_bar_parameters(double a, double b, double c, double d,
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

VecX four_bar_closure(const examples::FourBarParameters& p, const VecX& q) {
  VecX e(8);
  e.segment<2>(0) = body_point(q, 0, Vec2(-p.a / 2, 0));
  e.segment<2>(2) = body_point(q, 0, Vec2(p.a / 2, 0)) - body_point(q, 1, Vec2(-p.b / 2, 0));
  e.segment<2>(4) = body_point(q, 1, Vec2(p.b / 2, 0)) - body_point(q, 2, Vec2(-p.c / 2, 0));
  e.segment<2>(6) = body_point(q, 2, Vec2(p.c / 2, 0)) - Vec2(p.d, 0.0);
  return e;
}

// ---- gamma oracle -----------------------------------------------------------------------------

Vec3 Motion::at(double tau) const {
  Vec3 q;
  for (int k = 0; k < 3; ++k) q(k) = q0(k) + a(k) * tau + b(k) * std::sin(w(k) * tau + psi(k));
  return q;
}
Vec3 Motion::qd() const {
  Vec3 v;
  for (int k = 0; k < 3; ++k) v(k) = a(k) + b(k) * w(k) * std::cos(psi(k));
  return v;
}
Vec3 Motion::qdd() const {
  Vec3 v;
  for (int k = 0; k < 3; ++k) v(k) = -b(k) * w(k) * w(k) * std::sin(psi(k));
  return v;
}

// ---- hints ----------------------------------------------------------------------------------

std::string velocity_hint(const VecX& actual, const VecX& expected) {
  return diagnose(actual, expected,
                  {{with_formula("your q_dot has the wrong sign: the right-hand side of your velocity equation has the wrong sign",
                                 "C_q q_dot = v = -C_t, from C_q q_dot + C_t = 0"),
                    -expected},
                   {"your q_dot is 0: the right-hand side of the velocity equation is not 0 (drivers depend on time)",
                    VecX::Zero(expected.size())}},
                  with_formula("your q_dot does not solve the velocity equation with C_q and C_t from "
                               "evaluate_constraints(model, q, t)", "C_q q_dot = -C_t"),
                  Tolerance{1e-6, 1e-6});
}

Model every_constraint_model() {
  Model m;
  const BodyId a = m.add_body("a", 1, 1), b = m.add_body("b", 1, 1);
  const auto point = [&m](BodyId body, double x, double y, const char* name) { return m.add_point(body, Vec2(x, y), name); };
  m.add_revolute("ground-a", point(ground, 0.4, -0.2, "g1"), point(a, -0.3, 0.1, "a1"));
  m.add_translational("a-b", point(a, 0.2, 0.15, "a2"), point(b, -0.1, 0.25, "b1"), Vec2(0.6, 0.8));
  m.add_fixed("b-ground", point(b, 0.3, -0.2, "b2"), point(ground, -0.5, 0.6, "g2"), 0.3);
  const DriveFunction wave = DriveFunction::harmonic(0.4, 1.3, 0.2, 0.1);
  m.add_absolute_angle_driver("a angle", a, wave);
  m.add_relative_angle_driver("a-b angle", a, b, DriveFunction::polynomial({0.2, 0.5, -0.3}));
  m.add_point_coordinate_driver("b y", point(b, 0.05, 0.3, "b3"), Axis::y, wave);
  m.add_distance_driver("ground-b cable", point(ground, 1.0, 1.0, "g3"), point(b, -0.2, -0.1, "b4"),
                        DriveFunction::polynomial({1.1, 0.3, 0.2}));
  return m;
}

bool check_gamma_assembly(const Model& model, const VecX& q, const VecX& qd, double t, VecX& out,
                          const std::string& label) {
  INFO(label << ", q = " << q.transpose() << ", q_dot = " << qd.transpose() << ", t = " << t);
  const VecX before = out;
  constraint_gamma(model, q, qd, t, out);
  const VecX rest = VecX::Zero(qd.size());
  for (const Constraint& c : model.constraints()) {
    const ConstraintMarkers markers = constraint_markers(model, c, q, qd);
    const VecX want = kernel_gamma(c, markers, t), got = out.segment(c.first_row, c.rows);
    if (compare(got, want, Tolerance{1e-12, 1e-12}).ok) continue;
    const VecX at_rest = kernel_gamma(c, constraint_markers(model, c, q, rest), t);
    std::string hint = "your gamma differs in a constraint's rows: does each constraint fill its own rows first_row .. "
                       "first_row + rows - 1 with its own gamma?";
    if (compare(got, at_rest, Tolerance{1e-12, 1e-12}).ok)
      hint = "your gamma is the one of bodies at rest: the markers need the velocities q_dot, not zeros";
    else if (got == before.segment(c.first_row, c.rows))
      hint = "your gamma kept an earlier call's value in these rows: every row of gamma must be written";
    INFO("the rows of " << c.type_name() << " '" << c.name << "', from row " << c.first_row);
    CHECK_CLOSE_NAMED("your gamma in these rows", got, want, (Tolerance{1e-12, 1e-12}), hint);
    return false;
  }
  // gamma = -(d2/ds2) C(q + s q_dot, t + s) at s = 0: the terms of C's second derivative along the
  // motion that do not multiply q_ddot (here q_ddot = 0).
  const double h = 1e-4;
  const auto C_along = [&](double s) -> VecX { return constraints(model, q + s * qd, t + s); };
  const VecX oracle = -(C_along(h) - 2 * C_along(0.0) + C_along(-h)) / (h * h);
  CHECK_CLOSE_NAMED("your gamma", out, oracle, (Tolerance{1e-5, 1e-6}),
              "your gamma differs from -d2C/dt2 along the motion q + s q_dot, t + s: if the T3 and T4 tests "
              "pass, check the rows");
  return compare(out, oracle, Tolerance{1e-5, 1e-6}).ok;
}

std::string acceleration_hint(const Model& model, const VecX& q, const VecX& qd, double t, const VecX& actual,
                              const VecX& expected) {
  std::string sign = "your q_ddot has the wrong sign of gamma: the right-hand side of the acceleration equation is "
                     "+gamma";
  try {
    const VecX gamma_true = constraint_jacobian(model, q, t) * expected;
    const VecX gamma = constraint_gamma(model, q, qd, t);
    if (compare(gamma, -gamma_true, Tolerance{1e-5, 1e-5}).ok)
      sign = with_formula("your gamma functions have the wrong sign of gamma (see the T3 and T4 tests)",
                          "gamma = -(the terms of d2C/dt2 without q_ddot)");
  } catch (...) {
    // the diagnosis is best effort
  }
  return diagnose(actual, expected,
                  {{sign, -expected},
                   {"your q_ddot is 0: the right-hand side of the acceleration equation is constraint_gamma(model, "
                    "q, qd, t)",
                    VecX::Zero(expected.size())}},
                  with_formula("your q_ddot does not solve the acceleration equation with gamma = "
                               "constraint_gamma(model, q, qd, t); if the gamma tests (T3, T4) fail, fix those first",
                               "C_q q_ddot = gamma"),
                  Tolerance{1e-5, 1e-5});
}

std::optional<NewtonResult> newton_or_fail(const Model& model, const VecX& guess, double t,
                                           const NewtonOptions& options) {
  try {
    return newton_raphson(model, guess, t, options);
  } catch (const KinematicsError& e) {
    INFO("hint: " << with_formula("your newton_raphson failed from a good guess: each step must come from the "
                                  "Jacobian solve (solve_min_norm) with C_q re-evaluated at the current iterate",
                                  "C_q dq = -C, then q += dq"));
    FAIL_CHECK("newton_raphson threw: " << e.what());
    return std::nullopt;
  }
}

// ---- gamma of each constraint type against the oracle ---------------------------------------

GammaCase random_gamma_case(Random& rnd, bool ground_i, bool ground_j) {
  GammaCase c;
  c.mi = ground_i ? ground_motion() : random_motion(rnd);
  c.mj = ground_j ? ground_motion() : random_motion(rnd);
  c.si = rnd.vec2(-0.6, 0.6);
  c.sj = rnd.vec2(-0.6, 0.6);
  c.t0 = rnd.uniform(0.0, 2.0);
  const double offset = rnd.uniform(0.6, 1.0), amplitude = rnd.uniform(0.2, 0.4);
  const double omega = rnd.uniform(1.5, 3.0), phase = rnd.uniform(0.2, 1.2);
  c.f = DriveFunction::harmonic(offset, amplitude, omega, phase);
  return c;
}

void check_revolute_gamma(const GammaCase& c) {
  const Vec2 si = c.si, sj = c.sj;
  const VecX expected = gamma_by_differences(
      [&](const Vec3& qi, const Vec3& qj, double) { return VecX(revolute_constraint(qi, si, qj, sj).C); }, c.mi, c.mj);
  const VecX actual = as_vector(revolute_gamma(c.qi(), c.qdi(), si, c.qj(), c.qdj(), sj));
  const Vec2 ci = centripetal_term(c.qi(), c.qdi(), si), cj = centripetal_term(c.qj(), c.qdj(), sj);
  const double wi = c.qdi()(2), wj = c.qdj()(2);
  const VecX g = ci - cj;
  const std::vector<Suspect> suspects = {
      {"the centripetal term is missing: your gamma is 0, but the points of turning bodies accelerate towards their "
       "centroids (a joint that does not depend on time still has a gamma)",
       VecX::Zero(2)},
      {"wrong sign of gamma: yours is the opposite of the right one (gamma collects the terms of C's second time "
       "derivative without q_ddot, with the opposite sign)",
       -g},
      {"body j's centripetal term is missing: your gamma has body i's only", VecX(ci)},
      {"body i's centripetal term is missing: your gamma has body j's only", VecX(-cj)},
      {"wrong sign of the body-j centripetal term: body j's point enters C with the opposite sign of body i's", VecX(ci + cj)},
      {"your centripetal term has the angular velocity once: differentiating the turning arm twice brings it in twice",
       VecX(rotate(c.qi()(2), si) * wi - rotate(c.qj()(2), sj) * wj)},
      {"your centripetal term is tangential, a quarter turn off: it points along the arm, towards the centroid",
       VecX(perp(ci) - perp(cj))}};
  CHECK_CLOSE_NAMED("your gamma", actual, expected, gamma_tolerance(),
              diagnose(actual, expected, suspects,
                       "your revolute gamma differs from -d2C/dt2 along the motion: check each point's centripetal term and "
                       "that body j's is subtracted (./workbook hint M02T3 for more)",
                       Tolerance{1e-5, 1e-5}));
}

void check_translational_gamma(const GammaCase& c) {
  const Vec2 si = c.si, sj = c.sj;
  const Vec2 axis = (c.sj + Vec2(0.7, 0.3)).normalized();  // a unit axis that differs per case
  const VecX expected = gamma_by_differences(
      [&](const Vec3& qi, const Vec3& qj, double) {
        return VecX(translational_constraint(qi, si, qj, sj, axis, 0.3).C);
      },
      c.mi, c.mj);
  const VecX actual = as_vector(translational_gamma(c.qi(), c.qdi(), si, c.qj(), c.qdj(), sj, axis));
  const Vec3 qi = c.qi(), qj = c.qj(), qdi = c.qdi(), qdj = c.qdj();
  const double wi = qdi(2);
  const Vec2 Aa = rotate(qi(2), axis), n = perp(Aa);
  const Vec2 d = qj.head<2>() + rotate(qj(2), sj) - qi.head<2>() - rotate(qi(2), si);
  const Vec2 dd = point_velocity_of(qj, qdj, sj) - point_velocity_of(qi, qdi, si);
  const double normal = wi * wi * n.dot(d), coriolis = 2 * wi * Aa.dot(dd);
  const double centripetal = n.dot(centripetal_term(qj, qdj, sj) - centripetal_term(qi, qdi, si));
  const double g = normal + coriolis + centripetal;
  const std::vector<Suspect> suspects = {
      {"missing Coriolis term in row 1 of your gamma: the product rule on the normal times the joint's distance "
       "vector gives a cross term of their rates",
       vec({normal + centripetal, 0})},
      {"the Coriolis term needs the factor 2: yours is half the right one (the product rule gives the cross term twice)", vec({normal + coriolis / 2 + centripetal, 0})},
      {"wrong sign of the Coriolis term in row 1 of your gamma", vec({normal - coriolis + centripetal, 0})},
      {"missing the term of the turning normal's second derivative in row 1 of your gamma",
       vec({coriolis + centripetal, 0})},
      {"the two points' centripetal terms are missing in row 1 of your gamma",
       vec({normal + coriolis, 0})},
      {"wrong sign of gamma: your row 1 is the opposite of the right one",
       vec({-g, 0})},
      {"the centripetal terms are missing: a translational joint has a non-zero gamma in row 1", VecX::Zero(2)}};
  CHECK_CLOSE_NAMED("your gamma", actual, expected, gamma_tolerance(),
              diagnose(actual, expected, suspects,
                       "your translational gamma differs from -d2C/dt2 along the motion: row 1 has three kinds of terms (the "
                       "turning normal, a cross term, the points' centripetal terms), row 2 is 0 (the angle row is linear "
                       "in q); ./workbook hint M02T3 for more",
                       Tolerance{1e-5, 1e-5}));
}

void check_fixed_gamma(const GammaCase& c) {
  const Vec2 si = c.si, sj = c.sj;
  const VecX expected = gamma_by_differences(
      [&](const Vec3& qi, const Vec3& qj, double) { return VecX(fixed_constraint(qi, si, qj, sj, -0.4).C); }, c.mi,
      c.mj);
  const VecX actual = as_vector(fixed_gamma(c.qi(), c.qdi(), si, c.qj(), c.qdj(), sj));
  const Vec2 g = centripetal_term(c.qi(), c.qdi(), si) - centripetal_term(c.qj(), c.qdj(), sj);
  const std::vector<Suspect> suspects = {
      {"the centripetal term is missing: the point rows of your fixed joint's gamma are 0, but they are the "
       "revolute joint's",
       VecX::Zero(3)},
      {"wrong sign of gamma: your rows 1-2 are the opposite of the revolute joint's", vec({-g.x(), -g.y(), 0})}};
  CHECK_CLOSE_NAMED("your gamma", actual, expected, gamma_tolerance(),
              diagnose(actual, expected, suspects,
                       "fixed gamma: rows 1-2 are the revolute gamma, row 3 (angle) is 0; 3 rows in all",
                       Tolerance{1e-5, 1e-5}));
}

void check_absolute_angle_gamma(const GammaCase& c) {
  const DriveFunction f = c.f;
  const double t0 = c.t0;
  const VecX expected = gamma_by_differences(
      [&](const Vec3& qi, const Vec3&, double tau) { return VecX(absolute_angle_constraint(qi, f(t0 + tau)).C); },
      c.mi, c.mj);
  const VecX actual = as_vector(absolute_angle_gamma(c.fv()));
  CHECK_CLOSE_NAMED("your gamma", actual, expected, gamma_tolerance(),
              diagnose(actual, expected, drive_suspects(c.fv(), 0.0), "your absolute-angle driver's gamma differs from -d2C/dt2 (1 row)",
                       Tolerance{1e-5, 1e-5}));
}

void check_relative_angle_gamma(const GammaCase& c) {
  const DriveFunction f = c.f;
  const double t0 = c.t0;
  const VecX expected = gamma_by_differences(
      [&](const Vec3& qi, const Vec3& qj, double tau) {
        return VecX(relative_angle_constraint(qi, qj, f(t0 + tau)).C);
      },
      c.mi, c.mj);
  const VecX actual = as_vector(relative_angle_gamma(c.fv()));
  CHECK_CLOSE_NAMED("your gamma", actual, expected, gamma_tolerance(),
              diagnose(actual, expected, drive_suspects(c.fv(), 0.0), "your relative-angle driver's gamma differs from -d2C/dt2 (1 row)",
                       Tolerance{1e-5, 1e-5}));
}

void check_point_coordinate_gamma(const GammaCase& c, Axis axis) {
  const DriveFunction f = c.f;
  const double t0 = c.t0;
  const Vec2 si = c.si;
  const VecX expected = gamma_by_differences(
      [&](const Vec3& qi, const Vec3&, double tau) {
        return VecX(point_coordinate_constraint(qi, si, axis, f(t0 + tau)).C);
      },
      c.mi, c.mj);
  const VecX actual = as_vector(point_coordinate_gamma(c.qi(), c.qdi(), si, axis, c.fv()));
  const int k = static_cast<int>(axis);
  const Vec2 ci = centripetal_term(c.qi(), c.qdi(), si);
  const DriveValue fv = c.fv();
  std::vector<Suspect> suspects = drive_suspects(fv, ci(k));
  suspects.push_back({"the point's centripetal term is missing: your gamma has the drive term only", vec({fv.fdd})});
  suspects.push_back({"wrong axis: your gamma takes the other component of the point's centripetal term (k = 0 for Axis::x, 1 for Axis::y)",
                      vec({ci(1 - k) + fv.fdd})});
  suspects.push_back({"wrong sign of gamma: yours is the opposite of the right one", vec({-ci(k) - fv.fdd})});
  CHECK_CLOSE_NAMED("your gamma", actual, expected, gamma_tolerance(),
              diagnose(actual, expected, suspects,
                       "your point-coordinate driver's gamma differs from -d2C/dt2 (1 row): the point's centripetal term and the "
                       "drive term",
                       Tolerance{1e-5, 1e-5}));
}

void check_distance_gamma(const GammaCase& c) {
  const DriveFunction f = c.f;
  const double t0 = c.t0;
  const Vec2 si = c.si, sj = c.sj;
  const VecX expected = gamma_by_differences(
      [&](const Vec3& qi, const Vec3& qj, double tau) {
        return VecX(distance_constraint(qi, si, qj, sj, f(t0 + tau)).C);
      },
      c.mi, c.mj);
  const VecX actual = as_vector(distance_gamma(c.qi(), c.qdi(), si, c.qj(), c.qdj(), sj, c.fv()));
  const Vec3 qi = c.qi(), qj = c.qj(), qdi = c.qdi(), qdj = c.qdj();
  const DriveValue fv = c.fv();
  const Vec2 d = qj.head<2>() + rotate(qj(2), sj) - qi.head<2>() - rotate(qi(2), si);
  const Vec2 dd = point_velocity_of(qj, qdj, sj) - point_velocity_of(qi, qdi, si);
  const double vel = -dd.squaredNorm();
  const double cen = d.dot(centripetal_term(qj, qdj, sj) - centripetal_term(qi, qdi, si));
  const double fd2 = fv.fd * fv.fd, ffdd = fv.f * fv.fdd;
  const double g = vel + cen + fd2 + ffdd;
  const std::vector<Suspect> suspects = {
      {"the square of the drive's rate is missing: the second derivative of f^2 / 2 has two terms, and your gamma lacks "
       "that one", vec({g - fd2})},
      {"the term with the drive's second derivative is missing: the second derivative of f^2 / 2 has two terms, and "
       "your gamma lacks that one", vec({g - ffdd})},
      {"missing the drive terms of the distance driver: your gamma has none of f^2 / 2's second derivative", vec({vel + cen})},
      {"the drive's second derivative alone in your distance driver's gamma: C contains f^2 / 2, not f", vec({vel + cen + fv.fdd})},
      {"wrong sign of the term of the squared relative velocity in your gamma", vec({g - 2 * vel})},
      {"the term of the squared relative velocity is missing in your gamma (the product rule on the squared "
       "distance gives it)", vec({g - vel})},
      {"the two points' centripetal terms are missing in your gamma", vec({g - cen})},
      {"wrong sign of gamma: yours is the opposite of the right one",
       vec({-g})}};
  CHECK_CLOSE_NAMED("your gamma", actual, expected, gamma_tolerance(),
              diagnose(actual, expected, suspects,
                       "your distance driver's gamma differs from -d2C/dt2 (1 row): the d_dot term, the points' centripetal "
                       "terms and the drive terms",
                       Tolerance{1e-5, 1e-5}));
}

}  // namespace fmbd::testing::m02
