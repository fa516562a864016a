// Module 2, tasks T2 and T5: the velocity and acceleration equations (eq. 2).
#include "fmbd/constraints.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/gamma.hpp"
#include "fmbd/linear_solve.hpp"
#include "fmbd/velocity_acceleration.hpp"

namespace fmbd {

VecX solve_velocities(const Model& model, const VecX& q, double t) {
  // TASK(M02T2): the velocities q_dot (n) from the velocity equation of eq. (2) (README
  //   section 2, velocity_acceleration.hpp). Take C_q and C_t from evaluate_constraints() and
  //   solve with solve_square(model, Cq, rhs, "velocity equation"): it rejects models that are
  //   not kinematically driven and singular Jacobians, naming the rows.
  //   Stuck? ./workbook hint M02T2
  // BEGIN SOLUTION
  const ConstraintEvaluation e = evaluate_constraints(model, q, t);
  return solve_square(model, e.Cq, -e.Ct, "velocity equation");
  // END SOLUTION
  // STUB: unused(model, q, t);
  // STUB: throw NotImplemented("M02T2 solve_velocities");
}

VecX solve_accelerations(const Model& model, const VecX& q, const VecX& qd, double t) {
  // TASK(M02T5): the accelerations q_ddot (n) from the acceleration equation of eq. (2) (README
  //   section 2, velocity_acceleration.hpp), with gamma from your constraint_gamma() (gamma.cpp)
  //   and C_q from constraint_jacobian(); solve with solve_square(model, Cq, rhs,
  //   "acceleration equation"). Stuck? ./workbook hint M02T5
  // BEGIN SOLUTION
  return solve_square(model, constraint_jacobian(model, q, t), constraint_gamma(model, q, qd, t),
                      "acceleration equation");
  // END SOLUTION
  // STUB: unused(model, q, qd, t);
  // STUB: throw NotImplemented("M02T5 solve_accelerations");
}

}  // namespace fmbd
