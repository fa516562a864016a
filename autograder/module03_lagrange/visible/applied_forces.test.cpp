// Module 3, tasks T2 and T3: generalised forces of gravity, point forces and spring-dampers by
// virtual work and as gradients of their potentials (visible tests).
#include <cmath>
#include <string>

#include "dynamics_checks.hpp"
#include "fmbd/applied_forces.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m03;

namespace {

VecX stack(const Vec3& a, const Vec3& b) {
  VecX v(6);
  v << a, b;
  return v;
}
VecX stack(const PairForces& f) { return stack(f.Q_i, f.Q_j); }

// Generalised force of the global force F at the point s of a body at q_i, for the hints.
Vec3 generalised(const Vec2& F, double moment) { return Vec3(F.x(), F.y(), moment); }

// Hint for a wrong point_force: which slip reproduces `actual`.
std::string point_hint(const Vec3& q_i, const Vec2& s, const Vec2& F, Frame frame, const Vec3& actual) {
  const double phi = q_i(2);
  const Vec2 Fg = frame == Frame::global ? F : rotate(phi, F);
  const Vec2 As = rotate(phi, s);
  const char* moment = "Q_phi = (A_i I~ s_i)^T F_global = (A_i s_i) x F_global";
  std::vector<Suspect> suspects = {
      {with_formula("your Q_phi is 0: moment term missing? It is the moment of F about the centroid", moment),
       generalised(Fg, 0.0)},
      {with_formula("your Q_phi: A where A I~ belongs?", moment), generalised(Fg, As.dot(Fg))},
      {with_formula("your Q_phi has the wrong sign (moment sign)", moment), generalised(Fg, -cross(As, Fg))},
      {with_formula("your Q_phi is the moment of F about the global origin instead of the centroid: the arm is "
                    "A_i s_i, not r_P", moment),
       generalised(Fg, cross(point_at(q_i, s), Fg))}};
  if (frame == Frame::body) {
    suspects.push_back({"your force for Frame::body: body-frame force not rotated? Turn it into the global frame "
                        "by A_i",
                        generalised(F, cross(As, F))});
    const Vec2 back = rotate(-phi, F);
    suspects.push_back({"your force for Frame::body is turned by A_i^T: turn it from the body frame into the global "
                        "one, by A_i",
                        generalised(back, cross(As, back))});
  } else {
    const Vec2 turned = rotate(phi, F);
    suspects.push_back({"your force for Frame::global is turned by A_i: a global force is not rotated",
                        generalised(turned, cross(As, turned))});
  }
  const Vec3 expected = generalised(Fg, cross(As, Fg));
  return diagnose(actual, expected, suspects,
                  with_formula("your point force is not the generalised force of F at the point (F turned into the "
                               "global frame for Frame::body)",
                               "Q_i = (dr_P/dq_i)^T F_global = (F_x, F_y, (A_i I~ s_i)^T F_global)"));
}

// Gradient of the work F^T r_P(q) of a constant global force F: the generalised force.
Vec3 work_gradient(const Vec3& q_i, const Vec2& s, const Vec2& F) {
  auto W = [&](const VecX& x) { return vec({F.dot(point_at(x, s))}); };
  return finite_difference_jacobian(W, VecX(q_i)).transpose();
}

// Q^T dq against the work F^T dr_P of small random virtual displacements dq (central).
void check_virtual_work(Random& rnd, const Vec3& Q, const Vec3& q_i, const Vec2& s, const Vec2& Fg,
                        const std::string& hint) {
  for (int k = 0; k < 3; ++k) {
    const Vec3 dq = 1e-5 * rnd.vec3(-1, 1);
    const double work = Fg.dot(point_at(q_i + dq, s) - point_at(q_i - dq, s)) / 2;
    CHECK_NEAR_NAMED("the virtual work of your Q (per 1e-5 of dq)", Q.dot(dq) / 1e-5, work / 1e-5,
                     (Tolerance{1e-8, 1e-7}), hint);
  }
}

// Spring-damper hint: slips of the direction, the rate L_dot and the actuator.
std::string tsda_hint(const VecX& actual, const VecX& expected, const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i,
                      const Vec3& q_j, const Vec3& qd_j, const Vec2& s_j, double k, double L0, double c, double f_a) {
  const Vec2 d = point_at(q_j, s_j) - point_at(q_i, s_i);
  const Vec2 dd = velocity_at(q_j, qd_j, s_j) - velocity_at(q_i, qd_i, s_i);
  const double L = d.norm();
  const Vec2 u = d / L;
  auto with_tension = [&](double f) {
    return stack(jacobian_at(q_i, s_i).transpose() * (f * u), jacobian_at(q_j, s_j).transpose() * (-f * u));
  };
  const double spring = k * (L - L0), L_dot = u.dot(dd);
  VecX no_moment = with_tension(spring + c * L_dot + f_a);
  no_moment(2) = no_moment(5) = 0.0;
  return diagnose(
      actual, expected,
      {{with_formula("your TSDA force: force direction flipped? A stretched spring (L > L0) pulls the points "
                     "together", "+f u on P_i, -f u on P_j, u = d / L from P_i to P_j"),
        -expected},
       {with_formula("your TSDA damping: |d_dot| instead of u^T d_dot? The damper acts on the rate of the length, "
                     "which has a sign", kTensionFormula),
        with_tension(spring + c * dd.norm() + f_a)},
       {with_formula("your TSDA tension: actuator f_a missing?", kTensionFormula), with_tension(spring + c * L_dot)},
       {with_formula("your TSDA tension: actuator sign? A positive f_a pulls the points together", kTensionFormula),
        with_tension(spring + c * L_dot - f_a)},
       {with_formula("your TSDA tension: damping missing?", kTensionFormula), with_tension(spring + f_a)},
       {"your TSDA force: moment terms missing? Turn the force at each point into a generalised force with "
        "(dr_P/dq)^T",
        no_moment}},
      with_formula("your TSDA force is not the tension along the line of its points, as generalised forces of both "
                   "bodies",
                   "f = k (L - L0) + c L_dot + f_a; Q_i = (dr_Pi/dq_i)^T (f u), Q_j = (dr_Pj/dq_j)^T (-f u)"));
}

// A random pair of bodies and points with the points at least 0.2 apart.
struct PairCase {
  Vec3 q_i, q_j, qd_i, qd_j;
  Vec2 s_i, s_j;
  double L = 0;
};
PairCase random_pair(Random& rnd) {
  PairCase p;
  do {
    p.q_i = rnd.vec3(-1, 1);
    p.q_j = rnd.vec3(-1, 1);
    p.s_i = rnd.vec2(-0.5, 0.5);
    p.s_j = rnd.vec2(-0.5, 0.5);
    p.L = (point_at(p.q_j, p.s_j) - point_at(p.q_i, p.s_i)).norm();
  } while (p.L < 0.2);
  p.qd_i = rnd.vec3(-2, 2);
  p.qd_j = rnd.vec3(-2, 2);
  return p;
}

}  // namespace

