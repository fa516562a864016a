// Module 1 (hidden): the example mechanisms with other geometry and negative crank angles.
#include <cmath>

#include "fmbd/constraints.hpp"
#include "fmbd/examples.hpp"
#include "kinematics_checks.hpp"

using namespace fmbd;
using namespace fmbd::m01;

GRADED_TEST("four-bar: other link lengths close across a full crank revolution", "[M01][T2][points=1]") {
  examples::FourBarParameters p;
  p.a = 0.15;
  p.b = 0.4;
  p.c = 0.35;
  p.d = 0.45;
  p.theta0 = -1.0;
  p.omega = 1.5;
  p.driven = false;  // joints only: the drivers are task T5
  const Model m = examples::four_bar(p);
  for (int k = 0; k < 18; ++k) {
    const double theta = p.theta0 - 2 * kPi * k / 18;  // turning backwards: negative times
    const VecX q = four_bar_configuration(p, theta);
    const double t = (theta - p.theta0) / p.omega;
    if (!check_model_closes(m, q, t)) break;
    if (!check_model_derivatives(m, q, t)) break;
  }
  // Slider-crank with a long rod, turning backwards.
  examples::SliderCrankParameters s;
  s.r = 0.2;
  s.l = 0.5;
  s.A0 = 1.0;
  s.omega = -3.0;
  const Model sc = examples::slider_crank(s);
  for (double A : {1.0, -0.5, -2.0, -4.4}) {
    const double t = (A - s.A0) / s.omega;
    const VecX q = examples::slider_crank_configuration(s, A);
    if (!check_model_closes(sc, q, t)) break;
    if (!check_model_derivatives(sc, q, t)) break;
  }
}
