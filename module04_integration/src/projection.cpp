// Exercise file of module 4, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
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
  // TODO(M04T4): move q (in place) to the positions with the smallest correction in the M-norm
  //   that restore C(q, t) = 0 (README section 3, projection.hpp), M = M(q) at the start, into
  //   data.M: Newton iterations, each one solve with solve_augmented(..., "project_positions",
  //   data.solution), whose .qdd holds the correction (data.zero is the top right-hand side).
  //   Stop at |C| <= options.tolerance; after options.max_iterations iterations (or at a
  //   non-finite |C|) throw ConvergenceError(message, iterations, |C|). Check the size of q.
  //   Stuck? ./workbook hint M04T4
  unused(model, q, t, options, data);
  throw NotImplemented("M04T4 project_positions");
}

void project_velocities(const Model& model, const VecX& q, VecX& qd, double t, DynamicsData& data) {
  // TODO(M04T4): move qd (in place) to the velocities q_dot + dv that satisfy
  //   C_q (q_dot + dv) + C_t = 0 with the smallest correction dv in the M-norm (README section 3,
  //   projection.hpp), M = M(q) in data.M: one solve with solve_augmented(...,
  //   "project_velocities", data.solution). Check the size of qd.
  unused(model, q, qd, t, data);
  throw NotImplemented("M04T4 project_velocities");
}

}  // namespace fmbd
