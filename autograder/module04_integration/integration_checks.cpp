// Definitions of the module 4 checks (see integration_checks.hpp), compiled once per build.
#include "integration_checks.hpp"

#include "linear_algebra.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace fmbd::testing::m04 {

namespace {

// A point with C(q, t) = 0 near q, by Gauss-Newton steps of minimum Euclidean norm
// (dq = -C_q^T (C_q C_q^T)^-1 C), module 1's C and C_q only.
VecX feasible_point_near(const Model& model, VecX q, double t) {
  for (int k = 0; k < 50; ++k) {
    const ConstraintEvaluation e = evaluate_constraints(model, q, t);
    if (e.C.norm() < 1e-14) break;
    const MatX JJt = e.Cq * e.Cq.transpose();
    q -= e.Cq.transpose() * solve_symmetric(JJt, e.C);
  }
  return q;
}

// |a^T M b| / (|a|_M |b|_M): 0 when a and b are M-orthogonal.
double m_cosine(const MatX& M, const VecX& a, const VecX& b) {
  const double na = std::sqrt(a.dot(M * a)), nb = std::sqrt(b.dot(M * b));
  if (na == 0 || nb == 0) return 0.0;
  return std::abs(a.dot(M * b)) / (na * nb);
}

// Largest |cosine| in the M inner product between `correction` and the columns of `N`.
double worst_m_cosine(const MatX& M, const VecX& correction, const MatX& N) {
  double worst = 0;
  for (Eigen::Index k = 0; k < N.cols(); ++k) worst = std::max(worst, m_cosine(M, correction, N.col(k)));
  return worst;
}

std::string minimum_m_norm() {
  return with_formula("your correction q_proj - q is not the one of minimum M-norm: it must be M-orthogonal to every "
                      "feasible direction (the null space of C_q); use M = mass_matrix(model, q), not the identity",
                      "[M C_q^T; C_q 0] (dq; mu) = (0; -C)");
}

}  // namespace

// ---- plain planar formulas (not the student's) ------------------------------------------

Vec2 unit(double phi) { return Vec2(std::cos(phi), std::sin(phi)); }
Vec2 perp(const Vec2& v) { return Vec2(-v.y(), v.x()); }  // I~ v
Vec2 rotate(double phi, const Vec2& s) { return s.x() * unit(phi) + s.y() * perp(unit(phi)); }

MatX mass_matrix_of(const Model& model) {
  MatX M = MatX::Zero(model.num_coordinates(), model.num_coordinates());
  for (int k = 0; k < model.num_bodies(); ++k) {
    const Body& b = model.bodies()[k];
    M(3 * k, 3 * k) = b.mass;
    M(3 * k + 1, 3 * k + 1) = b.mass;
    M(3 * k + 2, 3 * k + 2) = b.inertia;
  }
  return M;
}

double gravity_energy_of(const Model& model, const VecX& q, const VecX& qd) {
  double E = 0;
  for (int k = 0; k < model.num_bodies(); ++k) {
    const Body& b = model.bodies()[k];
    E += 0.5 * (b.mass * qd.segment<2>(3 * k).squaredNorm() + b.inertia * qd(3 * k + 2) * qd(3 * k + 2));
    E -= b.mass * model.gravity().dot(q.segment<2>(3 * k));
  }
  return E;
}

MatX null_space(const MatX& Cq) {
  return fmbd::testing::null_space(Cq, 1e-10);
}

// ---- pendulum ---------------------------------------------------------------------------------

VecX Pendulum::q(double phi) const {
  const Vec2 c = hinge * unit(phi);
  return vec({c.x(), c.y(), phi});
}
VecX Pendulum::qd(double phi, double w) const {
  const Vec2 v = hinge * w * perp(unit(phi));
  return vec({v.x(), v.y(), w});
}
double Pendulum::angular_acceleration(double phi) const {
  return (torque - mass * kG * hinge * std::cos(phi)) / pivot_inertia();
}
Vec2 Pendulum::centroid_acceleration(double phi, double w) const {
  return hinge * (angular_acceleration(phi) * perp(unit(phi)) - w * w * unit(phi));
}

