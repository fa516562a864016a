#pragma once
// Velocity and acceleration analysis (module 2, tasks T2 and T5). Both need a kinematically
// driven model: m = n and C_q non-singular, i.e. 0 degrees of freedom.

#include "fmbd/model.hpp"

namespace fmbd {

/// M02T2. Velocity equation C_q q_dot = v with v = -C_t (eq. 2). Returns q_dot (n).
VecX solve_velocities(const Model& model, const VecX& q, double t);

/// M02T5. Acceleration equation C_q q_ddot = gamma (eq. 2). Returns q_ddot (n).
VecX solve_accelerations(const Model& model, const VecX& q, const VecX& qd, double t);

}  // namespace fmbd
