// Module 4: a larger mechanism (hidden tests). Two crank-rocker four-bars share one balanced
// crank (5 bodies, 2 closed loops, 14 constraint rows, 1 degree of freedom), loaded by gravity,
// two spring-dampers, a rotational damper and a motor torque. Started at rest, it must keep the
// energy balance E(t) - E(0) = W(t) (W: work of the motor and the dampers, from the monitors of
// simulate) and its constraints.
#include <cmath>
#include <string>

#include "fmbd/constraints.hpp"
#include "fmbd/simulation.hpp"
#include "grading.hpp"
#include "integration_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m04;

namespace {

struct TwinFourBar {
  Model model;
  VecX q0;
};

// The intersection of the circle of radius rb about B and of radius rc about O with the larger y.
Vec2 upper_intersection(const Vec2& B, double rb, const Vec2& O, double rc) {
  const Vec2 BO = O - B;
  const double e = BO.norm();
  const double along = (rb * rb - rc * rc + e * e) / (2 * e);
  const double h = std::sqrt(std::max(0.0, rb * rb - along * along));
  const Vec2 u = BO / e;
  const Vec2 c1 = B + along * u + h * perp(u), c2 = B + along * u - h * perp(u);
  return c1.y() > c2.y() ? c1 : c2;
}

Vec3 link_between(const Vec2& a, const Vec2& b) {
  const Vec2 m = 0.5 * (a + b), d = b - a;
  return Vec3(m.x(), m.y(), std::atan2(d.y(), d.x()));
}

TwinFourBar twin_four_bar(double theta0) {
  const double a = 0.08;                          // half-length of the balanced crank
  const double b1 = 0.30, c1 = 0.22, d1 = 0.28;   // right loop: coupler, rocker, ground pivot at (d1, 0)
  const double b2 = 0.26, c2 = 0.25, d2 = 0.24;   // left loop: ground pivot at (-d2, 0)
  const Vec2 O2 = Vec2::Zero(), O4(d1, 0.0), O6(-d2, 0.0);
  const Vec2 B1 = a * unit(theta0), B2 = -B1;
  const Vec2 C1 = upper_intersection(B1, b1, O4, c1), C2 = upper_intersection(B2, b2, O6, c2);

  TwinFourBar tw;
  Model& m = tw.model;
  m.set_gravity(Vec2(0.0, -kG));
  const BodyId crank = m.add_body("crank", 0.6, 0.6 * 4 * a * a / 12, Vec3(0, 0, theta0));
  const BodyId coupler1 = m.add_body("right coupler", 1.2, 1.2 * b1 * b1 / 12, link_between(B1, C1));
  const BodyId rocker1 = m.add_body("right rocker", 0.8, 0.8 * c1 * c1 / 12, link_between(C1, O4));
  const BodyId coupler2 = m.add_body("left coupler", 1.0, 1.0 * b2 * b2 / 12, link_between(B2, C2));
  const BodyId rocker2 = m.add_body("left rocker", 0.7, 0.7 * c2 * c2 / 12, link_between(C2, O6));
  tw.q0 = VecX(15);
  tw.q0 << Vec3(0, 0, theta0), link_between(B1, C1), link_between(C1, O4), link_between(B2, C2),
      link_between(C2, O6);

  const PointId g_O2 = m.add_point(ground, O2, "O2"), g_O4 = m.add_point(ground, O4, "O4"),
                g_O6 = m.add_point(ground, O6, "O6");
  const PointId k_O2 = m.add_point(crank, Vec2::Zero(), "crank centre");
  const PointId k_B1 = m.add_point(crank, Vec2(a, 0), "crank B1"), k_B2 = m.add_point(crank, Vec2(-a, 0), "crank B2");
  const PointId u_B1 = m.add_point(coupler1, Vec2(-b1 / 2, 0), "right coupler B1");
  const PointId u_C1 = m.add_point(coupler1, Vec2(b1 / 2, 0), "right coupler C1");
  const PointId r_C1 = m.add_point(rocker1, Vec2(-c1 / 2, 0), "right rocker C1");
  const PointId r_O4 = m.add_point(rocker1, Vec2(c1 / 2, 0), "right rocker O4");
  const PointId v_B2 = m.add_point(coupler2, Vec2(-b2 / 2, 0), "left coupler B2");
  const PointId v_C2 = m.add_point(coupler2, Vec2(b2 / 2, 0), "left coupler C2");
  const PointId s_C2 = m.add_point(rocker2, Vec2(-c2 / 2, 0), "left rocker C2");
  const PointId s_O6 = m.add_point(rocker2, Vec2(c2 / 2, 0), "left rocker O6");
  m.add_revolute("O2", g_O2, k_O2);
  m.add_revolute("B1", k_B1, u_B1);
  m.add_revolute("C1", u_C1, r_C1);
  m.add_revolute("O4", r_O4, g_O4);
  m.add_revolute("B2", k_B2, v_B2);
  m.add_revolute("C2", v_C2, s_C2);
  m.add_revolute("O6", s_O6, g_O6);

  const PointId anchor1 = m.add_point(ground, Vec2(0.10, 0.45), "right anchor");
  const PointId spring1 = m.add_point(coupler1, Vec2(0.03, 0.0), "right coupler spring end");
  m.add_tsda("right spring", anchor1, spring1, 80.0, 0.20, 3.0);
  const PointId anchor2 = m.add_point(ground, Vec2(-0.15, 0.40), "left anchor");
  const PointId spring2 = m.add_point(rocker2, Vec2(0.0, 0.0), "left rocker spring end");
  m.add_tsda("left spring", anchor2, spring2, 60.0, 0.10, 2.0);
  m.add_rsda("right rocker bearing", ground, rocker1, 0.0, 0.0, 0.02);
  m.add_torque("motor", crank, DriveFunction::harmonic(0.4, 0.15, 5.0));
  return tw;
}

// Checks the energy balance and the drift of a run; `drift_tolerance` on |C| and |C_dot|.
void check_balance(const Model& model, const Trajectory& s, double drift_tolerance, const std::string& hint) {
  REQUIRE(s.t.size() > 10);
  REQUIRE(s.energy.size() == s.t.size());
  REQUIRE(s.work_done.size() == s.t.size());
  double scale = 0, worst = 0, drift = 0, velocity_drift = 0;
  for (std::size_t i = 0; i < s.t.size(); ++i) {
    scale = std::max({scale, std::abs(s.energy[i] - s.energy[0]), std::abs(s.work_done[i])});
    worst = std::max(worst, std::abs(s.energy[i] - s.energy[0] - s.work_done[i]));
    const ConstraintEvaluation e = evaluate_constraints(model, s.q[i], s.t[i]);
    drift = std::max(drift, e.C.norm());
    velocity_drift = std::max(velocity_drift, (e.Cq * s.qd[i] + e.Ct).norm());
  }
  CAPTURE(s.steps, scale, worst, drift, velocity_drift, s.q.back()(2));
  CHECK(scale > 0.05);  // the motor does real work: the crank turns
  CHECK(std::abs(s.q.back()(2) - s.q.front()(2)) > 1.0);
  CHECK_NEAR_NAMED("the largest violation of your run's energy balance, relative", worst / scale, 0.0,
                   (Tolerance{2e-4, 0}), "energy balance E(t) - E(0) = W(t) violated: " + hint);
  CHECK_NEAR_NAMED("your largest |C| in the run", drift, 0.0, (Tolerance{drift_tolerance, 0}), hint);
  CHECK_NEAR_NAMED("your largest velocity-equation residual in the run", velocity_drift, 0.0,
                   (Tolerance{drift_tolerance, 0}), hint);
}

}  // namespace

