// Module 4, tasks T2 and T3: one-step integrators on plain ODEs (visible tests).
// The oracles: the step formulas written out on a time-dependent ODE, and the exact solution
// exp(A t) y0 of a linear ODE, which shows the order of each method as h is halved.
#include <cmath>
#include <string>

#include "fmbd/integrators.hpp"
#include "grading.hpp"
#include "integration_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m04;

namespace {

// The integrators' formulas, shown by with_formula at the tasks' last hint level only.
constexpr const char* kEuler = "y_{n+1} = y_n + h f(t_n, y_n)";
constexpr const char* kRk4 = "k1 = f(t, y), k2 = f(t + h/2, y + h/2 k1), k3 = f(t + h/2, y + h/2 k2), k4 = f(t + h, "
                             "y + h k3), y + h/6 (k1 + 2 k2 + 2 k3 + k4)";
constexpr const char* kDormandPrince = "k_s = f(t + c_s h, y + h sum_r a_sr k_r), y = y + h sum_s b_s k_s";
constexpr const char* kErrorEstimate = "error = y5 - y4 = h sum_s (b_s - b_hat_s) k_s";

// A non-linear, time-dependent right-hand side on R^3 that counts its evaluations.
struct CountingRhs {
  int calls = 0;
  static VecX eval(double t, const VecX& y) {
    return vec({std::cos(2 * t) * y(0) - y(1) * y(1), std::sin(t) + y(0) * y(1), t * y(2) - 0.5 * y(0)});
  }
  OdeRhs rhs() {
    return [this](double t, const VecX& y) {
      ++calls;
      return eval(t, y);
    };
  }
};

// Global error |y_N - y(T)| of N fixed steps on the linear ODE.
double global_error(const StepFunction& step, const LinearOde& ode, double T, int N) {
  return (integrate(step, ode.rhs(), 0.0, ode.y0, T, N) - ode.exact(T)).norm();
}

}  // namespace

// ---- T2 -------------------------------------------------------------------------------------

GRADED_TEST("euler_step and rk4_step one step matches the formulas on a time-dependent ODE", "[M04][T2][points=1]") {
  Random rnd(4201);
  for (int k = 0; k < 3; ++k) {
    const double t = rnd.uniform(0.0, 2.0), h = rnd.uniform(0.2, 0.4);
    const VecX y = rnd.vector(3, -1, 1);
    CAPTURE(t, h);
    auto f = [](double s, const VecX& x) { return CountingRhs::eval(s, x); };

    CountingRhs euler_f;
    const VecX euler = euler_step(euler_f.rhs(), t, y, h);
    const VecX euler_expected = y + h * f(t, y);
    CHECK_CLOSE_NAMED(
        "your euler_step's y", euler, euler_expected, (Tolerance{1e-14, 1e-14}),
        diagnose(euler, euler_expected,
                 {{with_formula("your Euler step evaluates f at the end: Euler evaluates f at the start of "
                                "the step",
                                kEuler),
                   VecX(y + h * f(t + h, y))},
                  {with_formula("your Euler step: the step h is missing", kEuler), VecX(y + f(t, y))}},
                 with_formula("your Euler step is not the explicit Euler step", kEuler), Tolerance{1e-12, 1e-12}));
    {
      INFO("hint: explicit Euler needs exactly one evaluation of f per step");
      CHECK(euler_f.calls == 1);
    }

    CountingRhs rk4_f;
    const VecX rk4 = rk4_step(rk4_f.rhs(), t, y, h);
    const VecX k1 = f(t, y), k2 = f(t + h / 2, y + h / 2 * k1), k3 = f(t + h / 2, y + h / 2 * k2),
               k4 = f(t + h, y + h * k3);
    const VecX rk4_expected = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    // Typical slips, each computed in full.
    const VecX k3_full = f(t + h / 2, y + h * k2), k4_full = f(t + h, y + h * k3_full);
    const VecX k2_at_t = f(t, y + h / 2 * k1), k3_at_t = f(t, y + h / 2 * k2_at_t), k4_at_t = f(t, y + h * k3_at_t);
    CHECK_CLOSE_NAMED(
        "your rk4_step's y", rk4, rk4_expected, (Tolerance{1e-13, 1e-13}),
        diagnose(rk4, rk4_expected,
                 {{with_formula("your RK4 weights: the middle stages count twice", kRk4),
                   VecX(y + h / 6 * (k1 + k2 + k3 + k4))},
                  {with_formula("your RK4 weights are equal: the middle stages count twice", kRk4),
                   VecX(y + h / 4 * (k1 + k2 + k3 + k4))},
                  {with_formula("your RK4 stage k3 takes a full step from y: it is a half step", kRk4),
                   VecX(y + h / 6 * (k1 + 2 * k2 + 2 * k3_full + k4_full))},
                  {with_formula("your RK4 stage k4 takes a half step: it is a full step", kRk4),
                   VecX(y + h / 6 * (k1 + 2 * k2 + 2 * k3 + f(t + h, y + h / 2 * k3)))},
                  {with_formula("your RK4 stage times: k2 and k3 are at the middle of the step, k4 at its end "
                                "(f depends on t)",
                                kRk4),
                   VecX(y + h / 6 * (k1 + 2 * k2_at_t + 2 * k3_at_t + k4_at_t))}},
                 with_formula("your RK4 step is not the classical RK4 step", kRk4), Tolerance{1e-12, 1e-12}));
    {
      INFO("hint: classical RK4 needs exactly four evaluations of f per step");
      CHECK(rk4_f.calls == 4);
    }
  }
}

