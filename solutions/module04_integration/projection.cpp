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
  // TASK(M04T4): smallest M-norm correction that restores C(q, t) = 0. Newton iterations:
  //   while |C| > options.tolerance: solve [M C_q^T; C_q 0] (dq; mu) = (0; -C) with
  //   solve_augmented(model, M, Cq, zero, -C, "project_positions") and update q += dq
  //   (the .qdd part of the result holds dq).
  //   After options.max_iterations iterations throw ConvergenceError(message, iterations, |C|).
  // Hint: with M = I this is the minimum-norm Newton step of module 2.
  // BEGIN SOLUTION
  Model::check_size(q, model.num_coordinates(), "q", "project_positions");
  const MatX M = mass_matrix(model);
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
  // TASK(M04T4): smallest M-norm correction dv with C_q (q_dot + dv) + C_t = 0: one solve of
  //   [M C_q^T; C_q 0] (dv; mu) = (0; -(C_q q_dot + C_t)).
  // BEGIN SOLUTION
  Model::check_size(qd, model.num_coordinates(), "q_dot", "project_velocities");
  const ConstraintEvaluation e = evaluate_constraints(model, q, t);
  return qd + solve_augmented(model, mass_matrix(model), e.Cq, VecX::Zero(qd.size()), -(e.Cq * qd + e.Ct),
                              "project_velocities")
                  .qdd;
  // END SOLUTION
  // STUB: unused(model, q, qd, t);
  // STUB: throw NotImplemented("M04T4 project_velocities");
}

}  // namespace fmbd
