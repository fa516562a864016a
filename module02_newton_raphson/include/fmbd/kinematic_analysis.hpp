#pragma once
// The kinematic analysis of a driven mechanism over time (module 2, task T6), with the velocity
// and acceleration analysis it calls (fmbd/velocity_acceleration.hpp, tasks T2 and T5). It needs
// a kinematically driven model: m = n and C_q non-singular, i.e. 0 degrees of freedom.

#include <vector>

#include "fmbd/model.hpp"
#include "fmbd/newton_raphson.hpp"
#include "fmbd/velocity_acceleration.hpp"

namespace fmbd {

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
