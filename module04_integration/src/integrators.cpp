// Exercise file of module 4, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory and the hints.
// Module 4, tasks T2 and T3: explicit Euler, classical Runge-Kutta, Dormand-Prince 5(4).
#include <array>

#include "fmbd/errors.hpp"
#include "fmbd/integrators.hpp"

namespace fmbd {

VecX euler_step(const OdeRhs& f, double t, const VecX& y, double h) {
  // TODO(M04T2): explicit Euler, y_{n+1} = y_n + h f(t_n, y_n).
  unused(f, t, y, h);
  throw NotImplemented("M04T2 euler_step");
}

VecX rk4_step(const OdeRhs& f, double t, const VecX& y, double h) {
  // TODO(M04T2): classical Runge-Kutta:
  //   k1 = f(t, y),               k2 = f(t + h/2, y + h/2 k1),
  //   k3 = f(t + h/2, y + h/2 k2), k4 = f(t + h, y + h k3),
  //   y_{n+1} = y + h/6 (k1 + 2 k2 + 2 k3 + k4).
  unused(f, t, y, h);
  throw NotImplemented("M04T2 rk4_step");
}

EmbeddedStep dormand_prince_step(const OdeRhs& f, double t, const VecX& y, double h) {
  // TODO(M04T3): one step of the embedded pair with the tableau DormandPrince (c, a, b, b_hat):
  //   k_s = f(t + c_s h, y + h sum_{r<s} a_{s,r} k_r),  s = 0..6,
  //   y5 = y + h sum_s b_s k_s,   y4 = y + h sum_s b_hat_s k_s,
  //   return {y5, y5 - y4}.
  // Hint: the error is h sum_s (b_s - b_hat_s) k_s; it needs no extra evaluation of f.
  unused(f, t, y, h);
  throw NotImplemented("M04T3 dormand_prince_step");
}

}  // namespace fmbd
