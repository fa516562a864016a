// Exercise file of module 2, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory and the hints.
// Module 2, tasks T2 and T5: the velocity and acceleration equations (eq. 2).
#include "fmbd/constraints.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/gamma.hpp"
#include "fmbd/linear_solve.hpp"
#include "fmbd/velocity_acceleration.hpp"

namespace fmbd {

VecX solve_velocities(const Model& model, const VecX& q, double t) {
  // TODO(M02T2): velocity equation C_q q_dot = v with v = -C_t (only drivers depend on t).
  //   Use evaluate_constraints() for C_q and C_t, and
  //   solve_square(model, Cq, v, "velocity equation") for the solve: it rejects models that
  //   are not kinematically driven and singular Jacobians, naming the rows.
  unused(model, q, t);
  throw NotImplemented("M02T2 solve_velocities");
}

VecX solve_accelerations(const Model& model, const VecX& q, const VecX& qd, double t) {
  // TODO(M02T5): acceleration equation C_q q_ddot = gamma, eq. (2), with gamma from
  //   constraint_gamma() (tasks T3 and T4) and solve_square(..., "acceleration equation").
  unused(model, q, qd, t);
  throw NotImplemented("M02T5 solve_accelerations");
}

}  // namespace fmbd
