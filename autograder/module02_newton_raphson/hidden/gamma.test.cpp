// Module 2, tasks T3 and T4: gamma with other seeds, ground sides and smooth_step drives (hidden).
#include "grading.hpp"
#include "kinematic_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m02;

GRADED_TEST("joint gamma with other seeds and a ground side", "[M02][T3][points=1]") {
  Random rnd(1301);
  for (int k = 0; k < 3; ++k) {
    check_revolute_gamma(random_gamma_case(rnd, true, false));
    check_revolute_gamma(random_gamma_case(rnd, false, false));
    check_translational_gamma(random_gamma_case(rnd, false, true));
    check_translational_gamma(random_gamma_case(rnd, false, false));
    check_fixed_gamma(random_gamma_case(rnd, true, false));
    check_fixed_gamma(random_gamma_case(rnd, false, false));
  }
}

GRADED_TEST("driver gamma with smooth_step drives and other seeds", "[M02][T4][points=1]") {
  Random rnd(1302);
  for (int k = 0; k < 3; ++k) {
    GammaCase c = random_gamma_case(rnd, false, k == 2);
    // A smooth step from f0 to f1 over [0, 2]; t0 in (0, 2) so f' and f'' are both non-zero.
    c.f = DriveFunction::smooth_step(rnd.uniform(0.4, 0.8), rnd.uniform(1.0, 1.6), 0.0, 2.0);
    c.t0 = rnd.uniform(0.2, 0.8);
    check_absolute_angle_gamma(c);
    check_relative_angle_gamma(c);
    check_point_coordinate_gamma(c, Axis::x);
    check_point_coordinate_gamma(c, Axis::y);
    check_distance_gamma(c);
  }
}
