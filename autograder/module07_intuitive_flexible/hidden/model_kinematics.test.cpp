// Module 7, tasks T2-T3 through whole models (hidden tests): the spin-up beam (a fixed joint, so
// the node angle theta + psi enters C), the flexible pendulum (lumped mass, free-free modes) and
// the slider-crank reduced by free-free modes, against central differences of C(q, t).
#include <string>

#include "fmbd/constraints.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/gamma.hpp"
#include "flexible_checks.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m07;

GRADED_TEST("spin up beam pendulum and modal slider crank constraint Jacobians match differences of C",
            "[M07][T2][points=2]") {
  Random rnd(7291);
  {
    SpinUpBeamParameters p;
    p.elements = 6;
    const FlexibleExample ex = spin_up_beam(p);
    for (int trial = 0; trial < 2; ++trial)
      check_constraint_jacobian(ex.model, random_model_state(ex.model, ex.q0, rnd, 0.2, 0.5, 0.05),
                                rnd.uniform(1.0, 12.0), "spin-up beam, trial " + std::to_string(trial));
  }
  {
    const FlexibleExample ex = flexible_pendulum();
    for (int trial = 0; trial < 2; ++trial)
      check_constraint_jacobian(ex.model, random_model_state(ex.model, ex.q0, rnd, 0.05, 1.0, 0.05), 0.0,
                                "pendulum, trial " + std::to_string(trial));
  }
  {
    FlexibleSliderCrankParameters p;
    p.basis = BodyBasis::free_free_modes;
    p.modes = 3;
    const FlexibleExample ex = flexible_slider_crank(p);
    check_constraint_jacobian(ex.model, random_model_state(ex.model, ex.q0, rnd, 0.02, 0.4, 0.05), 0.01,
                              "slider crank with free-free modes");
  }
}

GRADED_TEST("spin up beam and pendulum gamma match the second time derivative of C", "[M07][T3][points=2]") {
  Random rnd(7392);
  {
    SpinUpBeamParameters p;
    p.elements = 6;
    const FlexibleExample ex = spin_up_beam(p);
    for (int trial = 0; trial < 2; ++trial) {
      const VecX q = random_model_state(ex.model, ex.q0, rnd, 0.2, 0.5, 0.05);
      const VecX qd = random_model_rates(ex.model, rnd, 1.0, 2.0, 1.0);
      // During the spin-up the driver has C_tt != 0; the differences in t include it.
      check_gamma(ex.model, q, qd, rnd.uniform(2.0, 12.0), "spin-up beam, trial " + std::to_string(trial));
    }
  }
  {
    const FlexibleExample ex = flexible_pendulum();
    for (int trial = 0; trial < 2; ++trial) {
      const VecX q = random_model_state(ex.model, ex.q0, rnd, 0.05, 1.0, 0.05);
      const VecX qd = random_model_rates(ex.model, rnd, 1.0, 5.0, 10.0);
      check_gamma(ex.model, q, qd, 0.0, "pendulum, trial " + std::to_string(trial));
    }
  }
}
