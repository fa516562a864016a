#pragma once
// Rank-checked solves with the constraint Jacobian (given code, module 2). Use these instead
// of a bare Eigen solve: they refuse singular or redundant systems and name the rows.

#include <string>
#include <vector>

#include "fmbd/model.hpp"

namespace fmbd {

/// Rows of C_q that take part in a linear dependency (the support of the left null space,
/// found by SVD with rank_tolerance). Empty if C_q has full row rank.
std::vector<int> dependent_rows(const MatX& Cq);

/// Solves C_q x = rhs for a kinematically driven model (m = n equations and coordinates).
/// Throws std::invalid_argument if m < n (a degree of freedom without a driver),
/// SingularJacobianError naming the dependent rows if C_q is singular or m > n, and KinematicsError
/// if C_q or rhs is not finite. `what` names the equation in messages ("velocity equation").
VecX solve_square(const Model& model, const MatX& Cq, const VecX& rhs, const std::string& what);

/// Minimum-norm solution of C_q x = rhs for m <= n (used by Newton-Raphson, where free
/// degrees of freedom may remain). Same errors as solve_square, except m < n is allowed.
VecX solve_min_norm(const Model& model, const MatX& Cq, const VecX& rhs, const std::string& what);

}  // namespace fmbd
