// Module 7, tasks T2-T3 through whole models (visible tests): the flexible slider-crank's
// constraint Jacobian against central differences of C(q, t), and its gamma against the second
// time derivative of C along a smooth motion, at random states with deformed rods. The given
// assembly of modules 1 and 2 chains the joint kernels with the node markers of tasks T1-T3.
#include <string>

#include "fmbd/constraints.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/gamma.hpp"
#include "flexible_checks.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m07;

GRADED_TEST("flexible slider crank constraint Jacobian matches differences of C at deformed states",
            "[M07][T2][points=2]") {
  Random rnd(7211);
  const FlexibleExample ex = flexible_slider_crank();
  for (int trial = 0; trial < 3; ++trial) {
    const VecX q = random_model_state(ex.model, ex.q0, rnd, 0.02, 0.4, 0.05);
    const double t = rnd.uniform(0.0, 0.05);
    check_constraint_jacobian(ex.model, q, t, "slider crank, trial " + std::to_string(trial));
  }
}

GRADED_TEST("flexible slider crank gamma matches the second time derivative of C at deformed states",
            "[M07][T3][points=2]") {
  Random rnd(7311);
  FlexibleSliderCrankParameters p;
  p.crank_speed = 40.0;
  const FlexibleExample ex = flexible_slider_crank(p);
  for (int trial = 0; trial < 3; ++trial) {
    const VecX q = random_model_state(ex.model, ex.q0, rnd, 0.02, 0.4, 0.05);
    const VecX qd = random_model_rates(ex.model, rnd, 2.0, 40.0, 20.0);
    const double t = rnd.uniform(0.0, 0.05);
    check_gamma(ex.model, q, qd, t, "slider crank, trial " + std::to_string(trial));
  }
}
