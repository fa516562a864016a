// Exercise file of module 2, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory and the hints.
// Module 2, task T6: kinematic analysis of a driven mechanism over a time grid.
#include <stdexcept>
#include <string>

#include "fmbd/errors.hpp"
#include "fmbd/kinematic_analysis.hpp"

namespace fmbd {

KinematicSolution kinematic_analysis(const Model& model, const VecX& q_guess, const std::vector<double>& times,
                                     const NewtonOptions& options) {
  // TODO(M02T6): for each time t_k of `times` (check they increase; throw
  //   std::invalid_argument naming the index otherwise):
  //   1. guess: q_guess at k = 0, else q + qd dt + 1/2 qdd dt^2 from the previous time
  //      (a second-order extrapolation: Newton then needs one or two steps);
  //   2. positions by solve_positions(model, guess, t_k, options);
  //   3. velocities by solve_velocities(), accelerations by solve_accelerations();
  //   4. append t_k, q, qd, qdd and the Newton iteration count to the solution.
  unused(model, q_guess, times, options);
  throw NotImplemented("M02T6 kinematic_analysis");
}

}  // namespace fmbd
