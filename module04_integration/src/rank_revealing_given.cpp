#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <cmath>
#include <sstream>
#include <vector>

#include "fmbd/dof.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/rank_revealing.hpp"

namespace fmbd::augmented {

// The scales come from the geometry, not the masses: the rows and columns of C_q are
// equilibrated (each to a largest entry of about 1, which turns an angle into a length at the
// scale of the body's joints), M is divided by its largest scaled diagonal entry mu, and a
// coordinate that no constraint touches takes the scale of its mass. A few sweeps then
// equilibrate the whole matrix.
Equilibrated equilibrate(const MatX& M, const MatX& Cq) {
  const Eigen::Index n = M.rows(), m = Cq.rows(), size = n + m;
  VecX col = VecX::Ones(n), row = VecX::Ones(m);
  auto inverse_sqrt = [](double v) { return v > 0 ? 1 / std::sqrt(v) : 1.0; };
  for (int sweep = 0; sweep < 20 && m > 0; ++sweep) {
    const MatX scaled = row.asDiagonal() * Cq * col.asDiagonal();
    const VecX r = scaled.cwiseAbs().rowwise().maxCoeff(), c = scaled.cwiseAbs().colwise().maxCoeff().transpose();
    auto balanced = [](const VecX& v) { return ((v.array() == 0) || (v.array() > 0.5 && v.array() < 2)).all(); };
    if (balanced(r) && balanced(c)) break;
    row.array() *= r.unaryExpr(inverse_sqrt).array();
    col.array() *= c.unaryExpr(inverse_sqrt).array();
  }
  const VecX touched = (row.asDiagonal() * Cq).cwiseAbs().colwise().maxCoeff().transpose();
  double mu = 0;
  for (Eigen::Index k = 0; k < n; ++k)
    if (touched(k) > 0) mu = std::max(mu, col(k) * col(k) * std::abs(M(k, k)));
  if (!(mu > 0)) mu = M.diagonal().cwiseAbs().maxCoeff();
  if (!(mu > 0)) mu = 1;
  for (Eigen::Index k = 0; k < n; ++k)
    if (!(touched(k) > 0)) col(k) = M(k, k) != 0 ? std::sqrt(mu / std::abs(M(k, k))) : 1.0;
  // A = R [M C_q^T; C_q 0] Cs with R = diag(col / mu, row) and Cs = diag(col, mu row).
  Equilibrated e{MatX(size, size), VecX(size), VecX(size)};
  VecX &row_scale = e.row_scale, &col_scale = e.col_scale;
  MatX& A = e.A;
  row_scale << col / mu, row;
  col_scale << col, mu * row;
  A << M, Cq.transpose(), Cq, MatX::Zero(m, m);
  A = row_scale.asDiagonal() * A * col_scale.asDiagonal();
  for (int sweep = 0; sweep < 10; ++sweep) {
    const VecX r = A.cwiseAbs().rowwise().maxCoeff(), c = A.cwiseAbs().colwise().maxCoeff().transpose();
    if ((r.array() > 0.5).all() && (r.array() < 2).all() && (c.array() > 0.5).all() && (c.array() < 2).all()) break;
    const VecX dr = r.unaryExpr(inverse_sqrt), dc = c.unaryExpr(inverse_sqrt);
    A = dr.asDiagonal() * A * dc.asDiagonal();
    row_scale.array() *= dr.array();
    col_scale.array() *= dc.array();
  }
  return e;
}

[[noreturn]] void throw_massless(const Model& model, Eigen::Index k, const std::string& head) {
  int body = 0;
  while (body + 1 < model.num_bodies() && model.offset(BodyId{body + 1}) <= k) ++body;
  const std::string name = model.bodies()[body].name;
  std::ostringstream msg;
  msg << head << " The constraints let " << model.describe_coordinate(static_cast<int>(k))
      << " move without mass (M is not positive definite on the motions that C_q allows). Give body '" << name
      << "' mass or inertia in that direction, or a joint that holds it";
  throw MasslessMotionError(msg.str(), name, static_cast<int>(k));
}

namespace {

// ---- 3. The rank-revealing solve, where C_q is rank deficient ----------------------------------

// The SVD of the equilibrated C_q (Ce = R C_q C, R and C the general path's scales, free of
// units), with its rank counted as dependent_rows() counts it: singular values above
// rank_tolerance times the largest.
struct RankRevealed {
  MatX U, V;  // full: m x m and n x n
  VecX sigma;
  Eigen::Index rank = 0;
  // A large C_q (kSparseRows rows or more: a long chain at a singular position) by the divide and
  // conquer SVD, as accurate relative to the largest singular value, which is all the rank
  // decision uses, and several times faster at a few hundred rows than one-sided Jacobi.
  explicit RankRevealed(const MatX& Ce) {
    if (Ce.rows() >= kSparseRows)
      take(Eigen::BDCSVD<MatX>(Ce, Eigen::ComputeFullU | Eigen::ComputeFullV));
    else
      take(Eigen::JacobiSVD<MatX>(Ce, Eigen::ComputeFullU | Eigen::ComputeFullV));
    const double cut = rank_tolerance * (sigma.size() ? sigma(0) : 0.0);
    while (rank < sigma.size() && sigma(rank) > cut) ++rank;
  }
  template <typename Svd>
  void take(const Svd& svd) {
    U = svd.matrixU();
    V = svd.matrixV();
    sigma = svd.singularValues();
  }
  // The minimum-norm (least-squares) solution of Ce x = b, and of Ce^T y = c.
  VecX solve(const VecX& b) const {
    const VecX inner = U.leftCols(rank).transpose() * b;
    return V.leftCols(rank) * inner.cwiseQuotient(sigma.head(rank));
  }
  VecX solve_transposed(const VecX& c) const {
    const VecX inner = V.leftCols(rank).transpose() * c;
    return U.leftCols(rank) * inner.cwiseQuotient(sigma.head(rank));
  }
  // The rows that take part in a dependency (as dependent_rows() finds them).
  std::vector<int> dependent() const {
    std::vector<int> rows;
    const Eigen::Index m = U.rows();
    const MatX left_null = U.rightCols(m - rank);  // y with y^T Ce = 0
    for (Eigen::Index r = 0; r < m; ++r)
      if (left_null.row(r).norm() > 1e-8) rows.push_back(static_cast<int>(r));
    return rows;
  }
};

std::string describe_rows(const Model& model, const std::vector<int>& rows) {
  std::ostringstream s;
  for (int r : rows) s << " row " << r << ": " << model.describe_row(r) << ";";
  return s.str();
}

// Throws SingularJacobianError when Ce x = b has no solution: when the normwise backward error of
// x, |b - Ce x| / (sigma_max |x| + |b|), exceeds rank_tolerance. Within it, the residual is that of
// a change of Ce no larger than the one the rank decision already ignores (singular values below
// rank_tolerance sigma_max), as a drifted redundant linkage has.
void check_consistent(const Model& model, const MatX& Ce, const VecX& b, const VecX& x, const RankRevealed& rr,
                      const char* what) {
  const double sigma = rr.sigma.size() ? rr.sigma(0) : 0.0;
  const double residual = (b - Ce * x).norm(), scale = sigma * x.norm() + b.norm();
  if (residual == 0 || residual <= rank_tolerance * scale) return;
  const std::vector<int> rows = rr.dependent();
  std::ostringstream msg;
  msg << what << ": the constraint equations have no solution: C_q has rank " << rr.rank << " < " << b.size()
      << " rows, and the right-hand sides of its dependent rows contradict each other (relative residual "
      << readable(scale > 0 ? residual / scale : HUGE_VAL) << " of the least-squares solution, tolerance "
      << readable(rank_tolerance)
      << "): the mechanism is locked at this position (drivers that contradict each other, or a linkage that "
         "cannot move on as asked). Dependent rows:"
      << describe_rows(model, rows);
  throw SingularJacobianError(msg.str(), rows);
}

// Solves (Z^T Ms Z) y = g, where Z spans the null space of Ce and Ms = C M C. False when Z^T Ms Z
// is not positive definite (not invertible for a non-symmetric Ms): a motion that the constraints
// allow carries no mass; `kernel` is then that motion (in the coordinates of Z).
bool reduced_solve(const MatX& Ms, const MatX& Z, const VecX& g, VecX& y, VecX& kernel) {
  const MatX K = Z.transpose() * Ms * Z;
  if (symmetric(Ms)) {
    const Eigen::LLT<MatX> llt(K);
    const VecX pivots = llt.matrixLLT().diagonal().cwiseAbs2();
    const double scale = std::max(pivots.maxCoeff(), Ms.diagonal().cwiseAbs().maxCoeff());
    if (llt.info() == Eigen::Success && pivots.minCoeff() > pivot_tolerance * scale) {
      y = llt.solve(g);
      return true;
    }
    kernel = Eigen::SelfAdjointEigenSolver<MatX>(K).eigenvectors().col(0);
    return false;
  }
  Eigen::FullPivLU<MatX> lu(K);
  lu.setThreshold(rank_tolerance);
  if (lu.isInvertible()) {
    y = lu.solve(g);
    return true;
  }
  kernel = lu.kernel().col(0);
  return false;
}

// The multipliers of least Euclidean norm that solve C_q^T lambda = f (f in the range of C_q^T):
// the minimum-norm solution of the scaled system, less its part in the left null space R U_0 of C_q.
VecX minimum_norm_multipliers(const RankRevealed& rr, const VecX& row, const VecX& col, const VecX& f) {
  const Eigen::Index m = row.size(), r = rr.rank;
  VecX lambda = row.cwiseProduct(rr.solve_transposed(col.cwiseProduct(f)));
  if (m > r) {
    const MatX N = row.asDiagonal() * rr.U.rightCols(m - r);
    const Eigen::HouseholderQR<MatX> qr(N);
    const MatX Q = qr.householderQ() * MatX::Identity(m, m - r);
    lambda -= Q * (Q.transpose() * lambda);
  }
  return lambda;
}

// Step 3 of solve_augmented (see there), on the scales (row, col) of the general path:
//   q_ddot = x_p + Z (Z^T M Z)^-1 Z^T (top - M x_p),
// x_p the minimum-norm solution of C_q x = bottom, Z the null space of C_q. Also where C_q has
// full rank (rank_deficit 0) but the general path found the augmented matrix singular.
Accelerations solve_null_space(const Model& model, const MatX& M, const MatX& Cq, const VecX& top,
                               const VecX& bottom, const VecX& row, const VecX& col, const RankRevealed& rr,
                               const char* what) {
  const Eigen::Index n = M.rows(), m = Cq.rows();
  const MatX Ce = row.asDiagonal() * Cq * col.asDiagonal();
  const VecX b = row.cwiseProduct(bottom), x_p = rr.solve(b);
  // top = 0: a correction of least M-norm, as the projections solve. Their right-hand side (C, or
  // C_q q_dot + C_t) is a residual, consistent only to the round-off of its own terms, which this
  // solve cannot see: it takes the least-squares correction, and a locked mechanism is named by
  // the projection's own convergence check instead.
  const bool correction = top.isZero(0.0);
  VecX x = x_p;
  if (n > rr.rank) {
    const MatX Z = rr.V.rightCols(n - rr.rank);
    const MatX Ms = col.asDiagonal() * M * col.asDiagonal();
    const VecX g = Z.transpose() * (col.cwiseProduct(top) - Ms * x_p);
    VecX y, kernel;
    if (!reduced_solve(Ms, Z, g, y, kernel)) {
      if (!correction) check_consistent(model, Ce, b, x_p, rr, what);  // a locked mechanism is named first
      Eigen::Index k = 0;
      (Z * kernel).cwiseAbs().maxCoeff(&k);  // in the equilibrated coordinates, which are comparable
      throw_massless(model, k,
                     std::string(what) +
                         (rr.rank == m ? std::string(": the augmented matrix [M C_q^T; C_q 0] is singular although "
                                                     "C_q has full rank: the model is not well posed.")
                                       : ": the motion is not determined: C_q has dependent rows (rank " +
                                             std::to_string(rr.rank) + " < " + std::to_string(m) + ";" +
                                             describe_rows(model, rr.dependent()) +
                                             ") and the model is not well posed."));
    }
    x += Z * y;
  }
  if (!correction) check_consistent(model, Ce, b, x, rr, what);
  Accelerations a;
  a.qdd = col.cwiseProduct(x);
  a.lambda = minimum_norm_multipliers(rr, row, col, top - M * a.qdd);
  a.rank_deficit = static_cast<int>(m - rr.rank);
  a.dependent_rows = rr.dependent();
  a.rank_margin = a.rank_deficit > 0 || rr.sigma.size() == 0 || !(rr.sigma(0) > 0) ? 0.0 : rr.sigma(rr.sigma.size() - 1) / rr.sigma(0);
  return a;
}

}  // namespace

Accelerations solve_rank_revealing(const Model& model, const MatX& M, const MatX& Cq, const VecX& top,
                                   const VecX& bottom, const Equilibrated& e, const char* what) {
  const Eigen::Index n = M.rows(), m = Cq.rows();
  return solve_null_space(model, M, Cq, top, bottom, e.row_scale.tail(m), e.col_scale.head(n),
                          RankRevealed(e.A.bottomLeftCorner(m, n)), what);
}

bool solve_if_rank_deficient(const Model& model, const MatX& M, const MatX& Cq, const VecX& top, const VecX& bottom,
                             const Equilibrated& e, const char* what, Accelerations& out) {
  const Eigen::Index n = M.rows(), m = Cq.rows();
  const RankRevealed rr(e.A.bottomLeftCorner(m, n));
  if (rr.rank == m) return false;
  out = solve_null_space(model, M, Cq, top, bottom, e.row_scale.tail(m), e.col_scale.head(n), rr, what);
  return true;
}

}  // namespace fmbd::augmented
