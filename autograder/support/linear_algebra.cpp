// The linear solves behind linear_algebra.hpp, instantiated once. The eigensolvers and the SVD
// are in linear_algebra_spectral.cpp: together, one compiler needed 670 MB.
#include "linear_algebra.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/QR>

namespace fmbd::testing {

using Eigen::MatrixXd;
using Eigen::VectorXd;

MatrixXd solve_spd(const MatrixXd& A, const MatrixXd& B) { return Eigen::LLT<MatrixXd>(A).solve(B); }

MatrixXd solve_symmetric(const MatrixXd& A, const MatrixXd& B) { return Eigen::LDLT<MatrixXd>(A).solve(B); }

MatrixXd solve_general(const MatrixXd& A, const MatrixXd& B) { return Eigen::FullPivLU<MatrixXd>(A).solve(B); }

MatrixXd least_squares(const MatrixXd& A, const MatrixXd& B) {
  return Eigen::ColPivHouseholderQR<MatrixXd>(A).solve(B);
}

bool is_positive_definite(const MatrixXd& A) {
  const MatrixXd S = 0.5 * (A + A.transpose());
  return Eigen::LLT<MatrixXd>(S).info() == Eigen::Success;
}

double determinant(const MatrixXd& A) { return Eigen::PartialPivLU<MatrixXd>(A).determinant(); }

}  // namespace fmbd::testing
