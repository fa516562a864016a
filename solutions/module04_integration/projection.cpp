// Module 4, task T4: coordinate projection of positions and velocities.
#include <cmath>
#include <string>

#include "fmbd/constraints.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/forward_dynamics.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/mass_matrix.hpp"
#include "fmbd/projection.hpp"

#include <cstdio>

namespace fmbd {

namespace {

// A residual that may be tiny or huge, readable: "3.2e-09".
[[maybe_unused]] std::string scientific(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

}  // namespace

void project_positions(const Model& model, VecX& q, double t, const ProjectionOptions& options, DynamicsData& data) {
  // TASK(M04T4): move q (in place) to the positions with the smallest correction in the M-norm
  //   that restore C(q, t) = 0 (README section 3, projection.hpp), M = M(q) at the start, into
  //   data.M: Newton iterations, each one solve with solve_augmented(..., "project_positions",
  //   data.solution), whose .qdd holds the correction (data.zero is the top right-hand side).
  //   Stop at |C| <= options.tolerance; after options.max_iterations iterations (or at a
  //   non-finite |C|) throw ConvergenceError(message, iterations, |C|). Check the size of q.
  //   Stuck? ./workbook hint M04T4
  // BEGIN SOLUTION
  Model::check_size(q, model.num_coordinates(), "q", "project_positions");
  mass_matrix(model, q, data.M);
  const ConstraintEvaluation& e = data.constraints;
  for (int iteration = 0;; ++iteration) {
    evaluate_constraints(model, q, t, data.constraints);
    const double residual = e.C.norm();
    if (residual <= options.tolerance) return;
    if (iteration == options.max_iterations || !std::isfinite(residual))
      throw ConvergenceError("project_positions did not converge at t = " + std::to_string(t) + " after " +
                                 std::to_string(iteration) + " iterations: |C| = " + scientific(residual),
                             iteration, residual);
    data.rhs = -e.C;
    solve_augmented(model, data.M, e.Cq, data.zero, data.rhs, "project_positions", data.solution);
    q += data.solution.qdd;
  }
  // END SOLUTION
  // STUB: unused(model, q, t, options, data);
  // STUB: throw NotImplemented("M04T4 project_positions");
}

void project_velocities(const Model& model, const VecX& q, VecX& qd, double t, DynamicsData& data) {
  // TASK(M04T4): move qd (in place) to the velocities q_dot + dv that satisfy
  //   C_q (q_dot + dv) + C_t = 0 with the smallest correction dv in the M-norm (README section 3,
  //   projection.hpp), M = M(q) in data.M: one solve with solve_augmented(...,
  //   "project_velocities", data.solution). Check the size of qd.
  // BEGIN SOLUTION
  Model::check_size(qd, model.num_coordinates(), "q_dot", "project_velocities");
  mass_matrix(model, q, data.M);
  evaluate_constraints(model, q, t, data.constraints);
  const ConstraintEvaluation& e = data.constraints;
  data.rhs = -e.Ct;
  data.rhs.noalias() -= e.Cq * qd;
  solve_augmented(model, data.M, e.Cq, data.zero, data.rhs, "project_velocities", data.solution);
  qd += data.solution.qdd;
  // END SOLUTION
  // STUB: unused(model, q, qd, t, data);
  // STUB: throw NotImplemented("M04T4 project_velocities");
}

}  // namespace fmbd
