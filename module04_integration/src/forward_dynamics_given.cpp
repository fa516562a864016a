#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>
#include <sstream>

#include "fmbd/dof.hpp"
#include "fmbd/forward_dynamics.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/linear_solve.hpp"

namespace fmbd {

namespace {
// Smallest pivot of a Cholesky (or LDL^T) factor, relative to the largest. Its pivots are
// squares, so 1e-13 matches a ratio of singular values of about 3e-7.
constexpr double pivot_tolerance = 1e-13;
}  // namespace

Accelerations solve_augmented(const Model& model, const MatX& M, const MatX& Cq, const VecX& top,
                              const VecX& bottom, const char* what) {
  const Eigen::Index n = M.rows(), m = Cq.rows();
  if (M.cols() != n || Cq.cols() != n || top.size() != n || bottom.size() != m)
    throw std::invalid_argument(std::string(what) + ": sizes do not match (M " + std::to_string(M.rows()) + "x" +
                                std::to_string(M.cols()) + ", C_q " + std::to_string(Cq.rows()) + "x" +
                                std::to_string(Cq.cols()) + ", right-hand sides " + std::to_string(top.size()) +
                                " and " + std::to_string(bottom.size()) + ")");
  for (Eigen::Index r = 0; r < n + m; ++r) {
    const bool finite = r < n ? M.row(r).allFinite() && Cq.col(r).allFinite() && std::isfinite(top(r))
                              : Cq.row(r - n).allFinite() && std::isfinite(bottom(r - n));
    if (!finite)
      throw KinematicsError(std::string(what) + ": the augmented system contains NaN or Inf in " +
                            (r < n ? "the equation of motion of " + model.describe_coordinate(static_cast<int>(r))
                                   : "the acceleration equation of " + model.describe_row(static_cast<int>(r - n))));
  }
  // Scaled to be free of units: D = diag(1/sqrt(M_kk)) on the coordinates, so that D M D has a
  // unit diagonal, and S = diag(1/|row r of C_q D|) on the constraints. Every rank decision
  // below is then relative, and the same mechanism in kg and m or in g and mm gives the same
  // decision and the same motion.
  VecX d(n), s(m);
  for (Eigen::Index k = 0; k < n; ++k) d(k) = M(k, k) > 0 ? 1 / std::sqrt(M(k, k)) : 1.0;
  MatX C = Cq * d.asDiagonal();
  for (Eigen::Index r = 0; r < m; ++r) {
    const double norm = C.row(r).norm();
    s(r) = norm > 0 ? 1 / norm : 1.0;
  }
  C = s.asDiagonal() * C;
  const MatX Ms = d.asDiagonal() * M * d.asDiagonal();
  const VecX b1 = d.cwiseProduct(top), b2 = s.cwiseProduct(bottom);
  auto singular = [&] {
    const std::vector<int> rows = dependent_rows(C);
    std::ostringstream msg;
    msg << what << ": the augmented matrix [M C_q^T; C_q 0] is singular";
    if (rows.empty()) {
      msg << " although C_q has full rank: check the masses and inertias";
    } else {
      msg << ": the mechanism is locked or has redundant constraints. Dependent rows:";
      for (int r : rows) msg << " row " << r << ": " << model.describe_row(r) << ";";
    }
    return SingularJacobianError(msg.str(), rows);
  };
  // A symmetric positive definite M (every mass matrix): the range-space solve,
  //   M x = b1 - C^T y,  (C M^-1 C^T) y = C M^-1 b1 - b2,
  // with a Cholesky factor of M and of the Schur complement, no pivot search.
  const bool symmetric = (Ms - Ms.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * std::max(1.0, Ms.cwiseAbs().maxCoeff());
  if (symmetric) {
    const Eigen::LLT<MatX> llt(Ms);
    if (llt.info() == Eigen::Success) {
      const VecX pivots = llt.matrixLLT().diagonal().cwiseAbs2();
      if (pivots.minCoeff() > pivot_tolerance * pivots.maxCoeff()) {
        const MatX W = llt.solve(C.transpose());  // M^-1 C^T
        const VecX z = llt.solve(b1);
        VecX y = VecX::Zero(m);
        if (m > 0) {
          const Eigen::LDLT<MatX> schur(C * W);
          const VecX D = schur.vectorD();
          if (schur.info() != Eigen::Success || !(D.minCoeff() > pivot_tolerance * D.maxCoeff()))
            throw singular();
          y = schur.solve(C * z - b2);
        }
        return {d.cwiseProduct(z - W * y), s.cwiseProduct(y)};
      }
    }
  }
  // Otherwise (a singular or indefinite M, or the non-symmetric matrices of an implicit
  // integrator): LU with full pivoting of the scaled matrix.
  MatX A = MatX::Zero(n + m, n + m);
  A.topLeftCorner(n, n) = Ms;
  A.topRightCorner(n, m) = C.transpose();
  A.bottomLeftCorner(m, n) = C;
  Eigen::FullPivLU<MatX> lu(A);
  lu.setThreshold(rank_tolerance);
  if (!lu.isInvertible()) throw singular();
  VecX b(n + m);
  b << b1, b2;
  const VecX x = lu.solve(b);
  return {d.cwiseProduct(x.head(n)), s.cwiseProduct(x.tail(m))};
}

}  // namespace fmbd
