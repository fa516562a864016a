// Exercise file of module 2, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory and the hints.
// Module 2, task T1: Newton-Raphson for the position problem C(q, t) = 0.
#include <cmath>

#include "fmbd/constraints.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/linear_solve.hpp"
#include "fmbd/newton_raphson.hpp"

namespace fmbd {

NewtonResult newton_raphson(const Model& model, const VecX& q_guess, double t, const NewtonOptions& options) {
  // TODO(M02T1): Newton-Raphson iteration, eq. (1):
  //   repeat: evaluate C and C_q at q (evaluate_constraints()); record |C| in
  //           result.residuals; stop when |C| <= options.tolerance;
  //           otherwise solve C_q dq = -C with solve_min_norm(model, Cq, -C, "Newton-Raphson")
  //           and update q += dq, counting result.iterations.
  //   When options.max_iterations steps have been taken (or |C| is NaN), call
  //   throw_not_converged(model, q, t, result): it throws a ConvergenceError that reports them.
  // Hints: check q_guess.size() first (Model::check_size). Never invert C_q, and never use
  //   dq = -C: without the Jacobian solve the update has the wrong size and units.
  unused(model, q_guess, t, options);
  throw NotImplemented("M02T1 newton_raphson");
}

}  // namespace fmbd