Pendulum rod_pendulum(double mass, double length, double hinge, double torque) {
  Pendulum p;
  p.mass = mass;
  p.length = length;
  p.hinge = hinge;
  p.torque = torque;
  Model& m = p.model;
  m.set_gravity(Vec2(0.0, -kG));
  const VecX q0 = p.q(0.3);
  const BodyId rod = m.add_body("rod", mass, p.inertia(), q0.head<3>());
  const PointId O = m.add_point(ground, Vec2::Zero(), "O");
  const PointId P = m.add_point(rod, Vec2(-hinge, 0.0), "rod hinge");
  m.add_revolute("pivot", O, P);
  if (torque != 0.0) m.add_torque("motor", rod, DriveFunction::constant(torque));
  return p;
}

Vec2 pendulum_reference(const Pendulum& p, double phi0, double w0, double t_end) {
  auto f = [&](const Vec2& y) {
    return Vec2(y(1), (p.torque - p.mass * kG * p.hinge * std::cos(y(0))) / p.pivot_inertia());
  };
  const int steps = static_cast<int>(std::ceil(t_end / 1e-4));
  const double h = t_end / steps;
  Vec2 y(phi0, w0);
  for (int k = 0; k < steps; ++k) {
    const Vec2 a = f(y), b = f(y + h / 2 * a), c = f(y + h / 2 * b), d = f(y + h * c);
    y += h / 6 * (a + 2 * b + 2 * c + d);
  }
  return y;
}

double elliptic_K(double k) {
  double a = 1.0, b = std::sqrt(1.0 - k * k);
  for (int i = 0; i < 40 && std::abs(a - b) > 1e-16 * a; ++i) {
    const double next = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = next;
  }
  return kPi / (2 * a);
}

double pendulum_period(const Pendulum& p, double theta0) {
  return 4 * std::sqrt(p.pivot_inertia() / (p.mass * kG * p.hinge)) * elliptic_K(std::sin(theta0 / 2));
}

double small_angle_period(const Pendulum& p) {
  return 2 * kPi * std::sqrt(p.pivot_inertia() / (p.mass * kG * p.hinge));
}

std::vector<double> crossing_times(const Trajectory& s, int k, double level) {
  std::vector<double> times;
  for (std::size_t i = 1; i < s.t.size() && i < s.q.size() && i < s.qd.size(); ++i) {
    const double t0 = s.t[i - 1], t1 = s.t[i], h = t1 - t0;
    const double y0 = s.q[i - 1](k) - level, y1 = s.q[i](k) - level;
    const double d0 = s.qd[i - 1](k) * h, d1 = s.qd[i](k) * h;
    if (!(y0 < 0 && y1 >= 0) && !(y0 > 0 && y1 <= 0)) continue;
    auto hermite = [&](double x) {
      const double x2 = x * x, x3 = x2 * x;
      return (2 * x3 - 3 * x2 + 1) * y0 + (x3 - 2 * x2 + x) * d0 + (-2 * x3 + 3 * x2) * y1 + (x3 - x2) * d1;
    };
    double lo = 0, hi = 1;
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      if ((hermite(mid) < 0) == (y0 < 0)) lo = mid; else hi = mid;
    }
    times.push_back(t0 + 0.5 * (lo + hi) * h);
  }
  return times;
}

// ---- double pendulum ----------------------------------------------------------------------------

