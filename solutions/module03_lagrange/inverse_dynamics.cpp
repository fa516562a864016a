// Module 3, task T4: the Lagrange multipliers of a driven motion.
#include "fmbd/applied_forces.hpp"
#include "fmbd/constraints.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/inverse_dynamics.hpp"
#include "fmbd/mass_matrix.hpp"

namespace fmbd {

VecX lagrange_multipliers(const Model& model, const VecX& q, const VecX& qd, const VecX& qdd, double t) {
  // TASK(M03T4): inverse dynamics at one instant, from eq. (3):
  //   C_q^T lambda = Q_a - M q_ddot
  //   with C_q = constraint_jacobian(), Q_a = applied_forces(), M = mass_matrix(model, q) (your
  //   M03T1 matrix for rigid bodies; the q argument matters for the flexible bodies of module 8).
  //   Solve it with solve_multipliers(model, Cq, rhs): it refuses models that are not
  //   kinematically driven and redundant constraints, naming the rows.
  // Hint: the matrix is C_q transposed (n x m), not C_q; never invert it.
  // BEGIN SOLUTION
  Model::check_size(qdd, model.num_coordinates(), "q_ddot", "lagrange_multipliers");
  const VecX rhs = applied_forces(model, q, qd, t) - mass_matrix(model, q) * qdd;
  return solve_multipliers(model, constraint_jacobian(model, q, t), rhs);
  // END SOLUTION
  // STUB: unused(model, q, qd, qdd, t);
  // STUB: throw NotImplemented("M03T4 lagrange_multipliers");
}

}  // namespace fmbd
