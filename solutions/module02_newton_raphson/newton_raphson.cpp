// Module 2, task T1: Newton-Raphson for the position problem C(q, t) = 0.
#include <cmath>

#include "fmbd/constraints.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/linear_solve.hpp"
#include "fmbd/newton_raphson.hpp"

namespace fmbd {

NewtonResult newton_raphson(const Model& model, const VecX& q_guess, double t, const NewtonOptions& options) {
  // TASK(M02T1): Newton-Raphson for C(q, t) = 0 at the fixed time t, from q_guess (README
  //   section 1, newton_raphson.hpp). Record |C| in result.residuals before each step and at the
  //   end, count the steps in result.iterations, stop when |C| <= options.tolerance. Solve each
  //   step with solve_min_norm(model, Cq, rhs, "Newton-Raphson"); never invert C_q. After
  //   options.max_iterations steps (or at a non-finite |C|) call throw_not_converged(model, q, t,
  //   result). Check the size of q_guess first (Model::check_size). Stuck? ./workbook hint M02T1
  // BEGIN SOLUTION
  Model::check_size(q_guess, model.num_coordinates(), "q_guess", "newton_raphson");
  NewtonResult result;
  result.q = q_guess;
  for (;;) {
    const ConstraintEvaluation e = evaluate_constraints(model, result.q, t);
    const double residual = e.C.norm();
    result.residuals.push_back(residual);
    if (residual <= options.tolerance) return result;
    if (result.iterations >= options.max_iterations || !std::isfinite(residual))
      throw_not_converged(model, result.q, t, result);
    result.q += solve_min_norm(model, e.Cq, -e.C, "Newton-Raphson");
    ++result.iterations;
  }
  // END SOLUTION
  // STUB: unused(model, q_guess, t, options);
  // STUB: throw NotImplemented("M02T1 newton_raphson");
}

}  // namespace fmbd