GRADED_TEST("euler_step global error is first order on a linear ODE", "[M04][T2][points=1]") {
  const LinearOde ode;
  const StepFunction euler = euler_method();
  const double e1 = global_error(euler, ode, 3.0, 150), e2 = global_error(euler, ode, 3.0, 300),
               e3 = global_error(euler, ode, 3.0, 600);
  CAPTURE(e1, e2, e3, ratio(e1, e2), ratio(e2, e3));
  const std::string hint = with_formula("your Euler's global error does not halve with h: Euler is of order 1", kEuler);
  CHECK_NEAR_NAMED("your euler_step's global error with 150 steps over that with 300", ratio(e1, e2), 2.0,
                   (Tolerance{0.25, 0}), hint);
  CHECK_NEAR_NAMED("your euler_step's global error with 300 steps over that with 600", ratio(e2, e3), 2.0,
                   (Tolerance{0.2, 0}), hint);
  CHECK_NEAR_NAMED("your euler_step's global error with 600 steps", e3, 0.0, (Tolerance{0.03, 0}), hint);
}

GRADED_TEST("rk4_step global error is fourth order on a linear ODE", "[M04][T2][points=1]") {
  const LinearOde ode;
  const StepFunction rk4 = rk4_method();
  const double e1 = global_error(rk4, ode, 3.0, 20), e2 = global_error(rk4, ode, 3.0, 40),
               e3 = global_error(rk4, ode, 3.0, 80);
  CAPTURE(e1, e2, e3, ratio(e1, e2), ratio(e2, e3));
  const std::string hint =
      "RK4 order: halving h must divide the global error by about 16; check the stages (half steps for k2, k3, a "
      "full step for k4) and the weights h/6 (1, 2, 2, 1)";
  CHECK_NEAR_NAMED("your rk4_step's global error with 20 steps over that with 40", ratio(e1, e2), 16.0,
                   (Tolerance{4.0, 0}), hint);
  CHECK_NEAR_NAMED("your rk4_step's global error with 40 steps over that with 80", ratio(e2, e3), 16.0,
                   (Tolerance{4.0, 0}), hint);
  CHECK_NEAR_NAMED("your rk4_step's global error with 80 steps", e3, 0.0, (Tolerance{1e-6, 0}), hint);
}

// ---- T3 -------------------------------------------------------------------------------------

