#pragma once
// Errors of the kinematic solvers (module 2). Each message names the culprit: iteration
// count and residual, the constraint rows involved, or the time of the failing step.

#include <stdexcept>
#include <string>
#include <vector>

namespace fmbd {

/// Base of the errors below.
class KinematicsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Newton-Raphson did not reach the tolerance within the iteration limit.
class ConvergenceError : public KinematicsError {
 public:
  ConvergenceError(const std::string& message, int iterations, double residual)
      : KinematicsError(message), iterations(iterations), residual(residual) {}
  int iterations;   ///< iterations done
  double residual;  ///< |C| at the last iterate (may be NaN or Inf)
};

/// C_q is singular or has dependent (redundant) rows: the linear solve has no unique answer.
class SingularJacobianError : public KinematicsError {
 public:
  SingularJacobianError(const std::string& message, std::vector<int> rows)
      : KinematicsError(message), rows(std::move(rows)) {}
  std::vector<int> rows;  ///< 0-based rows of C involved in the dependency
};

/// The constraints cannot all be satisfied near the guess, e.g. a four-bar whose links cannot
/// close: the least-squares minimum of |C| stays away from zero.
class UnreachableConfigurationError : public KinematicsError {
 public:
  UnreachableConfigurationError(const std::string& message, double residual)
      : KinematicsError(message), residual(residual) {}
  double residual;  ///< smallest |C| found
};

/// The model is not well posed at this configuration: the constraints allow a motion that carries
/// no mass (M is not positive definite on the null space of C_q), so the accelerations are not
/// determined. Example: a body with zero inertia that no joint keeps from turning. The message
/// names the body and the coordinate that move.
class MasslessMotionError : public KinematicsError {
 public:
  MasslessMotionError(const std::string& message, std::string body, int coordinate)
      : KinematicsError(message), body(std::move(body)), coordinate(coordinate) {}
  std::string body;  ///< name of the body that moves most in that motion
  int coordinate;    ///< its entry of q that moves most (0-based)
};

/// A linear solve did not reach round-off accuracy: the componentwise backward error of its result
/// stays above the limit after iterative refinement, because the system is singular to working
/// precision (e.g. constraints that are independent only by a hair).
class IllConditionedError : public KinematicsError {
 public:
  IllConditionedError(const std::string& message, double backward_error)
      : KinematicsError(message), backward_error(backward_error) {}
  double backward_error;  ///< the componentwise backward error reached
};

}  // namespace fmbd
