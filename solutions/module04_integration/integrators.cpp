// Module 4, tasks T2 and T3: explicit Euler, classical Runge-Kutta, Dormand-Prince 5(4).
#include "fmbd/errors.hpp"
#include "fmbd/integrators.hpp"

namespace fmbd {

void euler_step(const OdeRhsInto& f, double t, const VecX& y, double h, Stages& stages, VecX& y_new) {
  // TASK(M04T2): one explicit Euler step of y' = f(t, y) from (t, y) with step h into y_new
  //   (README section 2, integrators.hpp); the slope in stages.k[0]. Stuck? ./workbook hint M04T2
  // BEGIN SOLUTION
  f(t, y, stages.k[0]);
  y_new = y + h * stages.k[0];
  // END SOLUTION
  // STUB: unused(f, t, y, h, stages, y_new);
  // STUB: throw NotImplemented("M04T2 euler_step");
}

void rk4_step(const OdeRhsInto& f, double t, const VecX& y, double h, Stages& stages, VecX& y_new) {
  // TASK(M04T2): one step of the classical Runge-Kutta method of order 4 into y_new (README
  //   section 2, integrators.hpp), with four evaluations of f; the slopes in stages.k, each
  //   stage's state in stages.y_stage.
  // BEGIN SOLUTION
  auto& k = stages.k;
  f(t, y, k[0]);
  stages.y_stage = y + h / 2 * k[0];
  f(t + h / 2, stages.y_stage, k[1]);
  stages.y_stage = y + h / 2 * k[1];
  f(t + h / 2, stages.y_stage, k[2]);
  stages.y_stage = y + h * k[2];
  f(t + h, stages.y_stage, k[3]);
  y_new = y + h / 6 * (k[0] + 2 * k[1] + 2 * k[2] + k[3]);
  // END SOLUTION
  // STUB: unused(f, t, y, h, stages, y_new);
  // STUB: throw NotImplemented("M04T2 rk4_step");
}

void dormand_prince_step(const OdeRhsInto& f, double t, const VecX& y, double h, Stages& stages,
                         EmbeddedStep& step) {
  // TASK(M04T3): one step of the Dormand-Prince 5(4) pair (README section 2) with the tableau
  //   DormandPrince (c, a, b, b_hat) of integrators.hpp: the 5th-order solution y5 and the error
  //   estimate y5 - y4 into `step`, the slopes in stages.k. Seven evaluations of f, no more.
  //   Stuck? ./workbook hint M04T3
  // BEGIN SOLUTION
  using DP = DormandPrince;
  auto& k = stages.k;
  for (int s = 0; s < DP::stages; ++s) {
    stages.y_stage = y;
    for (int r = 0; r < s; ++r) stages.y_stage += h * DP::a[s][r] * k[r];
    f(t + DP::c[s] * h, stages.y_stage, k[s]);
  }
  step.y = y;
  step.error.setZero(y.size());
  for (int s = 0; s < DP::stages; ++s) {
    step.y += h * DP::b[s] * k[s];
    step.error += h * (DP::b[s] - DP::b_hat[s]) * k[s];
  }
  // END SOLUTION
  // STUB: unused(f, t, y, h, stages, step);
  // STUB: throw NotImplemented("M04T3 dormand_prince_step");
}

}  // namespace fmbd
