#pragma once
// Forward dynamics in the augmented (index-3 DAE, differentiated twice) form (module 4, task T1):
//
//   [ M    C_q^T ] [ q_ddot ]   [ Q_a                              ]
//   [ C_q  0     ] [ lambda ] = [ gamma - 2 alpha C_dot - beta^2 C ]             eq. (3a)
//
// with C_dot = C_q q_dot + C_t. Without stabilisation (alpha = beta = 0) the constraints hold
// only at the acceleration level and drift; Baumgarte's terms pull C and C_dot back to zero
// like a critically damped oscillator when alpha = beta.

#include "fmbd/model.hpp"

namespace fmbd {

/// Baumgarte stabilisation parameters [1/s]; zero switches it off.
struct Baumgarte {
  double alpha = 0.0;
  double beta = 0.0;
};

/// Solution of the augmented system at one instant.
struct Accelerations {
  VecX qdd;     ///< q_ddot (n)
  VecX lambda;  ///< Lagrange multipliers (m)
};

/// Solves [M C_q^T; C_q 0] (x; y) = (top; bottom) once (given code). The system is first scaled
/// free of units (M to a unit diagonal, the rows of C_q to unit length), so that its rank
/// decisions are relative to the model's own scales. A symmetric positive definite M is solved
/// in range space: a Cholesky factor of M (one per body where M couples no two bodies, as every
/// mass matrix of the engine does) and an LL^T factor of the Schur complement C_q M^-1 C_q^T;
/// the buffers are kept per thread, so that repeated solves of one model do not allocate. Any other
/// M (singular, indefinite, or the non-symmetric matrix of an implicit integrator) by LU with
/// full pivoting of the whole scaled matrix. Throws SingularJacobianError naming the dependent
/// constraint rows when the matrix is singular (a locked or redundant mechanism), and
/// KinematicsError when an entry is not finite. `what` names the caller in messages.
Accelerations solve_augmented(const Model& model, const MatX& M, const MatX& Cq, const VecX& top,
                              const VecX& bottom, const char* what);

/// M04T1. q_ddot and lambda from eq. (3a) at (q, q_dot, t), with Baumgarte terms if given.
Accelerations forward_dynamics(const Model& model, const VecX& q, const VecX& qd, double t,
                               const Baumgarte& baumgarte = {});

}  // namespace fmbd