VecX DoublePendulum::q(double phi1, double phi2) const {
  const Vec2 c1 = L1 / 2 * unit(phi1), c2 = L1 * unit(phi1) + L2 / 2 * unit(phi2);
  return vec({c1.x(), c1.y(), phi1, c2.x(), c2.y(), phi2});
}
VecX DoublePendulum::qd(double phi1, double phi2, double w1, double w2) const {
  const Vec2 v1 = L1 / 2 * w1 * perp(unit(phi1));
  const Vec2 v2 = L1 * w1 * perp(unit(phi1)) + L2 / 2 * w2 * perp(unit(phi2));
  return vec({v1.x(), v1.y(), w1, v2.x(), v2.y(), w2});
}

DoublePendulum double_pendulum(double m1, double L1, double m2, double L2) {
  DoublePendulum d;
  d.m1 = m1;
  d.L1 = L1;
  d.m2 = m2;
  d.L2 = L2;
  Model& m = d.model;
  m.set_gravity(Vec2(0.0, -kG));
  const VecX q0 = d.q(-1.0, -0.5);
  const BodyId r1 = m.add_body("upper rod", m1, m1 * L1 * L1 / 12, q0.segment<3>(0));
  const BodyId r2 = m.add_body("lower rod", m2, m2 * L2 * L2 / 12, q0.segment<3>(3));
  const PointId O = m.add_point(ground, Vec2::Zero(), "O");
  const PointId r1_O = m.add_point(r1, Vec2(-L1 / 2, 0.0), "upper rod O");
  const PointId r1_E = m.add_point(r1, Vec2(L1 / 2, 0.0), "upper rod elbow");
  const PointId r2_E = m.add_point(r2, Vec2(-L2 / 2, 0.0), "lower rod elbow");
  m.add_revolute("shoulder", O, r1_O);
  m.add_revolute("elbow", r1_E, r2_E);
  return d;
}

// ---- four-bar -------------------------------------------------------------------------------

examples::FourBarParameters four_bar_parameters(double a, double b, double c, double d) {
  examples::FourBarParameters p;
  p.a = a;
  p.b = b;
  p.c = c;
  p.d = d;
  p.theta0 = 0.5;
  p.omega = 1.0;
  p.driven = false;
  return p;
}

VecX four_bar_q(const examples::FourBarParameters& p, double theta) {
  Vec2 C;
  if (!examples::four_bar_joint_C(p, theta, C)) return VecX::Constant(9, std::nan(""));
  const Vec2 O2 = Vec2::Zero(), O4(p.d, 0.0), B = p.a * unit(theta);
  auto link = [](const Vec2& a, const Vec2& b) {
    const Vec2 m = 0.5 * (a + b), d = b - a;
    return Vec3(m.x(), m.y(), std::atan2(d.y(), d.x()));
  };
  VecX q(9);
  q << link(O2, B), link(B, C), link(C, O4);
  q(2) = theta;
  return q;
}

// ---- linear test ODE -----------------------------------------------------------------------

MatX LinearOde::A() const {
  MatX A = MatX::Zero(3, 3);
  A << -a, -w, 0, w, -a, 0, 0, 0, -c;
  return A;
}
OdeRhs LinearOde::rhs() const {
  const MatX Am = A();
  return [Am](double, const VecX& y) { return VecX(Am * y); };
}
VecX LinearOde::exact(double t, const VecX& y_start) const {
  const Vec2 xy = std::exp(-a * t) * rotate(w * t, y_start.head<2>());
  return vec({xy.x(), xy.y(), std::exp(-c * t) * y_start(2)});
}

StepFunction euler_method() {
  return [](const OdeRhs& f, double t, const VecX& y, double h) { return euler_step(f, t, y, h); };
}

StepFunction rk4_method() {
  return [](const OdeRhs& f, double t, const VecX& y, double h) { return rk4_step(f, t, y, h); };
}

StepFunction dormand_prince_solution() {
  return [](const OdeRhs& f, double t, const VecX& y, double h) { return dormand_prince_step(f, t, y, h).y; };
}

