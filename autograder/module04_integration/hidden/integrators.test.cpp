// Module 4, tasks T2 and T3: the integrators on a time-dependent ODE (hidden tests). Its exact
// solution y1 = y1(0) exp(sin t - sin t0), y2 = y2(0) exp(-(t^2 - t0^2) / 2) shows whether the
// stage times t + c_s h are right.
#include <cmath>

#include "fmbd/integrators.hpp"
#include "grading.hpp"
#include "integration_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m04;

namespace {

const double t0 = 0.3, t1 = 2.3;
const VecX y_start = vec({0.8, -1.2});

VecX rhs_value(double t, const VecX& y) { return vec({std::cos(t) * y(0), -t * y(1)}); }
VecX exact(double t) {
  return vec({y_start(0) * std::exp(std::sin(t) - std::sin(t0)), y_start(1) * std::exp(-(t * t - t0 * t0) / 2)});
}
double error(const StepFunction& step, int N) {
  return (integrate(step, rhs_value, t0, y_start, t1, N) - exact(t1)).norm();
}

}  // namespace

GRADED_TEST("euler_step and rk4_step orders on a time-dependent ODE", "[M04][T2][points=1]") {
  const double e1 = error(euler_method(), 100), e2 = error(euler_method(), 200), e3 = error(euler_method(), 400);
  CAPTURE(e1, e2, e3);
  CHECK_NEAR_NAMED("your euler_step's error with 100 steps over that with 200", ratio(e1, e2), 2.0, (Tolerance{0.3, 0}),
                   "Euler is first order: halving h halves the error");
  CHECK_NEAR_NAMED("your euler_step's error with 200 steps over that with 400", ratio(e2, e3), 2.0,
                   (Tolerance{0.25, 0}), "Euler is first order: halving h halves the error");
  const double r1 = error(rk4_method(), 10), r2 = error(rk4_method(), 20), r3 = error(rk4_method(), 40);
  CAPTURE(r1, r2, r3);
  const char* hint =
      "RK4 is fourth order also when f depends on t: k2 and k3 at t + h/2, k4 at t + h; halving h divides the error "
      "by about 16";
  CHECK_NEAR_NAMED("your rk4_step's error with 10 steps over that with 20", ratio(r1, r2), 16.0, (Tolerance{5.0, 0}),
                   hint);
  CHECK_NEAR_NAMED("your rk4_step's error with 20 steps over that with 40", ratio(r2, r3), 16.0, (Tolerance{4.0, 0}),
                   hint);
  CHECK_NEAR_NAMED("your rk4_step's error with 40 steps", r3, 0.0, (Tolerance{1e-6, 0}), hint);
}

GRADED_TEST("dormand_prince_step order and error estimate on a time-dependent ODE", "[M04][T3][points=1]") {
  const StepFunction dp = dormand_prince_solution();
  const double e1 = error(dp, 8), e2 = error(dp, 16), e3 = error(dp, 32);
  CAPTURE(e1, e2, e3);
  const char* hint =
      "Dormand-Prince is fifth order also when f depends on t: stage s at t + c_s h; halving h divides the error of y "
      "by about 32";
  CHECK_NEAR_NAMED("your Dormand-Prince y's error with 16 steps over that with 32", ratio(e2, e3), 32.0,
                   (Tolerance{10.0, 0}), hint);
  CHECK_NEAR_NAMED("your Dormand-Prince y's error with 32 steps", e3, 0.0, (Tolerance{1e-8, 0}), hint);
  for (double t : {0.4, 1.1, 1.9}) {
    const VecX y = exact(t);
    const double h = 0.05;
    const EmbeddedStep s = dormand_prince_step(rhs_value, t, y, h);
    const TableauStep oracle = dormand_prince_by_tableau(rhs_value, t, y, h);
    CAPTURE(t);
    CHECK_CLOSE_NAMED("your y", s.y, oracle.y5, (Tolerance{1e-14, 1e-13}),
                      with_formula("your y is not the 5th-order solution of the tableau",
                                   "y + h sum_s b_s k_s, k_s = f(t + c_s h, y + h sum_r a_sr k_r)"));
    CHECK_CLOSE_NAMED("your error", s.error, VecX(oracle.y5 - oracle.y4), (Tolerance{1e-13, 1e-9}),
                      with_formula("your error estimate is not the difference of the 5th- and 4th-order solutions",
                                   "y5 - y4 = h sum_s (b_s - b_hat_s) k_s"));
  }
}
