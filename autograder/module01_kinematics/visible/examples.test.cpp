// Module 1: the example mechanisms assembled from the student's joints and drivers.
#include <cmath>

#include "fmbd/constraints.hpp"
#include "fmbd/examples.hpp"
#include "kinematics_checks.hpp"

using namespace fmbd;
using namespace fmbd::m01;

GRADED_TEST("slider-crank: C vanishes on the closed-form configuration and C_q, C_t match finite differences",
            "[M01][T3][points=1]") {
  examples::SliderCrankParameters p;  // r = 0.1, l = 0.3
  p.driven = false;                   // joints only: the drivers are task T5
  const Model m = examples::slider_crank(p);
  for (int k = 0; k < 24; ++k) {
    const double A = p.A0 + 2 * kPi * k / 24 + 0.05;
    const double t = (A - p.A0) / p.omega;
    const VecX q = examples::slider_crank_configuration(p, A);
    if (!check_model_closes(m, q, t)) break;
    if (!check_model_derivatives(m, q, t)) break;
  }
  // Lift the slider by delta: the guide reads C_1 = delta (normal (0, 1)), joint C reads (0, -delta).
  const double delta = 0.01, A = 0.8;
  VecX q = examples::slider_crank_configuration(p, A);
  q(7) += delta;
  const VecX C = kernel_evaluation(m, q, (A - p.A0) / p.omega).C;
  INFO("slider lifted by delta = " << delta << " at crank angle " << A);
  CHECK_NEAR_NAMED("the slider guide's offset row of your C, slider lifted",
                   C(6), delta, kGeometry, hint::translational_offset);
  CHECK_CLOSE_NAMED("the rod-slider revolute's rows of your C, slider lifted",
                    C.segment<2>(4), Vec2(0, -delta), kGeometry, hint::revolute_gap);
  CHECK_NEAR_NAMED("the slider guide's angle row of your C, slider lifted", C(7), 0.0, kGeometry, hint::angle_row);
}

GRADED_TEST("four-bar: C vanishes on the closed-form configuration and C_q, C_t match finite differences",
            "[M01][T2][points=1]") {
  examples::FourBarParameters p;
  p.driven = false;  // joints only: the drivers are task T5
  const Model m = examples::four_bar(p);
  for (int k = 0; k < 24; ++k) {
    const double theta = p.theta0 + 2 * kPi * k / 24;
    const VecX q = four_bar_configuration(p, theta);
    const double t = (theta - p.theta0) / p.omega;
    if (!check_model_closes(m, q, t)) break;
    if (!check_model_derivatives(m, q, t)) break;
  }
}
