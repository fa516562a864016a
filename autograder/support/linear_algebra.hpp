#pragma once
// Dense linear algebra for the graded tests' oracles, compiled once for every module
// (linear_algebra.cpp). Eigen's decompositions are the costliest templates a test file can
// instantiate (a generalised eigensolver takes seconds of compile time in every file that names
// it), so test files call these functions instead of including <Eigen/Cholesky>, <Eigen/LU>,
// <Eigen/QR>, <Eigen/SVD> or <Eigen/Eigenvalues>.
//
// None of them throws on a bad matrix: like Eigen, they return what the decomposition gives, and
// the test's check on the result reports the problem. Fixed-size arguments convert to MatrixXd.

#include <Eigen/Core>

namespace fmbd::testing {

/// x with A x = B for symmetric positive definite A (Cholesky, LLT).
Eigen::MatrixXd solve_spd(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B);

/// x with A x = B for symmetric A, definite or semi-definite (LDLT with pivoting).
Eigen::MatrixXd solve_symmetric(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B);

/// x with A x = B for any square A (LU with full pivoting).
Eigen::MatrixXd solve_general(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B);

/// x minimising |A x - B| column by column (QR with column pivoting).
Eigen::MatrixXd least_squares(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B);

/// Whether the symmetric part of A has a Cholesky factor (A is positive definite).
bool is_positive_definite(const Eigen::MatrixXd& A);

/// det(A), by LU with partial pivoting.
double determinant(const Eigen::MatrixXd& A);

/// Eigenvalues of the symmetric matrix A (its lower triangle is read), ascending.
Eigen::VectorXd symmetric_eigenvalues(const Eigen::MatrixXd& A);

/// K v = lambda M v for symmetric K and symmetric positive definite M: eigenvalues ascending,
/// eigenvectors M-normalised in the columns (empty when not asked for).
struct GeneralizedEigen {
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
};
GeneralizedEigen generalized_eigen(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M,
                                   bool with_vectors = true);

/// An orthonormal basis of the null space of A (columns), from the SVD: the right singular
/// vectors whose singular value is at most relative_tolerance times the largest.
Eigen::MatrixXd null_space(const Eigen::MatrixXd& A, double relative_tolerance);

}  // namespace fmbd::testing
