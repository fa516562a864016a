#pragma once
// The rank-revealing path of solve_augmented (given code, module 4; forward_dynamics.hpp describes
// its three paths), the equilibration it shares with the general path, and the constants of
// both files of the solve (forward_dynamics_given.cpp: the structured and general paths;
// rank_revealing_given.cpp: this one).

#include <string>

#include "fmbd/forward_dynamics.hpp"

namespace fmbd::augmented {

/// Smallest pivot of a Cholesky factor, relative to the largest. Its pivots are squares, so 1e-13
/// matches a ratio of singular values of about 3e-7.
inline constexpr double pivot_tolerance = 1e-13;

/// From this many constraint rows on (with M per body), C_q and the Schur complement are sparse,
/// and a rank decision takes the divide and conquer SVD. Below it the dense products of a few
/// dozen rows cost less than the sparse bookkeeping: the seven-body loop's 20 rows take 78 us a
/// step dense and 109 us sparse, a chain of 40 parallelogram windows (242 rows) 25 ms dense and
/// 2.9 ms sparse.
inline constexpr Eigen::Index kSparseRows = 48;

/// Whether A is symmetric to 1e-12 of its largest entry.
template <typename Matrix>
bool symmetric(const Matrix& A) {
  return (A - A.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * A.cwiseAbs().maxCoeff();
}

/// A = diag(row_scale) [M C_q^T; C_q 0] diag(col_scale), equilibrated (rows and columns to a
/// largest entry of about 1; the scales come from the geometry of C_q, not the masses).
struct Equilibrated {
  MatX A;
  VecX row_scale, col_scale;
};
Equilibrated equilibrate(const MatX& M, const MatX& Cq);

/// Throws MasslessMotionError: a motion that the constraints allow carries no mass; `head` says
/// where it was found, coordinate k (the one that moves most in it) names the culprit.
[[noreturn]] void throw_massless(const Model& model, Eigen::Index k, const std::string& head);

/// Step 3 on the equilibrated system e: the SVD of its C_q block, q_ddot = x_p + Z (Z^T M Z)^-1
/// Z^T (top - M x_p) and the minimum-norm multipliers (also where C_q has full rank but the general
/// path found the augmented matrix singular).
Accelerations solve_rank_revealing(const Model& model, const MatX& M, const MatX& Cq, const VecX& top,
                                   const VecX& bottom, const Equilibrated& e, const char* what);

/// Step 3 where an SVD finds C_q rank deficient: the result in `out` and true; false (out
/// untouched) where C_q has full rank.
bool solve_if_rank_deficient(const Model& model, const MatX& M, const MatX& Cq, const VecX& top, const VecX& bottom,
                             const Equilibrated& e, const char* what, Accelerations& out);

}  // namespace fmbd::augmented
