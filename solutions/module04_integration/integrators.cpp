// Module 4, tasks T2 and T3: explicit Euler, classical Runge-Kutta, Dormand-Prince 5(4).
#include <array>

#include "fmbd/errors.hpp"
#include "fmbd/integrators.hpp"

namespace fmbd {

VecX euler_step(const OdeRhs& f, double t, const VecX& y, double h) {
  // TASK(M04T2): one explicit Euler step of y' = f(t, y) from (t, y) with step h (README
  //   section 2, integrators.hpp). Stuck? ./workbook hint M04T2
  // BEGIN SOLUTION
  return y + h * f(t, y);
  // END SOLUTION
  // STUB: unused(f, t, y, h);
  // STUB: throw NotImplemented("M04T2 euler_step");
}

VecX rk4_step(const OdeRhs& f, double t, const VecX& y, double h) {
  // TASK(M04T2): one step of the classical Runge-Kutta method of order 4 (README section 2,
  //   integrators.hpp), with four evaluations of f.
  // BEGIN SOLUTION
  const VecX k1 = f(t, y);
  const VecX k2 = f(t + h / 2, y + h / 2 * k1);
  const VecX k3 = f(t + h / 2, y + h / 2 * k2);
  const VecX k4 = f(t + h, y + h * k3);
  return y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  // END SOLUTION
  // STUB: unused(f, t, y, h);
  // STUB: throw NotImplemented("M04T2 rk4_step");
}

EmbeddedStep dormand_prince_step(const OdeRhs& f, double t, const VecX& y, double h) {
  // TASK(M04T3): one step of the Dormand-Prince 5(4) pair (README section 2) with the tableau
  //   DormandPrince (c, a, b, b_hat) of integrators.hpp: return the 5th-order solution y5 and
  //   the error estimate y5 - y4 (EmbeddedStep). Seven evaluations of f, no more.
  //   Stuck? ./workbook hint M04T3
  // BEGIN SOLUTION
  using DP = DormandPrince;
  std::array<VecX, DP::stages> k;
  for (int s = 0; s < DP::stages; ++s) {
    VecX y_stage = y;
    for (int r = 0; r < s; ++r) y_stage += h * DP::a[s][r] * k[r];
    k[s] = f(t + DP::c[s] * h, y_stage);
  }
  EmbeddedStep step{y, VecX::Zero(y.size())};
  for (int s = 0; s < DP::stages; ++s) {
    step.y += h * DP::b[s] * k[s];
    step.error += h * (DP::b[s] - DP::b_hat[s]) * k[s];
  }
  return step;
  // END SOLUTION
  // STUB: unused(f, t, y, h);
  // STUB: throw NotImplemented("M04T3 dormand_prince_step");
}

}  // namespace fmbd