TableauStep dormand_prince_by_tableau(const OdeRhs& f, double t, const VecX& y, double h) {
  using DP = DormandPrince;
  std::vector<VecX> k;
  for (int s = 0; s < DP::stages; ++s) {
    VecX stage = y;
    for (int r = 0; r < s; ++r) stage += h * DP::a[s][r] * k[r];
    k.push_back(f(t + DP::c[s] * h, stage));
  }
  TableauStep out{y, y};
  for (int s = 0; s < DP::stages; ++s) {
    out.y5 += h * DP::b[s] * k[s];
    out.y4 += h * DP::b_hat[s] * k[s];
  }
  return out;
}

VecX integrate(const StepFunction& step, const OdeRhs& f, double t0, const VecX& y0, double t_end, int N) {
  const double h = (t_end - t0) / N;
  VecX y = y0;
  for (int k = 0; k < N; ++k) y = step(f, t0 + k * h, y, h);
  return y;
}

// ---- hints ----------------------------------------------------------------------------------

double ratio(double coarse, double fine) { return fine > 0 ? coarse / fine : 0.0; }

// ---- T1: both rows of eq. (3) -------------------------------------------------------------

void check_augmented_rows(const Model& model, const VecX& q, const VecX& qd, double t) {
  const Accelerations a = forward_dynamics(model, q, qd, t);
  const int n = model.num_coordinates(), m = model.num_constraints();
  {
    INFO("hint: forward_dynamics returns q_ddot (n = " << n << " entries) and lambda (m = " << m
                                                         << " entries): the two parts of solve_augmented's result");
    REQUIRE(a.qdd.size() == n);
    REQUIRE(a.lambda.size() == m);
  }
  const MatX M = mass_matrix_of(model);
  const ConstraintEvaluation e = evaluate_constraints(model, q, t);
  const VecX Qa = applied_forces(model, q, qd, t);
  const VecX gamma = constraint_gamma(model, q, qd, t);
  const VecX top = M * a.qdd + e.Cq.transpose() * a.lambda;
  const VecX bottom = e.Cq * a.qdd;
  const Tolerance tol{1e-8, 1e-8};
  const char* top_row = "M q_ddot + C_q^T lambda = Q_a";
  const char* bottom_row = "C_q q_ddot = gamma";
  CHECK_CLOSE_NAMED(
      "M q_ddot + C_q^T lambda of your q_ddot and lambda", top, Qa, tol,
      diagnose(top, Qa,
               {{with_formula("your top row of (3) has the wrong sign of Q_a (sign of Q_a)", top_row), -Qa},
                {with_formula("Q_a missing from the top row of your (3): use applied_forces(model, q, qd, t)", top_row),
                 VecX::Zero(n)},
                {"your Q_a is evaluated at q_dot = 0: dampers need the actual q_dot in applied_forces(model, q, qd, t)",
                 applied_forces(model, q, VecX::Zero(n), t)}},
               with_formula("your q_ddot and lambda do not solve the top row of (3) with M = mass_matrix(model, q) "
                            "and Q_a = applied_forces(model, q, qd, t)", top_row),
               tol));
  CHECK_CLOSE_NAMED(
      "C_q q_ddot of your q_ddot", bottom, gamma, tol,
      diagnose(
          bottom, gamma,
          {{with_formula("your (3): the bottom row needs gamma = constraint_gamma(model, q, qd, t), not 0", bottom_row),
            VecX::Zero(m)},
           {with_formula("your bottom row of (3) has the wrong sign of gamma (sign of gamma): it is the acceleration "
                         "equation of module 2", bottom_row),
            -gamma},
           {"your gamma is evaluated at q_dot = 0: constraint_gamma needs the actual velocities",
            constraint_gamma(model, q, VecX::Zero(n), t)}},
          with_formula("your q_ddot does not solve the bottom row of (3) (without Baumgarte terms when alpha = beta = "
                       "0)", bottom_row),
          tol));
}

// ---- T4: projections ----------------------------------------------------------------------

