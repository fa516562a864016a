// The eigensolvers and the SVD behind linear_algebra.hpp, instantiated once (the solves are in
// linear_algebra.cpp).
#include "linear_algebra.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

namespace fmbd::testing {

using Eigen::MatrixXd;
using Eigen::VectorXd;

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
