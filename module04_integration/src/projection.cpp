// Exercise file of module 4, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory and the hints.
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
  // TODO(M04T4): smallest M-norm correction that restores C(q, t) = 0. Newton iterations:
  //   while |C| > options.tolerance: solve [M C_q^T; C_q 0] (dq; mu) = (0; -C) with
  //   solve_augmented(model, M, Cq, zero, -C, "project_positions") and update q += dq
  //   (the .qdd part of the result holds dq).
  //   After options.max_iterations iterations throw ConvergenceError(message, iterations, |C|).
  // Hint: with M = I this is the minimum-norm Newton step of module 2.
  unused(model, q, t, options);
  throw NotImplemented("M04T4 project_positions");
}

VecX project_velocities(const Model& model, const VecX& q, const VecX& qd, double t) {
  // TODO(M04T4): smallest M-norm correction dv with C_q (q_dot + dv) + C_t = 0: one solve of
  //   [M C_q^T; C_q 0] (dv; mu) = (0; -(C_q q_dot + C_t)).
  unused(model, q, qd, t);
  throw NotImplemented("M04T4 project_velocities");
}

}  // namespace fmbd
