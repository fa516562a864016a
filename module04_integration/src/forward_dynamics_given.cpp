#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "fmbd/dof.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/forward_dynamics.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/linear_solve.hpp"

namespace fmbd {

namespace {
// Smallest pivot of a Cholesky factor, relative to the largest. Its pivots are
// squares, so 1e-13 matches a ratio of singular values of about 3e-7.
constexpr double pivot_tolerance = 1e-13;

// One thread's buffers: sized by the first solve of a model and reused after, so that a run of
// simulate() allocates nothing here but the result.
struct Workspace {
  VecX d, s, z, y, r, x, lambda, r1, r2, den1, den2, size1, size2;
  MatX C, Ms, W, S;
  std::vector<Eigen::LLT<MatX>> blocks;
  Eigen::LLT<MatX> schur;
};

Workspace& workspace() {
  thread_local Workspace w;
  return w;
}

// True when M couples no two bodies (every mass matrix of the engine): each body's diagonal
// block is then factored on its own, and M^-1 C^T costs a few small solves.
bool couples_no_bodies(const Model& model, const MatX& M) {
  if (M.rows() != model.num_coordinates()) return false;
  for (int b = 0; b < model.num_bodies(); ++b) {
    const Eigen::Index first = model.offset(BodyId{b}), size = model.bodies()[b].num_coordinates();
    const Eigen::Index after = M.rows() - first - size;
    for (Eigen::Index j = first; j < first + size; ++j)
      if (!(M.col(j).head(first).array() == 0).all() || !(M.col(j).tail(after).array() == 0).all()) return false;
  }
  return true;
}

[[noreturn]] void throw_not_finite(const Model& model, const MatX& M, const MatX& Cq, const VecX& top,
                                   const VecX& bottom, const char* what) {
  const Eigen::Index n = M.rows();
  for (Eigen::Index r = 0;; ++r) {
    const bool finite = r < n ? M.row(r).allFinite() && Cq.col(r).allFinite() && std::isfinite(top(r))
                              : Cq.row(r - n).allFinite() && std::isfinite(bottom(r - n));
    if (!finite)
      throw KinematicsError(std::string(what) + ": the augmented system contains NaN or Inf in " +
                            (r < n ? "the equation of motion of " + model.describe_coordinate(static_cast<int>(r))
                                   : "the acceleration equation of " + model.describe_row(static_cast<int>(r - n))));
  }
}

// Componentwise (Oettli-Prager) backward error of (x, y) on the unscaled system
//   [M C_q^T; C_q 0] (x; y) = (top; bottom):
// the smallest relative change of each entry of the matrix and the right-hand side for which
// (x, y) is exact, max_i |r_i| / (|A| |(x; y)| + |b|)_i, which no change of units alters. A row
// whose terms all vanish next to the solution's own size (an acceleration held at zero by a
// driver) is measured against that size instead, (|A| zeta)_i with zeta_j = scale_j max_k
// |z_k| / scale_k, where `scale_x`, `scale_y` are the solve's own unit-free scales (Arioli,
// Demmel and Duff 1989). Leaves the residual in w.r1, w.r2.
double backward_error(const MatX& M, const MatX& Cq, const VecX& top, const VecX& bottom, const VecX& x,
                      const VecX& y, const VecX& scale_x, const VecX& scale_y, Workspace& w) {
  VecX &r1 = w.r1, &r2 = w.r2, &den1 = w.den1, &den2 = w.den2, &size1 = w.size1, &size2 = w.size2;
  r1 = top;
  r1.noalias() -= M * x;
  r1.noalias() -= Cq.transpose() * y;
  r2 = bottom;
  r2.noalias() -= Cq * x;
  double largest = 0;  // max_k |z_k| / scale_k
  for (Eigen::Index j = 0; j < x.size(); ++j) largest = std::max(largest, std::abs(x(j)) / scale_x(j));
  for (Eigen::Index r = 0; r < y.size(); ++r) largest = std::max(largest, std::abs(y(r)) / scale_y(r));
  den1 = top.cwiseAbs();
  den2 = bottom.cwiseAbs();
  size1.setZero(x.size());
  size2.setZero(y.size());
  for (Eigen::Index j = 0; j < M.cols(); ++j) {  // column by column: no temporary |M|
    den1 += M.col(j).cwiseAbs() * std::abs(x(j));
    size1 += M.col(j).cwiseAbs() * (scale_x(j) * largest);
    den2 += Cq.col(j).cwiseAbs() * std::abs(x(j));
    size2 += Cq.col(j).cwiseAbs() * (scale_x(j) * largest);
    den1(j) += Cq.col(j).cwiseAbs().dot(y.cwiseAbs());
    size1(j) += Cq.col(j).cwiseAbs().dot(scale_y) * largest;
  }
  const double negligible = augmented_round_off(x.size() + y.size());
  double worst = 0;
  auto rows = [&](const VecX& r, const VecX& den, const VecX& size) {
    for (Eigen::Index i = 0; i < r.size(); ++i) {
      if (r(i) == 0) continue;
      const double d = den(i) < negligible * size(i) ? den(i) + size(i) : den(i);
      worst = std::max(worst, d > 0 ? std::abs(r(i)) / d : HUGE_VAL);
    }
  };
  rows(r1, den1, size1);
  rows(r2, den2, size2);
  return worst;
}

}  // namespace

double augmented_round_off(Eigen::Index size) {
  return 4.0 * static_cast<double>(size + 1) * std::numeric_limits<double>::epsilon();
}

Accelerations solve_augmented(const Model& model, const MatX& M, const MatX& Cq, const VecX& top,
                              const VecX& bottom, const char* what) {
  const Eigen::Index n = M.rows(), m = Cq.rows();
  if (M.cols() != n || Cq.cols() != n || top.size() != n || bottom.size() != m)
    throw std::invalid_argument(std::string(what) + ": sizes do not match (M " + std::to_string(M.rows()) + "x" +
                                std::to_string(M.cols()) + ", C_q " + std::to_string(Cq.rows()) + "x" +
                                std::to_string(Cq.cols()) + ", right-hand sides " + std::to_string(top.size()) +
                                " and " + std::to_string(bottom.size()) + ")");
  if (!M.allFinite() || !Cq.allFinite() || !top.allFinite() || !bottom.allFinite())
    throw_not_finite(model, M, Cq, top, bottom, what);
  Workspace& w = workspace();
  const double limit = augmented_round_off(n + m);

  // 1. The structured solve, where M is symmetric positive definite: scaled free of units
  // (D = diag(1/sqrt(M_kk)) on the coordinates, so that D M D has a unit diagonal, and
  // S = diag(1/|row r of C_q D|) on the constraints), a Cholesky factor of M (per body where M
  // couples no bodies), and an LL^T factor of the Schur complement C W, W = M^-1 C^T:
  //   (C W) y = C z - b2,  x = z - W y,  z = M^-1 b1.
  // Its accuracy falls with the conditioning of C W, which grows as m L^2 / J for a body of
  // small inertia J: the result is kept only when its backward error, after at most one step
  // of refinement, is round-off; otherwise step 2 solves the system.
  VecX &d = w.d, &s = w.s;
  d.resize(n);
  s.resize(m);
  for (Eigen::Index k = 0; k < n; ++k) d(k) = M(k, k) > 0 ? 1 / std::sqrt(M(k, k)) : 1.0;
  MatX& C = w.C;
  C.noalias() = Cq * d.asDiagonal();
  for (Eigen::Index r = 0; r < m; ++r) {
    const double norm = C.row(r).norm();
    s(r) = norm > 0 ? 1 / norm : 1.0;
  }
  C = s.asDiagonal() * C;
  auto symmetric = [](const auto& A) {
    return (A - A.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * A.cwiseAbs().maxCoeff();
  };
  // Factors M (scaled): per body, or whole (w.Ms) when it couples bodies. False when M is not
  // symmetric positive definite with pivots that pass pivot_tolerance.
  bool per_body = false;
  Eigen::LLT<MatX> whole;
  auto factor_mass = [&]() -> bool {
    if (couples_no_bodies(model, M)) {
      const int bodies = model.num_bodies();
      if (static_cast<int>(w.blocks.size()) < bodies) w.blocks.resize(bodies);
      double smallest = HUGE_VAL, largest = 0;
      for (int b = 0; b < bodies; ++b) {
        const Eigen::Index first = model.offset(BodyId{b}), size = model.bodies()[b].num_coordinates();
        const auto block = M.block(first, first, size, size);
        const auto d_b = d.segment(first, size).asDiagonal();
        Eigen::LLT<MatX>& llt = w.blocks[b];
        if (!symmetric(block) || llt.compute(d_b * block * d_b).info() != Eigen::Success) return false;
        const auto pivots = llt.matrixLLT().diagonal().cwiseAbs2();
        smallest = std::min(smallest, pivots.minCoeff());
        largest = std::max(largest, pivots.maxCoeff());
      }
      per_body = true;
      return smallest > pivot_tolerance * largest;
    }
    w.Ms.noalias() = d.asDiagonal() * M * d.asDiagonal();
    if (!symmetric(w.Ms) || whole.compute(w.Ms).info() != Eigen::Success) return false;
    const VecX pivots = whole.matrixLLT().diagonal().cwiseAbs2();
    return pivots.minCoeff() > pivot_tolerance * pivots.maxCoeff();
  };
  // z <- M^-1 z (scaled), with the factors above.
  auto apply_mass_inverse = [&](VecX& z) {
    if (!per_body) {
      whole.solveInPlace(z);
      return;
    }
    for (int b = 0; b < model.num_bodies(); ++b) {
      auto z_b = z.segment(model.offset(BodyId{b}), model.bodies()[b].num_coordinates());
      w.blocks[b].solveInPlace(z_b);
    }
  };
  if (factor_mass()) {
    // W = M^-1 C^T (a rigid body's block inverted at fixed size).
    w.W.resize(n, m);
    if (per_body) {
      for (int b = 0; b < model.num_bodies(); ++b) {
        const Eigen::Index first = model.offset(BodyId{b}), size = model.bodies()[b].num_coordinates();
        if (size == 3) {
          const Eigen::Matrix3d inverse = w.blocks[b].solve(Eigen::Matrix3d::Identity());
          w.W.middleRows<3>(first).noalias() = inverse.lazyProduct(C.middleCols<3>(first).transpose());
        } else {
          auto W_b = w.W.middleRows(first, size);
          W_b = C.middleCols(first, size).transpose();
          w.blocks[b].solveInPlace(W_b);
        }
      }
    } else {
      w.W = whole.solve(C.transpose());
    }
    bool schur_ok = true;
    if (m > 0) {
      w.S.noalias() = C * w.W;
      schur_ok = w.schur.compute(w.S).info() == Eigen::Success;
      if (schur_ok) {  // a pivot this small: (nearly) dependent rows, for the general path to judge
        const auto D = w.schur.matrixLLT().diagonal().cwiseAbs2();
        schur_ok = D.minCoeff() > pivot_tolerance * D.maxCoeff();
      }
    }
    if (schur_ok) {
      // Solves the scaled system for the unscaled right-hand sides (f, g): (x, lambda) += ...
      auto solve = [&](const VecX& f, const VecX& g, VecX& x, VecX& lambda) {
        VecX &z = w.z, &y = w.y, &r = w.r;
        z = d.cwiseProduct(f);
        apply_mass_inverse(z);
        y.setZero(m);
        if (m > 0) {
          r.noalias() = C * z;
          r -= s.cwiseProduct(g);
          y = w.schur.solve(r);
          z.noalias() -= w.W * y;
        }
        x += d.cwiseProduct(z);
        lambda += s.cwiseProduct(y);
      };
      w.x.setZero(n);
      w.lambda.setZero(m);
      solve(top, bottom, w.x, w.lambda);
      double error = backward_error(M, Cq, top, bottom, w.x, w.lambda, d, s, w);
      if (error > limit && std::isfinite(error)) {  // one step of iterative refinement
        solve(w.r1, w.r2, w.x, w.lambda);
        error = backward_error(M, Cq, top, bottom, w.x, w.lambda, d, s, w);
      }
      if (error <= limit) return {w.x, w.lambda};
    }
  }

  // 2. Any other system: M singular (a point mass, a massless link), indefinite, non-symmetric
  // (an implicit integrator's), or a structured result that was not accurate. The scales come
  // from the geometry, not the masses: the rows and columns of C_q are equilibrated (each to a
  // largest entry of about 1, which turns an angle into a length at the scale of the body's
  // joints), M is divided by its largest scaled diagonal entry mu, and a coordinate that no
  // constraint touches takes the scale of its mass. A few sweeps then equilibrate the whole
  // matrix, which is factored by LU with full pivoting; the result is refined until its
  // backward error is round-off.
  const Eigen::Index size = n + m;
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
  VecX row_scale(size), col_scale(size);
  row_scale << col / mu, row;
  col_scale << col, mu * row;
  MatX A(size, size);
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
  Eigen::FullPivLU<MatX> lu(A);
  lu.setThreshold(rank_tolerance);
  if (!lu.isInvertible()) {
    std::ostringstream msg;
    msg << what << ": the augmented matrix [M C_q^T; C_q 0] is singular";
    const MatX Ce = A.bottomLeftCorner(m, n);
    const std::vector<int> rows = dependent_rows(Ce);
    if (!rows.empty()) {
      msg << ": the mechanism is locked or has redundant constraints. Dependent rows:";
      for (int r : rows) msg << " row " << r << ": " << model.describe_row(r) << ";";
      throw SingularJacobianError(msg.str(), rows);
    }
    // C_q has full rank: a motion that the constraints allow carries no mass. Its largest
    // part (in the equilibrated coordinates, which are comparable) names the culprit.
    const MatX kernel = lu.kernel();
    Eigen::Index k = 0;
    kernel.col(0).head(n).cwiseAbs().maxCoeff(&k);
    int body = 0;
    while (body + 1 < model.num_bodies() && model.offset(BodyId{body + 1}) <= k) ++body;
    const std::string name = model.bodies()[body].name;
    msg << " although C_q has full rank: the model is not well posed. The constraints let "
        << model.describe_coordinate(static_cast<int>(k))
        << " move without mass (M is not positive definite on the motions that C_q allows). Give body '" << name
        << "' mass or inertia in that direction, or a joint that holds it";
    throw MasslessMotionError(msg.str(), name, static_cast<int>(k));
  }
  VecX b(size), correction(size);
  b << top, bottom;
  VecX z = col_scale.cwiseProduct(lu.solve(row_scale.cwiseProduct(b)));
  double error = backward_error(M, Cq, top, bottom, z.head(n), z.tail(m), col_scale.head(n), col_scale.tail(m), w);
  for (int step = 0; step < 3 && error > limit; ++step) {
    correction << w.r1, w.r2;
    z += col_scale.cwiseProduct(lu.solve(row_scale.cwiseProduct(correction)));
    error = backward_error(M, Cq, top, bottom, z.head(n), z.tail(m), col_scale.head(n), col_scale.tail(m), w);
  }
  if (!(error <= limit))
    throw IllConditionedError(std::string(what) + ": the augmented system [M C_q^T; C_q 0] is singular to working "
                              "precision: after refinement, its solution still has a componentwise backward error "
                              "of " + readable(error) + " (round-off would be " + readable(limit) +
                              "); check for constraints that are nearly dependent, or masses many orders of "
                              "magnitude apart", error);
  return {z.head(n), z.tail(m)};
}

}  // namespace fmbd
