#include <Eigen/LU>
#include <cmath>
#include <sstream>

#include "fmbd/dof.hpp"
#include "fmbd/forward_dynamics.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/linear_solve.hpp"

namespace fmbd {

Accelerations solve_augmented(const Model& model, const MatX& M, const MatX& Cq, const VecX& top,
                              const VecX& bottom, const char* what) {
  const Eigen::Index n = M.rows(), m = Cq.rows();
  if (M.cols() != n || Cq.cols() != n || top.size() != n || bottom.size() != m)
    throw std::invalid_argument(std::string(what) + ": sizes do not match (M " + std::to_string(M.rows()) + "x" +
                                std::to_string(M.cols()) + ", C_q " + std::to_string(Cq.rows()) + "x" +
                                std::to_string(Cq.cols()) + ", right-hand sides " + std::to_string(top.size()) +
                                " and " + std::to_string(bottom.size()) + ")");
  MatX A = MatX::Zero(n + m, n + m);
  A.topLeftCorner(n, n) = M;
  A.topRightCorner(n, m) = Cq.transpose();
  A.bottomLeftCorner(m, n) = Cq;
  VecX b(n + m);
  b << top, bottom;
  for (Eigen::Index r = 0; r < n + m; ++r) {
    if (!A.row(r).allFinite() || !std::isfinite(b(r)))
      throw KinematicsError(std::string(what) + ": the augmented system contains NaN or Inf in " +
                            (r < n ? "the equation of motion of " + model.describe_coordinate(static_cast<int>(r))
                                   : "the acceleration equation of " + model.describe_row(static_cast<int>(r - n))));
  }
  Eigen::FullPivLU<MatX> lu(A);
  lu.setThreshold(rank_tolerance);
  if (!lu.isInvertible()) {
    const std::vector<int> rows = dependent_rows(Cq);
    std::ostringstream s;
    s << what << ": the augmented matrix [M C_q^T; C_q 0] is singular";
    if (rows.empty()) {
      s << " although C_q has full rank: check the masses and inertias";
    } else {
      s << ": the mechanism is locked or has redundant constraints. Dependent rows:";
      for (int r : rows) s << " row " << r << ": " << model.describe_row(r) << ";";
    }
    throw SingularJacobianError(s.str(), rows);
  }
  const VecX x = lu.solve(b);
  return {x.head(n), x.tail(m)};
}

}  // namespace fmbd
