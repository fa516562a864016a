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

}  // namespace fmbd
