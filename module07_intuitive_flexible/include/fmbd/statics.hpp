#pragma once
// Static equilibrium of a model (given code, module 7): the positions where the applied and
// elastic forces balance the constraint forces at rest,
//
//   Q(q, 0, t) - C_q(q)^T lambda = 0,     C(q, t) = 0,
//
// with Q the generalised forces of applied_forces() at zero velocity (gravity, springs, and the
// elastic forces -K_ff q_f of flexible bodies). Solved by Newton's method on (q, lambda), with the
// tangent of Q by central finite differences and the constraint Jacobian of module 1.

#include "fmbd/model.hpp"

namespace fmbd {

struct StaticOptions {
  double tolerance = 1e-10;  ///< on the relative residual |(force residual, C)|
  int max_iterations = 30;
};

struct StaticSolution {
  VecX q;        ///< equilibrium positions
  VecX lambda;   ///< constraint multipliers (the negative constraint forces)
  int iterations = 0;
};

/// Equilibrium near q_guess at time t. Throws ConvergenceError (iterations, residual) if Newton's
/// method does not converge, and SingularJacobianError if the tangent is singular (a motion that
/// nothing resists, such as a body without supports).
StaticSolution static_equilibrium(const Model& model, const VecX& q_guess, double t = 0.0,
                                  const StaticOptions& options = {});

}  // namespace fmbd
