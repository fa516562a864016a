// Exercise file of module 4, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 4, task T1: accelerations and multipliers from the augmented system, eq. (3).
#include "fmbd/applied_forces.hpp"
#include "fmbd/constraints.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/forward_dynamics.hpp"
#include "fmbd/gamma.hpp"
#include "fmbd/mass_matrix.hpp"

namespace fmbd {

void forward_dynamics(const Model& model, const VecX& q, const VecX& qd, double t, const Baumgarte& baumgarte,
                      DynamicsData& data) {
  // TODO(M04T1): q_ddot (n) and lambda (m) at (q, q_dot, t) from the augmented system, eq. (3)
  //   (README section 1, forward_dynamics.hpp), with Baumgarte's terms in the bottom right-hand
  //   side (README section 3), into data.solution. Assemble the parts into data's own storage:
  //   mass_matrix(model, q, data.M), applied_forces(..., data.Q_a), evaluate_constraints(...,
  //   data.constraints) for C, C_q, C_t, constraint_gamma(..., data.rhs) for gamma. Solve once
  //   with solve_augmented(..., "forward_dynamics", data.solution); never invert M. Check the
  //   size of qd. Stuck? ./workbook hint M04T1
  unused(model, q, qd, t, baumgarte, data);
  throw NotImplemented("M04T1 forward_dynamics");
}

}  // namespace fmbd
