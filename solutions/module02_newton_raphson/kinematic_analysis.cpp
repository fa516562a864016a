// Module 2, task T6: kinematic analysis of a driven mechanism over a time grid.
#include <stdexcept>
#include <string>

#include "fmbd/errors.hpp"
#include "fmbd/kinematic_analysis.hpp"

namespace fmbd {

KinematicSolution kinematic_analysis(const Model& model, const VecX& q_guess, const std::vector<double>& times,
                                     const NewtonOptions& options) {
  // TASK(M02T6): positions, velocities and accelerations at every time of `times` (README
  //   sections 1-2, kinematic_analysis.hpp). Throw std::invalid_argument naming the index when
  //   the times do not increase. Positions by solve_positions() (not newton_raphson()), from
  //   q_guess at the first time and from the header's extrapolated guess after that; append t,
  //   q, qd, qdd and the Newton iterations to the solution. Stuck? ./workbook hint M02T6
  // BEGIN SOLUTION
  KinematicSolution out;
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (k > 0 && !(times[k] > times[k - 1]))
      throw std::invalid_argument("kinematic_analysis: times must increase, but times[" + std::to_string(k) +
                                  "] = " + std::to_string(times[k]) + " follows " + std::to_string(times[k - 1]));
    VecX guess = q_guess;
    if (k > 0) {
      const double dt = times[k] - times[k - 1];
      guess = out.q.back() + dt * out.qd.back() + 0.5 * dt * dt * out.qdd.back();
    }
    const NewtonResult position = solve_positions(model, guess, times[k], options);
    const VecX qd = solve_velocities(model, position.q, times[k]);
    out.qdd.push_back(solve_accelerations(model, position.q, qd, times[k]));
    out.t.push_back(times[k]);
    out.q.push_back(position.q);
    out.qd.push_back(qd);
    out.iterations.push_back(position.iterations);
  }
  return out;
  // END SOLUTION
  // STUB: unused(model, q_guess, times, options);
  // STUB: throw NotImplemented("M02T6 kinematic_analysis");
}

}  // namespace fmbd
