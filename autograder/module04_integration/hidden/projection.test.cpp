// Module 4, task T4: projections on the slider-crank with other seeds (hidden tests).
#include <cmath>

#include "fmbd/examples.hpp"
#include "fmbd/projection.hpp"
#include "grading.hpp"
#include "integration_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m04;

GRADED_TEST("project_positions and project_velocities on a slider-crank with other seeds", "[M04][T4][points=1]") {
  Random rnd(4411);
  examples::SliderCrankParameters p;
  p.r = 0.15;
  p.l = 0.4;
  p.driven = false;
  const Model undriven = examples::slider_crank(p);
  for (int k = 0; k < 3; ++k) {
    const double A = rnd.uniform(-kPi, kPi);
    CAPTURE(A);
    const VecX q = examples::slider_crank_configuration(p, A);
    check_position_projection(undriven, q, 0.0, rnd);
    check_velocity_projection(undriven, q, rnd.vector(9, -2, 2), 0.0);
  }
  // With a point-coordinate driver on the slider (C_t != 0): velocities on the velocity equation.
  Model driven = examples::slider_crank(p);
  const DriveFunction x = DriveFunction::harmonic(0.4, 0.1, 2.0, 0.3);
  driven.add_point_coordinate_driver("slider drive", driven.find_point("slider C"), Axis::x, x);
  for (int k = 0; k < 3; ++k) {
    const double t = rnd.uniform(0, 3);
    // The crank angle A that puts the slider at x(t): solve r cos A + sqrt(l^2 - r^2 sin^2 A) = x by bisection.
    double lo = 0.0, hi = kPi;
    for (int it = 0; it < 80; ++it) {
      const double mid = 0.5 * (lo + hi);
      const double xm = p.r * std::cos(mid) + std::sqrt(p.l * p.l - p.r * p.r * std::sin(mid) * std::sin(mid));
      (xm > x(t).f ? lo : hi) = mid;
    }
    const VecX q = examples::slider_crank_configuration(p, 0.5 * (lo + hi));
    CAPTURE(t);
    check_velocity_projection(driven, q, rnd.vector(9, -2, 2), t);
  }
}
