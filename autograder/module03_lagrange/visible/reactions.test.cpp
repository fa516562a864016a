// Module 3, task T5: joint reactions and driver efforts from the multipliers: Newton's third
// law, free-body diagrams of every body, and the drivers' power (visible tests). The
// multipliers come from the test's own solve of C_q^T lambda = Q_a - M q_ddot, not from T4.
#include <stdexcept>

#include "dynamics_checks.hpp"
#include "fmbd/reactions.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m03;

namespace {

// The slider-crank with every kind of load: gravity, a damped spring with an actuator, a global
// load on the slider, a follower force on the crank tip and a torque on the rod.
Model loaded_slider_crank(const examples::SliderCrankParameters& p) {
  Model m = examples::slider_crank(p);
  m.set_gravity(Vec2(0.0, -9.81));
  const PointId anchor = m.add_point(ground, Vec2(-0.05, 0.25), "spring anchor");
  const PointId rod = m.add_point(m.find_body("rod"), Vec2(0.04, 0.01), "rod spring point");
  m.add_tsda("rod spring", anchor, rod, 120.0, 0.1, 3.0, DriveFunction::harmonic(5.0, 4.0, 3.0));
  m.add_point_force("load", m.find_point("slider C"), Vec2(-30.0, 5.0));
  m.add_point_force("follower", m.find_point("crank B"), Vec2(2.0, 8.0), Frame::body);
  m.add_torque("rod torque", m.find_body("rod"), DriveFunction::harmonic(0.5, 1.0, 2.0));
  return m;
}

ArmCollar standard_arm_collar() {
  return arm_collar(0.2, DriveFunction::harmonic(0.2, 0.1, 1.5, 0.4), DriveFunction::harmonic(0.25, 0.08, 2.0, 0.3),
                    60.0, 1.5);
}

DoublePendulum standard_double_pendulum() {
  return double_pendulum(0.5, 0.4, DriveFunction::linear(0.3, 1.2), DriveFunction::harmonic(0.8, 0.5, 2.0, 0.2));
}

}  // namespace

GRADED_TEST("joint_reaction obeys Newton's third law and gives a revolute no moment", "[M03][T5][points=1]") {
  const auto p = slider_crank_parameters(0.1, 0.3, 0.3, 2.0);
  const Model sc = loaded_slider_crank(p);
  for (double t : {0.3, 1.4}) {
    const State s = state_at(sc, slider_crank_at(p, t), t);
    const VecX lambda = multipliers_of(sc, s.q, s.qd, s.qdd, t);
    CAPTURE(t);
    for (int c = 0; c < 4; ++c) check_joint_reaction(sc, c, s.q, lambda);  // O, B, C, slider guide
  }
  // A translational joint between two moving bodies transmits a moment too.
  const ArmCollar ac = standard_arm_collar();
  const State s = state_at(ac.model, ac.exact(0.7), 0.7);
  const VecX lambda = multipliers_of(ac.model, s.q, s.qd, s.qdd, s.t);
  check_joint_reaction(ac.model, 0, s.q, lambda);  // pivot (ground on side i)
  check_joint_reaction(ac.model, 1, s.q, lambda);  // collar guide
  const std::string hint = "joint_reaction is for joints and driver_effort for drivers: constraint_forces(model, c, q, "
                           "lambda, want_driver) checks it";
  const VecX q_sc = slider_crank_at(p, 0.0);
  check_throws_mentioning<std::invalid_argument>([&] { joint_reaction(sc, 4, q_sc, VecX::Zero(9)); }, "driver", hint);
  check_throws_mentioning<std::invalid_argument>([&] { driver_effort(sc, 0, q_sc, VecX::Zero(9)); }, "joint", hint);
}

GRADED_TEST("joint_reaction free-body diagram of every body balances", "[M03][T5][points=2]") {
  // m a = gravity + applied forces + joint reactions + driver efforts for each body, and
  // J phi_ddot = their moments about the centroid, with each reaction as a force at the joint
  // point plus the moment about that point.
  const auto p = slider_crank_parameters(0.1, 0.3, 0.3, 2.0);
  const Model sc = loaded_slider_crank(p);
  for (double t : {0.0, 0.5, 1.2, 2.4}) check_free_bodies(sc, state_at(sc, slider_crank_at(p, t), t));
  const auto p2 = slider_crank_parameters(0.2, 0.45, 2.0, -4.0);
  const Model sc2 = loaded_slider_crank(p2);
  for (double t : {0.1, 0.6}) check_free_bodies(sc2, state_at(sc2, slider_crank_at(p2, t), t));
  const DoublePendulum dp = standard_double_pendulum();
  for (double t : {0.2, 1.0}) check_free_bodies(dp.model, state_at(dp.model, dp.exact(t), t));
}

GRADED_TEST("driver_effort times the driven rate equals lambda^T C_t for every driver type", "[M03][T5][points=1]") {
  const auto p = slider_crank_parameters(0.1, 0.3, 0.3, 2.0);
  const Model sc = loaded_slider_crank(p);
  const DoublePendulum dp = standard_double_pendulum();
  const ArmCollar ac = standard_arm_collar();
  for (double t : {0.4, 1.3}) {
    const State s1 = state_at(sc, slider_crank_at(p, t), t);
    check_driver_effort(sc, 4, s1, multipliers_of(sc, s1.q, s1.qd, s1.qdd, t));  // absolute angle
    const State s2 = state_at(dp.model, dp.exact(t), t);
    const VecX l2 = multipliers_of(dp.model, s2.q, s2.qd, s2.qdd, t);
    check_driver_effort(dp.model, 2, s2, l2);  // absolute angle
    check_driver_effort(dp.model, 3, s2, l2);  // relative angle
    const State s3 = state_at(ac.model, ac.exact(t), t);
    const VecX l3 = multipliers_of(ac.model, s3.q, s3.qd, s3.qdd, t);
    check_driver_effort(ac.model, 2, s3, l3);  // point coordinate
    check_driver_effort(ac.model, 3, s3, l3);  // distance
  }
}