GRADED_TEST("simulate twin four-bar with springs dampers and a motor keeps the energy balance with projection",
            "[M04][T4][points=1]") {
  const TwinFourBar tw = twin_four_bar(0.7);
  SimulationOptions o;
  o.integrator = Integrator::rk4;
  o.step = 2e-3;
  o.stabilisation = Stabilisation::projection;
  const Trajectory s = simulate(tw.model, tw.q0, VecX::Zero(15), 0.0, 1.5, o);
  check_balance(tw.model, s, 1e-9,
                "RK4 with projection: forward_dynamics (T1), rk4_step (T2) and the projections (T4) must all be "
                "right; the projections move q and q_dot by minimum M-norm corrections");
}

GRADED_TEST("simulate twin four-bar with springs dampers and a motor keeps the energy balance with dormand_prince",
            "[M04][T3][points=1]") {
  const TwinFourBar tw = twin_four_bar(-0.4);
  SimulationOptions o;
  o.integrator = Integrator::dormand_prince;
  o.rtol = 1e-9;
  o.atol = 1e-11;
  o.max_step = 0.005;
  const Trajectory s = simulate(tw.model, tw.q0, VecX::Zero(15), 0.0, 1.5, o);
  check_balance(tw.model, s, 1e-6,
                "Dormand-Prince without stabilisation at rtol 1e-9: forward_dynamics (T1) and dormand_prince_step "
                "(T3) must be right");
}
