#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>
#include <sstream>
#include <vector>

#include "fmbd/dof.hpp"
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
  VecX d, s, b1, b2, z, y, r;
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

}  // namespace

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
  // Scaled to be free of units: D = diag(1/sqrt(M_kk)) on the coordinates, so that D M D has a
  // unit diagonal, and S = diag(1/|row r of C_q D|) on the constraints. Every rank decision
  // below is then relative, and the same mechanism in kg and m or in g and mm gives the same
  // decision and the same motion.
  Workspace& w = workspace();
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
  w.b1 = d.cwiseProduct(top);
  w.b2 = s.cwiseProduct(bottom);
  const VecX &b1 = w.b1, &b2 = w.b2;
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
  // With M^-1 C^T = W and M^-1 b1 = z (scaled), the range-space solve:
  //   (C W) y = C z - b2,  x = z - W y,
  // an LL^T factor of the Schur complement C W, no pivot search.
  auto range_space = [&]() -> Accelerations {
    VecX &z = w.z, &y = w.y, &r = w.r;
    y.setZero(m);
    if (m > 0) {
      w.S.noalias() = C * w.W;
      if (w.schur.compute(w.S).info() != Eigen::Success) throw singular();
      const auto D = w.schur.matrixLLT().diagonal().cwiseAbs2();
      if (!(D.minCoeff() > pivot_tolerance * D.maxCoeff())) throw singular();
      r.noalias() = C * z;
      r -= b2;
      y = w.schur.solve(r);
      z.noalias() -= w.W * y;
    }
    return {d.cwiseProduct(z), s.cwiseProduct(y)};
  };
  auto symmetric = [](const auto& A) {
    return (A - A.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * A.cwiseAbs().maxCoeff();
  };
  // M couples no bodies: a Cholesky factor per body. Any block that is not symmetric positive
  // definite, with pivots that pass the test below, sends the solve to the general paths.
  if (couples_no_bodies(model, M)) {
    const int bodies = model.num_bodies();
    if (static_cast<int>(w.blocks.size()) < bodies) w.blocks.resize(bodies);
    double smallest = HUGE_VAL, largest = 0;
    bool factored = true;
    for (int b = 0; b < bodies && factored; ++b) {
      const Eigen::Index first = model.offset(BodyId{b}), size = model.bodies()[b].num_coordinates();
      const auto block = M.block(first, first, size, size);
      const auto d_b = d.segment(first, size).asDiagonal();
      Eigen::LLT<MatX>& llt = w.blocks[b];
      factored = symmetric(block) && llt.compute(d_b * block * d_b).info() == Eigen::Success;
      if (factored) {
        const auto pivots = llt.matrixLLT().diagonal().cwiseAbs2();
        smallest = std::min(smallest, pivots.minCoeff());
        largest = std::max(largest, pivots.maxCoeff());
      }
    }
    if (factored && smallest > pivot_tolerance * largest) {
      w.W.resize(n, m);
      w.z = b1;
      for (int b = 0; b < bodies; ++b) {
        const Eigen::Index first = model.offset(BodyId{b}), size = model.bodies()[b].num_coordinates();
        auto z_b = w.z.segment(first, size);
        w.blocks[b].solveInPlace(z_b);
        if (size == 3) {  // a rigid body: its inverse, at fixed size
          const Eigen::Matrix3d inverse = w.blocks[b].solve(Eigen::Matrix3d::Identity());
          w.W.middleRows<3>(first).noalias() = inverse.lazyProduct(C.middleCols<3>(first).transpose());
        } else {
          auto W_b = w.W.middleRows(first, size);
          W_b = C.middleCols(first, size).transpose();
          w.blocks[b].solveInPlace(W_b);
        }
      }
      return range_space();
    }
  }
  // A symmetric positive definite M that couples bodies: one Cholesky factor of the whole M.
  MatX& Ms = w.Ms;
  Ms.noalias() = d.asDiagonal() * M * d.asDiagonal();
  if (symmetric(Ms)) {
    const Eigen::LLT<MatX> llt(Ms);
    if (llt.info() == Eigen::Success) {
      const VecX pivots = llt.matrixLLT().diagonal().cwiseAbs2();
      if (pivots.minCoeff() > pivot_tolerance * pivots.maxCoeff()) {
        w.W = llt.solve(C.transpose());
        w.z = llt.solve(b1);
        return range_space();
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
