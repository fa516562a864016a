#pragma once
// Forward dynamics in the augmented (index-3 DAE, differentiated twice) form (module 4, task T1):
//
//   [ M    C_q^T ] [ q_ddot ]   [ Q_a                              ]
//   [ C_q  0     ] [ lambda ] = [ gamma - 2 alpha C_dot - beta^2 C ]             eq. (3)
//
// with C_dot = C_q q_dot + C_t. Without stabilisation (alpha = beta = 0) the constraints hold
// only at the acceleration level and drift; Baumgarte's terms pull C and C_dot back to zero
// like a critically damped oscillator when alpha = beta.

#include <vector>

#include "fmbd/constraints.hpp"
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
  /// Lagrange multipliers (m). Where C_q is rank deficient (rank_deficit > 0), many lambda give the
  /// same reactions on the motion; this is the one of least Euclidean norm |lambda| (redundant
  /// joints share the load evenly, as far as their rows have the same units).
  VecX lambda;
  /// m - rank C_q: how many constraint rows were dependent at this instant (redundant constraints,
  /// or a singular position). 0 on the full-rank paths.
  int rank_deficit = 0;
  /// The rows that take part in the dependency (0-based rows of C, as dependent_rows() names
  /// them); empty when rank_deficit is 0.
  std::vector<int> dependent_rows;
  /// How far C_q is from losing rank: its smallest singular value relative to its largest, free
  /// of units (rows and columns scaled as the solve scales them), as the solve estimates it (the
  /// square root of the smallest pivot of the Schur complement relative to its largest, or the
  /// SVD's own ratio on the rank-revealing path); 0 where rank_deficit > 0, 1 without constraints.
  /// Near a singular position it falls linearly to 0 at the instant of the rank loss, which lets
  /// simulate() step over that instant (SimulationOptions::step).
  double rank_margin = 1.0;
};

/// The largest componentwise backward error that counts as round-off for a linear system of
/// `size` unknowns: 4 (size + 1) eps, a few rounding errors per term of a row. solve_augmented
/// returns no result beyond it.
double augmented_round_off(Eigen::Index size);

/// The storage one evaluation of the model takes, kept by the caller from call to call so that a
/// step of simulate() allocates no memory (the Model and Data of pinocchio): sized for a model
/// once, every later call writes over the same entries. forward_dynamics() and the projections
/// (projection.hpp) fill it.
struct DynamicsData {
  /// Storage sized for `model`: constraints m, m x n, m (constraint_storage()), M n x n, Q_a n,
  /// rhs m, zero n zeros, solution q_ddot n and lambda m; all zero.
  explicit DynamicsData(const Model& model);
  ConstraintEvaluation constraints;  ///< C, C_q, C_t at the last evaluation
  MatX M;                            ///< mass matrix
  VecX Q_a;                          ///< applied forces
  VecX rhs;                          ///< the bottom right-hand side of the last solve
  VecX zero;                         ///< n zeros, the top right-hand side of a projection's solve
  Accelerations solution;            ///< q_ddot and lambda; a projection's correction in .qdd
};

/// Solves [M C_q^T; C_q 0] (x; y) = (top; bottom) once (given code), to round-off for every
/// model whose motion it determines: M positive definite on the motions that C_q allows (its null
/// space). M itself may be singular: a point mass (J = 0), a massless link. C_q may be rank
/// deficient (redundant constraints, or an instant at a singular position) as long as the
/// right-hand side `bottom` is consistent with it.
///
/// Where C_q has full row rank, the result is accepted only when its componentwise backward error
/// is round-off (at most augmented_round_off(n + m)): it is then the exact solution of the system
/// with every entry of M, C_q and the right-hand sides changed by at most that relative amount, in
/// any units. Three paths:
/// - Structured, where M is symmetric positive definite: the system scaled free of units (M to a
///   unit diagonal, the rows of C_q to unit length), a Cholesky factor of M (per body where M
///   couples no two bodies, as every mass matrix of the engine does) and a factor of the Schur
///   complement C_q M^-1 C_q^T, with at most one step of iterative refinement. Where M couples no
///   bodies and C_q has 48 rows or more, C_q and the Schur complement are kept sparse (two rows are coupled only through a body
///   both touch) and factored by a sparse LDL^T with a fill-reducing ordering: the cost grows with
///   the bodies, not the cube of the coordinates. Its dense buffers are kept per thread. Its accuracy falls
///   as the ratio m L^2 / J of a body grows, so a result that misses round-off goes on to:
/// - General: the whole augmented matrix equilibrated (rows and columns scaled to a largest
///   entry of about 1), LU with full pivoting, and iterative refinement.
/// - Rank-revealing, only where the general path finds the matrix singular (C_q rank deficient:
///   singular values of the equilibrated C_q below rank_tolerance times the largest; or of full
///   rank but ill-conditioned, as a linkage near a singular position), or where one of the first
///   two passed with a pivot below 1e-6 of the largest and an SVD finds C_q rank deficient (a zero
///   pivot lifted by round-off; the multipliers would be an arbitrary set): with Z the
///   null space of C_q and x_p the minimum-norm solution of C_q x = bottom (from an SVD),
///   q_ddot = x_p + Z (Z^T M Z)^-1 Z^T (top - M x_p), and lambda the minimum-norm multipliers
///   solving C_q^T lambda = top - M q_ddot. The result reports rank_deficit and dependent_rows.
///   `bottom` counts as consistent when the residual |bottom - C_q q_ddot| is at most
///   rank_tolerance times sigma_max |q_ddot| + |bottom| (sigma_max the largest singular value;
///   all equilibrated): the residual of a change of C_q no larger than the one the rank decision
///   already ignores. With top = 0 (a correction of least M-norm, as the projections solve: their
///   `bottom` is a residual such as C, consistent only to the round-off of its own terms), the
///   least-squares correction is returned without this check.
///
/// Throws SingularJacobianError naming the dependent constraint rows when C_q is rank deficient
/// and the constraint equations have no solution (top not zero; a locked mechanism: drivers that
/// contradict each other, a linkage that cannot move on as asked), MasslessMotionError naming the
/// body and coordinate when a motion that C_q allows carries no mass (the model is not well posed,
/// with or without redundant rows), IllConditionedError when refinement cannot reach round-off,
/// and KinematicsError when an entry is not finite. `what` names the caller in messages.
/// Writes x into out.qdd and y into out.lambda (resized only when their sizes change): a solve on
/// the structured path allocates no memory once its thread has solved a model of these sizes.
void solve_augmented(const Model& model, const MatX& M, const MatX& Cq, const VecX& top, const VecX& bottom,
                     const char* what, Accelerations& out);
/// The same, returning a new result.
Accelerations solve_augmented(const Model& model, const MatX& M, const MatX& Cq, const VecX& top,
                              const VecX& bottom, const char* what);

/// M04T1. q_ddot and lambda from eq. (3) at (q, q_dot, t), with Baumgarte terms if given,
/// into data.solution; data's other members hold the parts of eq. (3) (M, Q_a, C_q, the bottom
/// right-hand side) afterwards. `data` is sized for the model (DynamicsData(model)).
void forward_dynamics(const Model& model, const VecX& q, const VecX& qd, double t, const Baumgarte& baumgarte,
                      DynamicsData& data);

/// The same with storage of its own (given code): a new result at every call.
Accelerations forward_dynamics(const Model& model, const VecX& q, const VecX& qd, double t,
                               const Baumgarte& baumgarte = {});

}  // namespace fmbd
