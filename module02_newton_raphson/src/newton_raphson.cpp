// Exercise file of module 2, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 2, task T1: Newton-Raphson for the position problem C(q, t) = 0.
#include <cmath>

#include "fmbd/constraints.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/linear_solve.hpp"
#include "fmbd/newton_raphson.hpp"

namespace fmbd {

NewtonResult newton_raphson(const Model& model, const VecX& q_guess, double t, const NewtonOptions& options) {
  // TODO(M02T1): Newton-Raphson for C(q, t) = 0 at the fixed time t, from q_guess (README
  //   section 1, newton_raphson.hpp). Record |C| in result.residuals before each step and at the
  //   end, count the steps in result.iterations, stop when |C| <= options.tolerance. Solve each
  //   step with solve_min_norm(model, Cq, rhs, "Newton-Raphson"); never invert C_q. After
  //   options.max_iterations steps (or at a non-finite |C|) call throw_not_converged(model, q, t,
  //   result). Check the size of q_guess first (Model::check_size). Stuck? ./workbook hint M02T1
  unused(model, q_guess, t, options);
  throw NotImplemented("M02T1 newton_raphson");
}

}  // namespace fmbd
