// Exercise file of module 5, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 5, task T5: the generalised eigenproblem K phi = omega^2 M phi.
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <sstream>

#include "fmbd/errors.hpp"
#include "fmbd/modal.hpp"

namespace fmbd {

namespace {

void check_symmetric(const MatX& A, const char* name, Eigen::Index n) {
  std::ostringstream s;
  s << "modal_analysis: " << name;
  if (A.rows() != n || A.cols() != n) {
    s << " is " << A.rows() << "x" << A.cols() << ", expected " << n << "x" << n;
    throw std::invalid_argument(s.str());
  }
  if (!A.allFinite()) throw std::invalid_argument(s.str() + " is not finite");
  const double asym = (A - A.transpose()).cwiseAbs().maxCoeff();
  if (asym > 1e-10 * std::max(A.cwiseAbs().maxCoeff(), 1e-300)) {
    s << " is not symmetric (max |A - A^T| = " << asym << ")";
    throw std::invalid_argument(s.str());
  }
}

}  // namespace

Modes modal_analysis(const MatX& K, const MatX& M, int count) {
  const Eigen::Index n = K.rows();
  check_symmetric(K, "K", n);
  check_symmetric(M, "M", n);
  if (count < 1 || count > n)
    throw std::invalid_argument("modal_analysis: count must be between 1 and " + std::to_string(n) + ", got " +
                                std::to_string(count));
  if (Eigen::LLT<MatX>(M).info() != Eigen::Success)
    throw std::invalid_argument("modal_analysis: M is not positive definite (a DOF without mass?)");
  // TODO(M05T5): the `count` lowest modes of K phi = omega^2 M phi, README section 4, modal.hpp:
  //   omega ascending (round-off negative eigenvalues give 0), shapes as columns, mass-normalised.
  //   Solve the generalised problem as it stands with Eigen::GeneralizedSelfAdjointEigenSolver<MatX>,
  //   never through M^-1 K; throw std::runtime_error if it does not converge.
  //   Stuck? ./workbook hint M05T5
  unused(K, M, count);
  throw NotImplemented("M05T5 modal_analysis");
}

}  // namespace fmbd
