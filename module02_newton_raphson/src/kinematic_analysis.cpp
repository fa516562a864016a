// Exercise file of module 2, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 2, task T6: kinematic analysis of a driven mechanism over a time grid.
#include <stdexcept>
#include <string>

#include "fmbd/errors.hpp"
#include "fmbd/kinematic_analysis.hpp"

namespace fmbd {

KinematicSolution kinematic_analysis(const Model& model, const VecX& q_guess, const std::vector<double>& times,
                                     const NewtonOptions& options) {
  // TODO(M02T6): positions, velocities and accelerations at every time of `times` (README
  //   sections 1-2, kinematic_analysis.hpp). Throw std::invalid_argument naming the index when
  //   the times do not increase. Positions by solve_positions() (not newton_raphson()), from
  //   q_guess at the first time and from the header's extrapolated guess after that; append t,
  //   q, qd, qdd and the Newton iterations to the solution. Stuck? ./workbook hint M02T6
  unused(model, q_guess, times, options);
  throw NotImplemented("M02T6 kinematic_analysis");
}

}  // namespace fmbd
