// Exercise file of module 4, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 4, tasks T2 and T3: explicit Euler, classical Runge-Kutta, Dormand-Prince 5(4).
#include "fmbd/errors.hpp"
#include "fmbd/integrators.hpp"

namespace fmbd {

void euler_step(const OdeRhsInto& f, double t, const VecX& y, double h, Stages& stages, VecX& y_new) {
  // TODO(M04T2): one explicit Euler step of y' = f(t, y) from (t, y) with step h into y_new
  //   (README section 2, integrators.hpp); the slope in stages.k[0]. Stuck? ./workbook hint M04T2
  unused(f, t, y, h, stages, y_new);
  throw NotImplemented("M04T2 euler_step");
}

void rk4_step(const OdeRhsInto& f, double t, const VecX& y, double h, Stages& stages, VecX& y_new) {
  // TODO(M04T2): one step of the classical Runge-Kutta method of order 4 into y_new (README
  //   section 2, integrators.hpp), with four evaluations of f; the slopes in stages.k, each
  //   stage's state in stages.y_stage.
  unused(f, t, y, h, stages, y_new);
  throw NotImplemented("M04T2 rk4_step");
}

void dormand_prince_step(const OdeRhsInto& f, double t, const VecX& y, double h, Stages& stages,
                         EmbeddedStep& step) {
  // TODO(M04T3): one step of the Dormand-Prince 5(4) pair (README section 2) with the tableau
  //   DormandPrince (c, a, b, b_hat) of integrators.hpp: the 5th-order solution y5 and the error
  //   estimate y5 - y4 into `step`, the slopes in stages.k. Seven evaluations of f, no more.
  //   Stuck? ./workbook hint M04T3
  unused(f, t, y, h, stages, step);
  throw NotImplemented("M04T3 dormand_prince_step");
}

}  // namespace fmbd