GRADED_TEST("dormand_prince_step fifth-order solution on a linear ODE", "[M04][T3][points=1]") {
  const LinearOde ode;
  const StepFunction dp = dormand_prince_solution();
  const double e1 = global_error(dp, ode, 3.0, 12), e2 = global_error(dp, ode, 3.0, 24),
               e3 = global_error(dp, ode, 3.0, 48);
  CAPTURE(e1, e2, e3, ratio(e1, e2), ratio(e2, e3));
  std::string hint = with_formula("your Dormand-Prince y is not of order 5: halving h must divide its error by about 32",
                                  kDormandPrince);
  if (ratio(e2, e3) > 12 && ratio(e2, e3) < 20)
    hint = "Dormand-Prince solution: continue with the 5th-order weights b, not b_hat (the error of y falls like "
           "h^4 instead of h^5)";
  CHECK_NEAR_NAMED("your Dormand-Prince y's global error with 12 steps over that with 24", ratio(e1, e2), 32.0,
                   (Tolerance{8.0, 0}), hint);
  CHECK_NEAR_NAMED("your Dormand-Prince y's global error with 24 steps over that with 48", ratio(e2, e3), 32.0,
                   (Tolerance{8.0, 0}), hint);
  CHECK_NEAR_NAMED("your Dormand-Prince y's global error with 48 steps", e3, 0.0, (Tolerance{1e-7, 0}), hint);
}

GRADED_TEST("dormand_prince_step error estimate tracks the local error of the embedded solution",
            "[M04][T3][points=1]") {
  const LinearOde ode;
  const VecX y0 = ode.y0;
  double previous = 0;
  for (double h : {0.1, 0.05, 0.025}) {
    CAPTURE(h);
    const EmbeddedStep s = dormand_prince_step(ode.rhs(), 0.0, y0, h);
    REQUIRE(s.y.size() == 3);
    REQUIRE(s.error.size() == 3);
    const VecX exact = ode.exact(h);
    const TableauStep oracle = dormand_prince_by_tableau(ode.rhs(), 0.0, y0, h);
    const VecX local4 = exact - oracle.y4;  // true local error of the embedded 4th-order solution
    const VecX local5 = exact - s.y;        // local error of the solution returned
    CAPTURE(local4.norm(), local5.norm(), s.error.norm());
    std::string hint = with_formula("your error estimate is not the difference of the 5th- and 4th-order solutions",
                                    kErrorEstimate);
    const double size = local4.norm();
    if ((s.error + local4).norm() < 0.25 * size)
      hint = with_formula("your error estimate sign: it is y5 - y4, not y4 - y5", kErrorEstimate);
    else if ((h * s.error - local4).norm() < 0.25 * size)
      hint = with_formula("your error estimate missing the factor h", kErrorEstimate);
    else if (local5.norm() > 0.3 * size)
      hint = "Dormand-Prince solution: y must use the 5th-order weights b (local error O(h^6)), not b_hat";
    // y5 is much more accurate than y4, so y5 - y4 is the local error of y4 up to O(h^6).
    CHECK_NEAR_NAMED("the distance of your error estimate from the local error of y4", (s.error - local4).norm(), 0.0,
                     (Tolerance{0.25 * size, 0}), hint);
    CHECK_NEAR_NAMED("the local error of your y", local5.norm(), 0.0, (Tolerance{0.25 * size, 0}), hint);
    CHECK_CLOSE_NAMED("your Dormand-Prince error estimate", s.error, VecX(oracle.y5 - oracle.y4),
                      (Tolerance{1e-14, 1e-6}), hint);
    if (previous > 0) {
      CAPTURE(previous / s.error.norm());
      CHECK_NEAR_NAMED("your error estimate at h over that at h/2", previous / s.error.norm(), 32.0,
                       (Tolerance{8.0, 0}), hint + "; the local error estimate of a 5(4) pair scales like h^5");
    }
    previous = s.error.norm();
  }
}
