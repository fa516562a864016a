// The decompositions behind linear_algebra.hpp, instantiated once.
#include "linear_algebra.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>
#include <Eigen/SVD>

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

VectorXd symmetric_eigenvalues(const MatrixXd& A) {
  return Eigen::SelfAdjointEigenSolver<MatrixXd>(A, Eigen::EigenvaluesOnly).eigenvalues();
}

GeneralizedEigen generalized_eigen(const MatrixXd& K, const MatrixXd& M, bool with_vectors) {
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatrixXd> solver(
      K, M, with_vectors ? Eigen::ComputeEigenvectors : Eigen::EigenvaluesOnly);
  GeneralizedEigen out;
  out.values = solver.eigenvalues();
  if (with_vectors) out.vectors = solver.eigenvectors();
  return out;
}

MatrixXd null_space(const MatrixXd& A, double relative_tolerance) {
  const Eigen::Index n = A.cols();
  if (A.rows() == 0) return MatrixXd::Identity(n, n);
  const Eigen::JacobiSVD<MatrixXd> svd(A, Eigen::ComputeFullV);
  const VectorXd& s = svd.singularValues();
  Eigen::Index rank = 0;
  while (rank < s.size() && s(rank) > relative_tolerance * s(0)) ++rank;
  return svd.matrixV().rightCols(n - rank);
}

}  // namespace fmbd::testing
