// Module 3, task T5: reactions and efforts of other models (hidden tests): a fixed joint and a
// revolute with the ground on side j in a four-bar, a translational joint between two moving
// bodies and the distance and point-coordinate drivers of an arm and collar.
#include "dynamics_checks.hpp"
#include "dynamics_hidden_checks.hpp"
#include "fmbd/reactions.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m03;

GRADED_TEST("joint_reaction four-bar with a welded bob free-body diagrams and third law", "[M03][T5][points=1]") {
  const auto p = four_bar_parameters(0.1, 0.3, 0.25, 0.3, 0.5, 1.5);
  const Model model = four_bar_with_bob(p);
  for (double t : {0.2, 1.9, 3.4}) {
    const State s = state_at(model, four_bar_bob_configuration(p, p.theta0 + p.omega * t), t);
    const VecX lambda = multipliers_of(model, s.q, s.qd, s.qdd, t);
    CAPTURE(t);
    for (int c : {0, 1, 2, 3, 5}) check_joint_reaction(model, c, s.q, lambda);
    check_driver_effort(model, 4, s, lambda);
    check_free_bodies(model, s);
  }
}

GRADED_TEST("driver_effort and joint_reaction arm and collar free-body diagrams", "[M03][T5][points=1]") {
  const ArmCollar ac = arm_collar(0.3, DriveFunction::harmonic(-0.1, 0.25, 1.1, 0.5),
                                  DriveFunction::harmonic(0.35, 0.12, 1.7, 0.2), 40.0, 0.8,
                                  DriveFunction::harmonic(-2.0, 1.0, 3.0));
  for (double t : {0.15, 1.05, 2.6}) {
    const State s = state_at(ac.model, ac.exact(t), t);
    const VecX lambda = multipliers_of(ac.model, s.q, s.qd, s.qdd, t);
    CAPTURE(t);
    check_joint_reaction(ac.model, 0, s.q, lambda);
    check_joint_reaction(ac.model, 1, s.q, lambda);
    check_driver_effort(ac.model, 2, s, lambda);
    check_driver_effort(ac.model, 3, s, lambda);
    check_free_bodies(ac.model, s);
  }
}