// ---- T2 ----------------------------------------------------------------------------------------

GRADED_TEST("gravity_force is minus the gradient of the gravity potential", "[M03][T2][points=1]") {
  Random rnd(3201);
  for (int k = 0; k < 10; ++k) {
    const double m = rnd.uniform(0.1, 10);
    const Vec2 g = rnd.vec2(-10, 10);
    const Vec3 q = rnd.vec3(-2, 2);
    auto V = [&](const VecX& x) { return vec({-m * g.dot(x.head<2>())}); };
    const Vec3 expected = -finite_difference_jacobian(V, VecX(q)).transpose();
    const Vec3 Q = gravity_force(m, g);
    CAPTURE(m, g.transpose());
    CHECK_CLOSE_NAMED(
        "your Q", Q, expected, kFD,
        diagnose(Q, expected,
                 {{"your gravity force has the wrong sign (gravity sign): the weight m g points along g", -expected},
                  {"your gravity force is g, not the weight m g", Vec3(g.x(), g.y(), 0.0)}},
                 with_formula("your gravity force is wrong: the weight acts at the centroid, with no moment",
                              "Q = (m g_x, m g_y, 0)")));
  }
}

GRADED_TEST("point_force in the global frame does the virtual work of F at its point", "[M03][T2][points=2]") {
  Random rnd(3202);
  for (int k = 0; k < 20; ++k) {
    const Vec3 q_i = rnd.vec3(-2, 2);
    const Vec2 s = rnd.vec2(-1, 1), F = rnd.vec2(-5, 5);
    CAPTURE(q_i.transpose(), s.transpose(), F.transpose());
    const Vec3 Q = point_force(q_i, s, F, Frame::global);
    const std::string hint = point_hint(q_i, s, F, Frame::global, Q);
    CHECK_CLOSE_NAMED("your Q", Q, work_gradient(q_i, s, F), kFD, hint);
    check_virtual_work(rnd, Q, q_i, s, F, hint);
  }
}

