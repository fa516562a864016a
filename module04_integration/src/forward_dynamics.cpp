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

Accelerations forward_dynamics(const Model& model, const VecX& q, const VecX& qd, double t,
                               const Baumgarte& baumgarte) {
  // TODO(M04T1): q_ddot (n) and lambda (m) at (q, q_dot, t) from the augmented system, eq. (3)
  //   (README section 1, forward_dynamics.hpp), with Baumgarte's terms in the bottom right-hand
  //   side (README section 3). M from mass_matrix(model, q), Q_a from applied_forces(), C, C_q,
  //   C_t from evaluate_constraints(), gamma from constraint_gamma(). Solve once with
  //   solve_augmented(..., "forward_dynamics"); never invert M. Check the size of qd.
  //   Stuck? ./workbook hint M04T1
  unused(model, q, qd, t, baumgarte);
  throw NotImplemented("M04T1 forward_dynamics");
}

}  // namespace fmbd
