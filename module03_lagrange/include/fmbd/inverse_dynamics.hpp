#pragma once
// Inverse dynamics of a kinematically driven system (module 3, task T4).
//
//   M q_ddot + C_q^T lambda = Q_a                                              eq. (3), top row
//
// With q, q_dot, q_ddot known from the kinematic analysis (module 2), the multipliers follow
// from C_q^T lambda = Q_a - M q_ddot, n equations for m = n unknowns. The constraint forces are
// Q_c = -C_q^T lambda.

#include <vector>

#include "fmbd/kinematic_analysis.hpp"
#include "fmbd/model.hpp"

namespace fmbd {

/// Solves C_q^T lambda = rhs (given code). Throws std::invalid_argument unless the model is
/// kinematically driven (m = n), and SingularJacobianError naming the redundant constraint rows
/// if lambda is not unique.
VecX solve_multipliers(const Model& model, const MatX& Cq, const VecX& rhs);

/// M03T4. Lagrange multipliers lambda (m) at one instant of a driven motion.
VecX lagrange_multipliers(const Model& model, const VecX& q, const VecX& qd, const VecX& qdd, double t);

/// The kinematic analysis over `times` plus the multipliers at every time (given code).
struct InverseDynamicsSolution {
  KinematicSolution kinematics;
  std::vector<VecX> lambda;  ///< one entry per time, each of size m
};
InverseDynamicsSolution inverse_dynamics(const Model& model, const VecX& q_guess,
                                         const std::vector<double>& times);

}  // namespace fmbd