GRADED_TEST("point_force in the body frame turns with the body", "[M03][T2][points=1]") {
  Random rnd(3203);
  for (int k = 0; k < 20; ++k) {
    const Vec3 q_i = rnd.vec3(-2, 2);
    const Vec2 s = rnd.vec2(-1, 1), F = rnd.vec2(-5, 5);
    const Vec2 Fg = rotate(q_i(2), F);  // the force in the global frame at this configuration
    CAPTURE(q_i.transpose(), s.transpose(), F.transpose());
    const Vec3 Q = point_force(q_i, s, F, Frame::body);
    const std::string hint = point_hint(q_i, s, F, Frame::body, Q);
    CHECK_CLOSE_NAMED("your Q", Q, work_gradient(q_i, s, Fg), kFD, hint);
    check_virtual_work(rnd, Q, q_i, s, Fg, hint);
  }
}

// ---- T3 ----------------------------------------------------------------------------------------

GRADED_TEST("tsda_force spring force is minus the gradient of the spring potential", "[M03][T3][points=1]") {
  Random rnd(3301);
  for (int n = 0; n < 12; ++n) {
    const PairCase p = random_pair(rnd);
    const double k = rnd.uniform(10, 100), L0 = p.L * (n % 2 == 0 ? rnd.uniform(0.3, 0.8) : rnd.uniform(1.2, 1.7));
    auto V = [&](const VecX& x) {
      const double L = (point_at(x.segment<3>(3), p.s_j) - point_at(x.head<3>(), p.s_i)).norm();
      return vec({0.5 * k * (L - L0) * (L - L0)});
    };
    const VecX expected = -finite_difference_jacobian(V, stack(p.q_i, p.q_j)).transpose();
    const VecX actual = stack(tsda_force(p.q_i, p.qd_i, p.s_i, p.q_j, p.qd_j, p.s_j, k, L0, 0.0, 0.0));
    CAPTURE(n, p.L, L0, k);
    const std::string hint =
        tsda_hint(actual, expected, p.q_i, p.qd_i, p.s_i, p.q_j, p.qd_j, p.s_j, k, L0, 0.0, 0.0);
    CHECK_CLOSE_NAMED("your tsda_force (Q_i, Q_j)", actual, expected, kFD, hint);
    // A stretched spring pulls P_i towards P_j, a compressed one pushes it away.
    const Vec2 u = (point_at(p.q_j, p.s_j) - point_at(p.q_i, p.s_i)) / p.L;
    INFO("hint: force direction flipped? A stretched spring (L > L0) pulls P_i towards P_j: the force on P_i is +f u");
    CHECK(((p.L > L0) == (actual.head<2>().dot(u) > 0)));
  }
}

GRADED_TEST("tsda_force damper and actuator act along the line with the rate L_dot", "[M03][T3][points=1]") {
  Random rnd(3302);
  for (int n = 0; n < 12; ++n) {
    const PairCase p = random_pair(rnd);
    const double k = rnd.uniform(0, 50), L0 = p.L * rnd.uniform(0.5, 1.5), c = rnd.uniform(1, 10);
    const double f_a = rnd.uniform(-20, 20);
    // L_dot by central differences of L along the motion q + tau q_dot.
    auto length = [&](double tau) {
      return vec({(point_at(p.q_j + tau * p.qd_j, p.s_j) - point_at(p.q_i + tau * p.qd_i, p.s_i)).norm()});
    };
    const double L_dot = finite_difference_first(length, 0.0, 1e-6)(0);
    const Vec2 u = (point_at(p.q_j, p.s_j) - point_at(p.q_i, p.s_i)) / p.L;
    const double f = k * (p.L - L0) + c * L_dot + f_a;
    // The force f u at P_i and -f u at P_j as generalised forces: gradients of their work.
    const VecX expected = stack(work_gradient(p.q_i, p.s_i, f * u), work_gradient(p.q_j, p.s_j, -f * u));
    const VecX actual = stack(tsda_force(p.q_i, p.qd_i, p.s_i, p.q_j, p.qd_j, p.s_j, k, L0, c, f_a));
    CAPTURE(n, p.L, L0, k, c, f_a, L_dot);
    CHECK_CLOSE_NAMED("your tsda_force (Q_i, Q_j)", actual, expected, kFD,
                      tsda_hint(actual, expected, p.q_i, p.qd_i, p.s_i, p.q_j, p.qd_j, p.s_j, k, L0, c, f_a));
  }
}

