// Module 2, tasks T3 and T4: gamma of each joint and driver type against the second time
// derivative of its constraint along smooth trajectories (visible tests).
#include "grading.hpp"
#include "kinematic_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m02;

GRADED_TEST("revolute_gamma matches d2C/dt2 along moving bodies", "[M02][T3][points=1]") {
  Random rnd(301);
  for (int k = 0; k < 4; ++k) {
    check_revolute_gamma(random_gamma_case(rnd, false, k == 3));
  }
}

GRADED_TEST("translational_gamma matches d2C/dt2 with both bodies turning", "[M02][T3][points=1]") {
  Random rnd(302);
  for (int k = 0; k < 4; ++k) {
    check_translational_gamma(random_gamma_case(rnd, false, false));
  }
}

GRADED_TEST("fixed_gamma matches d2C/dt2 along moving bodies", "[M02][T3][points=1]") {
  Random rnd(303);
  for (int k = 0; k < 3; ++k) {
    check_fixed_gamma(random_gamma_case(rnd, false, false));
  }
}

GRADED_TEST("angle driver gamma matches d2C/dt2 for a harmonic drive", "[M02][T4][points=1]") {
  Random rnd(304);
  for (int k = 0; k < 3; ++k) {
    const GammaCase c = random_gamma_case(rnd, false, false);
    check_absolute_angle_gamma(c);
    check_relative_angle_gamma(c);
  }
}

GRADED_TEST("point_coordinate_gamma matches d2C/dt2 for both axes", "[M02][T4][points=1]") {
  Random rnd(305);
  for (int k = 0; k < 3; ++k) {
    const GammaCase c = random_gamma_case(rnd, false, true);
    check_point_coordinate_gamma(c, Axis::x);
    check_point_coordinate_gamma(c, Axis::y);
  }
}

GRADED_TEST("distance_gamma matches d2C/dt2 for a harmonic drive", "[M02][T4][points=1]") {
  Random rnd(306);
  for (int k = 0; k < 4; ++k) {
    check_distance_gamma(random_gamma_case(rnd, false, false));
  }
}
