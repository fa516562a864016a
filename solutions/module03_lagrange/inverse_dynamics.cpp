// Module 3, task T4: the Lagrange multipliers of a driven motion.
#include "fmbd/applied_forces.hpp"
#include "fmbd/constraints.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/inverse_dynamics.hpp"
#include "fmbd/mass_matrix.hpp"

namespace fmbd {

VecX lagrange_multipliers(const Model& model, const VecX& q, const VecX& qd, const VecX& qdd, double t) {
  // TASK(M03T4): the multipliers lambda (m) of a driven motion at one instant, from eq. (3), top row
  //   (README section 3, inverse_dynamics.hpp). Q_a from applied_forces(), M from
  //   mass_matrix(model, q) (q matters for module 8), C_q from constraint_jacobian(). Solve with
  //   solve_multipliers(model, Cq, rhs), passing C_q itself (m x n), not its transpose: it
  //   solves C_q^T lambda = rhs and names redundant rows. Check the size of qdd
  //   (Model::check_size). Stuck? ./workbook hint M03T4
  // BEGIN SOLUTION
  Model::check_size(qdd, model.num_coordinates(), "q_ddot", "lagrange_multipliers");
  const VecX rhs = applied_forces(model, q, qd, t) - mass_matrix(model, q) * qdd;
  return solve_multipliers(model, constraint_jacobian(model, q, t), rhs);
  // END SOLUTION
  // STUB: unused(model, q, qd, qdd, t);
  // STUB: throw NotImplemented("M03T4 lagrange_multipliers");
}

}  // namespace fmbd
