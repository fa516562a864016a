#pragma once
// One-step integrators for y' = f(t, y) (module 4, tasks T2-T3). For a multibody system
// y = (q, q_dot) and f = (q_dot, q_ddot from forward dynamics).

#include <array>
#include <functional>

#include "fmbd/model.hpp"

namespace fmbd {

/// The right-hand side f(t, y, dy): writes y' = f(t, y) into dy (resizing it to y's size if it
/// has another size), so that a caller that keeps dy from step to step allocates nothing.
using OdeRhsInto = std::function<void(double t, const VecX& y, VecX& dy)>;
/// The same as a function that returns y'.
using OdeRhs = std::function<VecX(double t, const VecX& y)>;

/// Result of one step of an embedded pair.
struct EmbeddedStep {
  VecX y;      ///< the 5th-order solution (used to continue: local extrapolation)
  VecX error;  ///< y5 - y4, the local error estimate
};

/// Dormand-Prince 5(4) coefficients (Dormand & Prince 1980): nodes c, matrix a, weights b
/// (5th order) and b_hat (4th order, embedded).
struct DormandPrince {
  static constexpr int stages = 7;
  static constexpr double c[7] = {0.0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1.0, 1.0};
  static constexpr double a[7][6] = {
      {},
      {1.0 / 5},
      {3.0 / 40, 9.0 / 40},
      {44.0 / 45, -56.0 / 15, 32.0 / 9},
      {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
      {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
      {35.0 / 384, 0.0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}};
  static constexpr double b[7] = {35.0 / 384, 0.0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0.0};
  static constexpr double b_hat[7] = {5179.0 / 57600, 0.0, 7571.0 / 16695, 393.0 / 640,
                                      -92097.0 / 339200, 187.0 / 2100, 1.0 / 40};
};

/// The storage of a one-step method's stages, kept by the caller from step to step (as
/// DynamicsData for forward dynamics): k[s] the slope of stage s, y_stage the state at which a
/// stage evaluates f. A method writes over them; they take their sizes at the first step
/// (Eigen resizes on assignment), so that the later steps allocate nothing.
struct Stages {
  std::array<VecX, 7> k;
  VecX y_stage;
};

/// M04T2. Explicit Euler, y_new = y + h f(t, y): first order. y_new may not be y.
void euler_step(const OdeRhsInto& f, double t, const VecX& y, double h, Stages& stages, VecX& y_new);

/// M04T2. Classical Runge-Kutta of order 4 (four evaluations of f) into y_new, which may not be y.
void rk4_step(const OdeRhsInto& f, double t, const VecX& y, double h, Stages& stages, VecX& y_new);

/// M04T3. One Dormand-Prince 5(4) step from (t, y) with step h into `step` (y5 and y5 - y4).
void dormand_prince_step(const OdeRhsInto& f, double t, const VecX& y, double h, Stages& stages,
                         EmbeddedStep& step);

/// The three methods with storage of their own and a right-hand side that returns y' (given
/// code): a new result at every call.
VecX euler_step(const OdeRhs& f, double t, const VecX& y, double h);
VecX rk4_step(const OdeRhs& f, double t, const VecX& y, double h);
EmbeddedStep dormand_prince_step(const OdeRhs& f, double t, const VecX& y, double h);

/// Weighted RMS norm of a local error, sqrt(mean((e_k / (atol + rtol max(|y_k|, |y_new_k|)))^2)):
/// a step is accepted when it is <= 1 (given code).
double error_norm(const Eigen::Ref<const VecX>& error, const Eigen::Ref<const VecX>& y,
                  const Eigen::Ref<const VecX>& y_new, double rtol, double atol);

}  // namespace fmbd
