// Exercise file of module 2, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 2, tasks T2 and T5: the velocity and acceleration equations (eq. 2).
#include "fmbd/constraints.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/gamma.hpp"
#include "fmbd/linear_solve.hpp"
#include "fmbd/velocity_acceleration.hpp"

namespace fmbd {

VecX solve_velocities(const Model& model, const VecX& q, double t) {
  // TODO(M02T2): the velocities q_dot (n) from the velocity equation of eq. (2) (README
  //   section 2, velocity_acceleration.hpp). Take C_q and C_t from evaluate_constraints() and
  //   solve with solve_square(model, Cq, rhs, "velocity equation"): it rejects models that are
  //   not kinematically driven and singular Jacobians, naming the rows.
  //   Stuck? ./workbook hint M02T2
  unused(model, q, t);
  throw NotImplemented("M02T2 solve_velocities");
}

VecX solve_accelerations(const Model& model, const VecX& q, const VecX& qd, double t) {
  // TODO(M02T5): the accelerations q_ddot (n) from the acceleration equation of eq. (2) (README
  //   section 2, velocity_acceleration.hpp), with gamma from your constraint_gamma() (gamma.cpp)
  //   and C_q from constraint_jacobian(); solve with solve_square(model, Cq, rhs,
  //   "acceleration equation"). Stuck? ./workbook hint M02T5
  unused(model, q, qd, t);
  throw NotImplemented("M02T5 solve_accelerations");
}

}  // namespace fmbd