GRADED_TEST("tsda_force obeys Newton's third law", "[M03][T3][points=1]") {
  Random rnd(3303);
  for (int n = 0; n < 12; ++n) {
    const PairCase p = random_pair(rnd);
    const double k = rnd.uniform(0, 50), L0 = p.L * rnd.uniform(0.5, 1.5), c = rnd.uniform(0, 10);
    const double f_a = rnd.uniform(-20, 20);
    const PairForces Q = tsda_force(p.q_i, p.qd_i, p.s_i, p.q_j, p.qd_j, p.s_j, k, L0, c, f_a);
    const Vec2 Fi = Q.Q_i.head<2>(), Fj = Q.Q_j.head<2>();
    const Vec2 d = point_at(p.q_j, p.s_j) - point_at(p.q_i, p.s_i);
    CAPTURE(n);
    CHECK_CLOSE_NAMED("the sum of your forces on P_i and P_j", Fi + Fj, Vec2::Zero(), (Tolerance{1e-10, 0}),
                      "your forces on P_i and P_j are not opposite: +f u on body i, -f u on body j");
    CHECK_NEAR_NAMED("the part of your force across the line P_i -> P_j", cross(d, Fi), 0.0, (Tolerance{1e-10, 0}),
                     with_formula("your force does not act along the line P_i -> P_j", "u = d / |d|"));
    // Moments about the global origin: Q_phi is the moment about the centroid R.
    const double total = Q.Q_i(2) + cross(p.q_i.head<2>(), Fi) + Q.Q_j(2) + cross(p.q_j.head<2>(), Fj);
    CHECK_NEAR_NAMED(
        "the total moment of your two forces about the origin", total, 0.0, (Tolerance{1e-10, 0}),
        with_formula("your moments of the two forces do not cancel, though the forces are collinear: check "
                     "the phi entries of both bodies",
                     "(A I~ s)^T F"));
  }
}

GRADED_TEST("rsda_force is minus the gradient of 1/2 k theta^2 plus damping and actuator", "[M03][T3][points=1]") {
  Random rnd(3304);
  for (int n = 0; n < 10; ++n) {
    const Vec3 q_i = rnd.vec3(-2, 2), q_j = rnd.vec3(-2, 2), qd_i = rnd.vec3(-2, 2), qd_j = rnd.vec3(-2, 2);
    const double k = rnd.uniform(1, 50), theta0 = rnd.uniform(-1, 1), c = rnd.uniform(0.5, 5), T_a = rnd.uniform(-5, 5);
    auto V = [&](const VecX& x) {
      const double dtheta = x(5) - x(2) - theta0;
      return vec({0.5 * k * dtheta * dtheta});
    };
    const VecX spring = -finite_difference_jacobian(V, stack(q_i, q_j)).transpose();
    const double rest = c * (qd_j(2) - qd_i(2)) + T_a;  // damping and actuator: +T on i, -T on j
    const VecX expected = spring + stack(Vec3(0, 0, rest), Vec3(0, 0, -rest));
    const VecX actual = stack(rsda_force(q_i, qd_i, q_j, qd_j, k, theta0, c, T_a));
    const double theta_swapped = q_i(2) - q_j(2);
    const double T_swapped = k * (theta_swapped - theta0) + c * (qd_i(2) - qd_j(2)) + T_a;
    const std::string hint = diagnose(
        actual, expected,
        {{with_formula("your RSDA torque sign? It acts +T on body i and -T on body j", kTorqueFormula), -expected},
         {with_formula("your RSDA angle is phi_i - phi_j, not phi_j - phi_i", kTorqueFormula),
          stack(Vec3(0, 0, T_swapped), Vec3(0, 0, -T_swapped))}},
        with_formula("your RSDA torque is not the spring, damper and actuator torque on the relative angle",
                     kTorqueFormula));
    CAPTURE(n);
    CHECK_CLOSE_NAMED("your rsda_force (Q_i, Q_j)", actual, expected, kFD, hint);
    const VecX spring_only = stack(rsda_force(q_i, qd_i, q_j, qd_j, k, theta0, 0.0, 0.0));
    CHECK_CLOSE_NAMED("your rsda_force with the spring alone", spring_only, spring, kFD, hint);
  }
}
