// Module 3, task T4: power balance of other driven models (hidden tests): a four-bar with
// gravity, rotational spring-dampers and a welded bob; an arm and collar driven by a
// point-coordinate and a distance driver, with a damped spring and an actuator.
#include "dynamics_checks.hpp"
#include "dynamics_hidden_checks.hpp"
#include "fmbd/inverse_dynamics.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m03;

GRADED_TEST("lagrange_multipliers four-bar with gravity and an RSDA keeps the power balance", "[M03][T4][points=2]") {
  for (const auto& p : {four_bar_parameters(0.1, 0.3, 0.25, 0.3, 0.5, 1.5),
                        four_bar_parameters(0.12, 0.32, 0.28, 0.3, 2.0, -2.0)}) {
    const Model model = four_bar_with_bob(p);
    for (double t : {0.3, 1.5, 3.0}) {
      CAPTURE(p.omega);
      check_power_balance(model, four_bar_bob_configuration(p, p.theta0 + p.omega * (t - 1e-4)), t);
    }
  }
}

GRADED_TEST("lagrange_multipliers arm and collar with distance and point-coordinate drivers keeps the power balance",
            "[M03][T4][points=1]") {
  const ArmCollar ac = arm_collar(0.25, DriveFunction::harmonic(0.1, 0.2, 1.2, 0.1),
                                  DriveFunction::harmonic(0.3, 0.1, 2.5, 0.7), 80.0, 2.0,
                                  DriveFunction::harmonic(1.0, 3.0, 4.0));
  for (double t : {0.35, 1.7, 3.1}) {
    check_power_balance(ac.model, ac.exact(t - 1e-4), t);
  }
}
