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

VecX project_positions(const Model& model, const VecX& q, double t, const ProjectionOptions& options) {
  // TASK(M04T4): the positions with the smallest correction in the M-norm that restore
  //   C(q, t) = 0 (README section 3, projection.hpp), M = mass_matrix(model, q): Newton iterations,
  //   each one solve with solve_augmented(..., "project_positions"), whose .qdd holds the
  //   correction. Stop at |C| <= options.tolerance; after options.max_iterations iterations (or
  //   at a non-finite |C|) throw ConvergenceError(message, iterations, |C|). Check the size of q.
  //   Stuck? ./workbook hint M04T4
  // BEGIN SOLUTION
  Model::check_size(q, model.num_coordinates(), "q", "project_positions");
  const MatX M = mass_matrix(model, q);
  const VecX zero = VecX::Zero(q.size());
  VecX p = q;
  for (int iteration = 0;; ++iteration) {
    const ConstraintEvaluation e = evaluate_constraints(model, p, t);
    const double residual = e.C.norm();
    if (residual <= options.tolerance) return p;
    if (iteration == options.max_iterations || !std::isfinite(residual))
      throw ConvergenceError("project_positions did not converge at t = " + std::to_string(t) + " after " +
                                 std::to_string(iteration) + " iterations: |C| = " + scientific(residual),
                             iteration, residual);
    p += solve_augmented(model, M, e.Cq, zero, -e.C, "project_positions").qdd;
  }
  // END SOLUTION
  // STUB: unused(model, q, t, options);
  // STUB: throw NotImplemented("M04T4 project_positions");
}

VecX project_velocities(const Model& model, const VecX& q, const VecX& qd, double t) {
  // TASK(M04T4): the velocities q_dot + dv that satisfy C_q (q_dot + dv) + C_t = 0 with the
  //   smallest correction dv in the M-norm (README section 3, projection.hpp), M =
  //   mass_matrix(model, q): one solve with solve_augmented(..., "project_velocities"). Check the
  //   size of qd.
  // BEGIN SOLUTION
  Model::check_size(qd, model.num_coordinates(), "q_dot", "project_velocities");
  const ConstraintEvaluation e = evaluate_constraints(model, q, t);
  return qd + solve_augmented(model, mass_matrix(model, q), e.Cq, VecX::Zero(qd.size()), -(e.Cq * qd + e.Ct),
                              "project_velocities")
                  .qdd;
  // END SOLUTION
  // STUB: unused(model, q, qd, t);
  // STUB: throw NotImplemented("M04T4 project_velocities");
}

}  // namespace fmbd
