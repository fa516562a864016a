#pragma once
// Velocity and acceleration analysis, and the kinematic analysis of a driven mechanism over
// time (module 2, tasks T2, T5, T6). All need a kinematically driven model: m = n and C_q
// non-singular, i.e. 0 degrees of freedom.

#include <vector>

#include "fmbd/model.hpp"
#include "fmbd/newton_raphson.hpp"

namespace fmbd {

/// M02T2. Velocity equation C_q q_dot = v with v = -C_t (eq. 2). Returns q_dot (n).
VecX solve_velocities(const Model& model, const VecX& q, double t);

/// M02T5. Acceleration equation C_q q_ddot = gamma (eq. 2). Returns q_ddot (n).
VecX solve_accelerations(const Model& model, const VecX& q, const VecX& qd, double t);

/// Positions, velocities and accelerations at each time of a grid.
struct KinematicSolution {
  std::vector<double> t;
  std::vector<VecX> q, qd, qdd;    ///< one entry per time, each of size n
  std::vector<int> iterations;     ///< Newton iterations at each time
};

/// M02T6. Kinematic analysis over `times` (increasing). At each time: positions by
/// solve_positions() from the extrapolated guess q + qd dt + 1/2 qdd dt^2 of the previous time
/// (q_guess at the first), then velocities and accelerations.
KinematicSolution kinematic_analysis(const Model& model, const VecX& q_guess, const std::vector<double>& times,
                                     const NewtonOptions& options = {});

}  // namespace fmbd
