// The seven-body loop: its structure, and simulate() on it against independent oracles (the
// energy balance, a second integrator, the same motion in scaled units).
#include <cmath>

#include "fmbd/constraints.hpp"
#include "fmbd/dof.hpp"
#include "fmbd/mechanisms.hpp"
#include "fmbd/simulation.hpp"
#include "grading.hpp"

using namespace fmbd;

TEST_CASE("seven-body loop: 21 coordinates, 20 constraint rows, one degree of freedom, closed at q0",
          "[mechanisms]") {
  const mechanisms::SevenBodyLoop loop = mechanisms::seven_body_loop();
  CHECK(loop.model.num_bodies() == 7);
  CHECK(loop.model.num_coordinates() == 21);
  CHECK(loop.model.num_constraints() == 20);
  CHECK(degrees_of_freedom(loop.model, loop.q0, 0.0) == 1);
  CHECK(constraints(loop.model, loop.q0, 0.0).norm() < 1e-15);
}

TEST_CASE("seven-body loop: simulate keeps the energy balance and agrees with a second integrator",
          "[mechanisms]") {
  const mechanisms::SevenBodyLoop loop = mechanisms::seven_body_loop();
  // The crank spins up fast: RK4 at 0.25 ms (global error ~1e-7) against DP at 1e-10.
  SimulationOptions rk4;
  rk4.step = 2.5e-4;
  rk4.stabilisation = Stabilisation::projection;
  rk4.output_interval = 0.05;
  const Trajectory a = simulate(loop.model, loop.q0, loop.qd0, 0.0, 1.0, rk4);
  REQUIRE(a.t.size() == 21);
  CHECK((a.q.back() - loop.q0).norm() > 0.1);  // it moves
  SimulationOptions dp;
  dp.integrator = Integrator::dormand_prince;
  dp.rtol = 1e-10;
  dp.atol = 1e-12;
  dp.output_interval = 0.05;
  const Trajectory b = simulate(loop.model, loop.q0, loop.qd0, 0.0, 1.0, dp);
  REQUIRE(b.t.size() == a.t.size());
  for (std::size_t i = 0; i < a.t.size(); ++i) {
    CAPTURE(a.t[i]);
    CHECK((a.q[i] - b.q[i]).norm() < 1e-6);
    // E - E0 = W (motor and damper): the DP run without projection keeps it to its tolerance.
    CHECK(b.energy[i] - b.energy[0] == Approx(b.work_done[i]).margin(1e-8));
    CHECK(b.position_drift[i] < 1e-8);
  }
}

TEST_CASE("seven-body loop: masses, forces and stiffness scaled by 1e-4 give the same motion", "[mechanisms]") {
  SimulationOptions o;
  o.step = 1e-3;
  o.stabilisation = Stabilisation::projection;
  o.output_interval = 0.1;
  const mechanisms::SevenBodyLoop si = mechanisms::seven_body_loop();
  mechanisms::SevenBodyLoopParameters light;
  light.mass_scale = 1e-4;
  const mechanisms::SevenBodyLoop scaled = mechanisms::seven_body_loop(light);
  const Trajectory a = simulate(si.model, si.q0, si.qd0, 0.0, 1.0, o);
  const Trajectory b = simulate(scaled.model, scaled.q0, scaled.qd0, 0.0, 1.0, o);
  REQUIRE(a.t.size() == b.t.size());
  for (std::size_t i = 0; i < a.t.size(); ++i) {
    CAPTURE(a.t[i]);
    CHECK((a.q[i] - b.q[i]).norm() < 1e-10);
    CHECK(b.energy[i] == Approx(1e-4 * a.energy[i]).margin(1e-14));
  }
}
