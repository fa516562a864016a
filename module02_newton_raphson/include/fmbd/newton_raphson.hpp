#pragma once
// Position analysis: solve C(q, t) = 0 (eq. 1) for q by Newton-Raphson (module 2, task T1).
//
//   C_q(q_k, t) dq = -C(q_k, t),    q_{k+1} = q_k + dq,    until |C(q_k, t)| <= tolerance.
//
// With m < n equations (free degrees of freedom) the step is the minimum-norm solution, so
// the solver also assembles an undriven mechanism close to its guess.

#include <vector>

#include "fmbd/model.hpp"

namespace fmbd {

struct NewtonOptions {
  double tolerance = 1e-10;  ///< on the Euclidean norm |C|
  int max_iterations = 25;
};

struct NewtonResult {
  VecX q;                          ///< solution (size n)
  int iterations = 0;              ///< Newton steps taken (0 if the guess already satisfied C = 0)
  std::vector<double> residuals;   ///< |C| before each step and at the end (iterations + 1 entries)
};

/// M02T1. Newton-Raphson from q_guess at time t. Uses solve_min_norm() for the step, so a
/// singular C_q throws SingularJacobianError; after max_iterations steps without reaching the
/// tolerance it calls throw_not_converged(). Throws std::invalid_argument for a wrong size.
NewtonResult newton_raphson(const Model& model, const VecX& q_guess, double t,
                            const NewtonOptions& options = {});

/// Throws ConvergenceError with the iteration count, the residual history and the constraint
/// row with the largest residual (given code; call it when the iterations run out).
[[noreturn]] void throw_not_converged(const Model& model, const VecX& q_last, double t,
                                      const NewtonResult& progress);

/// The position analysis of the workbook: newton_raphson() plus a diagnosis of failures.
/// When Newton fails, a damped least-squares search decides whether C = 0 can be reached at
/// all; if not, UnreachableConfigurationError says so and names the rows that stay violated.
NewtonResult solve_positions(const Model& model, const VecX& q_guess, double t,
                             const NewtonOptions& options = {});

}  // namespace fmbd
