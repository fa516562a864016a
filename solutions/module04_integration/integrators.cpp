// Module 4, tasks T2 and T3: explicit Euler, classical Runge-Kutta, Dormand-Prince 5(4).
#include <array>

#include "fmbd/errors.hpp"
#include "fmbd/integrators.hpp"

namespace fmbd {

VecX euler_step(const OdeRhs& f, double t, const VecX& y, double h) {
  // TASK(M04T2): explicit Euler, y_{n+1} = y_n + h f(t_n, y_n).
  // BEGIN SOLUTION
  return y + h * f(t, y);
  // END SOLUTION
  // STUB: unused(f, t, y, h);
  // STUB: throw NotImplemented("M04T2 euler_step");
}

VecX rk4_step(const OdeRhs& f, double t, const VecX& y, double h) {
  // TASK(M04T2): classical Runge-Kutta:
  //   k1 = f(t, y),               k2 = f(t + h/2, y + h/2 k1),
  //   k3 = f(t + h/2, y + h/2 k2), k4 = f(t + h, y + h k3),
  //   y_{n+1} = y + h/6 (k1 + 2 k2 + 2 k3 + k4).
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
  // TASK(M04T3): one step of the embedded pair with the tableau DormandPrince (c, a, b, b_hat):
  //   k_s = f(t + c_s h, y + h sum_{r<s} a_{s,r} k_r),  s = 0..6,
  //   y5 = y + h sum_s b_s k_s,   y4 = y + h sum_s b_hat_s k_s,
  //   return {y5, y5 - y4}.
  // Hint: the error is h sum_s (b_s - b_hat_s) k_s; it needs no extra evaluation of f.
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