void check_position_projection(const Model& model, const VecX& q_exact, double t, Random& rnd) {
  const VecX q = q_exact + rnd.vector(q_exact.size(), -3e-4, 3e-4);
  const VecX q_proj = project_positions(model, q, t);
  REQUIRE(q_proj.size() == q.size());
  const VecX C = constraints(model, q_proj, t);
  CHECK_CLOSE_NAMED(
      "C at your projected q", C, VecX::Zero(C.size()), (Tolerance{1e-9, 0}),
      "your project_positions stops too early: it must iterate until |C(q_proj, t)| <= options.tolerance, "
      "updating q and re-evaluating C and C_q at the new point every iteration");
  const MatX M = mass_matrix_of(model);
  const VecX dq = q_proj - q;
  const MatX N = null_space(constraint_jacobian(model, q_proj, t));
  const double cosine = worst_m_cosine(M, dq, N);
  CAPTURE(dq.norm(), cosine);
  CHECK_NEAR_NAMED("the largest M-cosine of your correction with the feasible directions", cosine, 0.0,
                   (Tolerance{1e-2, 0}), minimum_m_norm());
  // Any other feasible point nearby is farther from q in the M-norm.
  const double d_proj = std::sqrt(dq.dot(M * dq));
  for (Eigen::Index k = 0; k < N.cols(); ++k) {
    for (double sign : {-1.0, 1.0}) {
      const VecX other = feasible_point_near(model, q_proj + sign * 0.1 * dq.norm() * N.col(k), t);
      const VecX d_other = other - q;
      const double d = std::sqrt(d_other.dot(M * d_other));
      CAPTURE(k, sign, d_proj, d);
      INFO("hint: " << minimum_m_norm());
      INFO("a feasible point nearby is closer to q in the M-norm than q_proj");
      CHECK(d >= d_proj * (1 - 1e-9));
    }
  }
}

void check_velocity_projection(const Model& model, const VecX& q, const VecX& qd, double t) {
  const MatX M = mass_matrix_of(model);
  const VecX qd_proj = project_velocities(model, q, qd, t);
  REQUIRE(qd_proj.size() == qd.size());
  const ConstraintEvaluation e = evaluate_constraints(model, q, t);
  const VecX residual = e.Cq * qd_proj + e.Ct;
  CHECK_CLOSE_NAMED(
      "the velocity equation's residual at your projected q_dot", residual, VecX::Zero(residual.size()),
      (Tolerance{1e-10, 0}),
      diagnose(residual, VecX::Zero(residual.size()),
               {{"your project_velocities must satisfy the velocity equation: it returned the velocities "
                 "unchanged",
                 VecX(e.Cq * qd + e.Ct)},
                {with_formula("your project_velocities leaves out C_t (drivers depend on time)",
                              "[M C_q^T; C_q 0] (dv; mu) = (0; -(C_q q_dot + C_t)), then q_dot + dv"),
                 e.Ct}},
               with_formula("your project_velocities must satisfy the velocity equation (the constraints' rate is "
                            "zero), with one solve of the augmented matrix",
                            "C_q q_dot + C_t = 0: [M C_q^T; C_q 0] (dv; mu) = (0; -(C_q q_dot + C_t)), then "
                            "q_dot + dv"),
               Tolerance{1e-9, 0}));
  const MatX N = null_space(e.Cq);
  const double cosine = worst_m_cosine(M, qd_proj - qd, N);
  CAPTURE(cosine);
  CHECK_NEAR_NAMED(
      "the largest M-cosine of your velocity correction with the feasible directions", cosine, 0.0,
      (Tolerance{1e-8, 0}),
      "your velocity correction is not the one of minimum M-norm: it must be M-orthogonal to the null space "
      "of C_q (use M = mass_matrix(model, q) in the augmented matrix, not the identity)");
}

}  // namespace fmbd::testing::m04
