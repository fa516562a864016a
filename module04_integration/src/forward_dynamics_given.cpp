#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "fmbd/dof.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/forward_dynamics.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/linear_solve.hpp"
#include "fmbd/rank_revealing.hpp"

namespace fmbd {

using namespace augmented;  // the constants and step 3 of the solve (rank_revealing.hpp)

namespace {
// A smallest pivot below this, relative to the largest, in a factor that passed: C_q may still be
// rank deficient, its zero pivot lifted by round-off (as near a second, genuine small pivot), so an
// SVD decides (step 3). Every rank-deficient C_q seen leaves a pivot well below it.
constexpr double suspicious_pivot = 1e-6;

using SparseMat = Eigen::SparseMatrix<double>;

// One thread's buffers: sized by the first solve of a model and reused after, so that a run of
// simulate() allocates little here but the result and the sparse matrices.
struct Workspace {
  VecX d, s, z, y, r, x, lambda, r1, r2, den1, den2, size1, size2, abs_x, abs_y, size_x, size_y, pivots;
  MatX C, Ms, W, S;                           // C = S C_q D, dense (small models)
  SparseMat Cq, M, Csparse, Minv, Wsparse, Ssparse;  // large models: C_q and M by body blocks, C sparse
  std::vector<Eigen::Triplet<double>> triplets;
  std::vector<char> touched;
  std::vector<Eigen::LLT<MatX>> blocks;
  Eigen::LLT<MatX> whole, schur;
  Eigen::SimplicialLDLT<SparseMat, Eigen::Lower, Eigen::AMDOrdering<int>> sparse_schur;
  std::vector<int> pattern;  // the outer and inner indices sparse_schur was analysed for
  bool per_body = false;     // M factored per body (blocks), else whole
  bool sparse = false;       // per body, with C and the Schur complement sparse
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

// out += |A| v, column by column (no temporary |A|).
void add_abs_product(const MatX& A, const VecX& v, VecX& out) {
  for (Eigen::Index j = 0; j < A.cols(); ++j) out += A.col(j).cwiseAbs() * v(j);
}
void add_abs_product(const SparseMat& A, const VecX& v, VecX& out) {
  for (Eigen::Index j = 0; j < A.outerSize(); ++j)
    for (SparseMat::InnerIterator it(A, j); it; ++it) out(it.row()) += std::abs(it.value()) * v(j);
}

// out += |A|^T v.
void add_abs_transposed_product(const MatX& A, const VecX& v, VecX& out) {
  for (Eigen::Index j = 0; j < A.cols(); ++j) out(j) += A.col(j).cwiseAbs().dot(v);
}
void add_abs_transposed_product(const SparseMat& A, const VecX& v, VecX& out) {
  for (Eigen::Index j = 0; j < A.outerSize(); ++j)
    for (SparseMat::InnerIterator it(A, j); it; ++it) out(j) += std::abs(it.value()) * v(it.row());
}

// Componentwise (Oettli-Prager) backward error of (x, y) on the unscaled system
//   [M C_q^T; C_q 0] (x; y) = (top; bottom):
// the smallest relative change of each entry of the matrix and the right-hand side for which
// (x, y) is exact, max_i |r_i| / (|A| |(x; y)| + |b|)_i, which no change of units alters. A row
// whose terms all vanish next to the solution's own size (an acceleration held at zero by a
// driver) is measured against that size instead, (|A| zeta)_i with zeta_j = scale_j max_k
// |z_k| / scale_k, where `scale_x`, `scale_y` are the solve's own unit-free scales (Arioli,
// Demmel and Duff 1989). M and C_q dense or sparse (the same values). Leaves the residual in
// w.r1, w.r2.
template <typename MassMatrix, typename Jacobian>
double backward_error(const MassMatrix& M, const Jacobian& Cq, const VecX& top, const VecX& bottom, const VecX& x,
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
  w.abs_x = x.cwiseAbs();
  w.abs_y = y.cwiseAbs();
  w.size_x = scale_x * largest;
  w.size_y = scale_y * largest;
  den1 = top.cwiseAbs();
  den2 = bottom.cwiseAbs();
  size1.setZero(x.size());
  size2.setZero(y.size());
  add_abs_product(M, w.abs_x, den1);
  add_abs_transposed_product(Cq, w.abs_y, den1);
  add_abs_product(Cq, w.abs_x, den2);
  add_abs_product(M, w.size_x, size1);
  add_abs_transposed_product(Cq, w.size_y, size1);
  add_abs_product(Cq, w.size_x, size2);
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


void check_inputs(const Model& model, const MatX& M, const MatX& Cq, const VecX& top, const VecX& bottom,
                  const char* what) {
  const Eigen::Index n = M.rows(), m = Cq.rows();
  if (M.cols() != n || Cq.cols() != n || top.size() != n || bottom.size() != m)
    throw std::invalid_argument(std::string(what) + ": sizes do not match (M " + std::to_string(M.rows()) + "x" +
                                std::to_string(M.cols()) + ", C_q " + std::to_string(Cq.rows()) + "x" +
                                std::to_string(Cq.cols()) + ", right-hand sides " + std::to_string(top.size()) +
                                " and " + std::to_string(bottom.size()) + ")");
  if (!M.allFinite() || !Cq.allFinite() || !top.allFinite() || !bottom.allFinite())
    throw_not_finite(model, M, Cq, top, bottom, what);
}

// ---- 1. The structured solve --------------------------------------------------------------------

// A (C_q, or with `diagonal` M) as a sparse matrix by body blocks: the block of a row and a body
// is kept whole (its zeros too) when any entry of it is non-zero, so that the pattern stays as an
// angle passes through zero; M keeps each body's diagonal block.
void sparse_by_bodies(const Model& model, const MatX& A, bool diagonal, SparseMat& out, Workspace& w) {
  w.triplets.clear();
  for (int b = 0; b < model.num_bodies(); ++b) {
    const Eigen::Index first = model.offset(BodyId{b}), size = model.bodies()[b].num_coordinates();
    const Eigen::Index row0 = diagonal ? first : 0, rows = diagonal ? size : A.rows();
    const auto block = A.block(row0, first, rows, size);
    w.touched.resize(static_cast<std::size_t>(rows));
    Eigen::Map<Eigen::Array<char, Eigen::Dynamic, 1>>(w.touched.data(), rows) =
        (block.array() != 0).rowwise().any().cast<char>();
    for (Eigen::Index r = 0; r < rows; ++r)
      if (w.touched[r])
        for (Eigen::Index j = 0; j < size; ++j)
          w.triplets.emplace_back(static_cast<int>(row0 + r), static_cast<int>(first + j), block(r, j));
  }
  out.resize(A.rows(), A.cols());
  out.setFromTriplets(w.triplets.begin(), w.triplets.end());
}

// The unit-free scales: d = 1/sqrt(M_kk) on the coordinates (D M D has a unit diagonal) and
// s = 1/|row r of C_q D| on the constraints; C = S C_q D in w.C, or w.Csparse (from w.Cq).
void unit_free_scales(const MatX& M, const MatX& Cq, Workspace& w) {
  const Eigen::Index n = M.rows(), m = Cq.rows();
  VecX &d = w.d, &s = w.s;
  d.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) d(k) = M(k, k) > 0 ? 1 / std::sqrt(M(k, k)) : 1.0;
  if (!w.sparse) {
    MatX& C = w.C;
    C.noalias() = Cq * d.asDiagonal();
    s.resize(m);
    for (Eigen::Index r = 0; r < m; ++r) {
      const double norm = C.row(r).norm();
      s(r) = norm > 0 ? 1 / norm : 1.0;
    }
    C = s.asDiagonal() * C;
    return;
  }
  s.setZero(m);
  for (Eigen::Index j = 0; j < n; ++j)
    for (SparseMat::InnerIterator it(w.Cq, j); it; ++it) s(it.row()) += std::pow(it.value() * d(j), 2);
  for (Eigen::Index r = 0; r < m; ++r) s(r) = s(r) > 0 ? 1 / std::sqrt(s(r)) : 1.0;
  w.Csparse = w.Cq;
  for (Eigen::Index j = 0; j < n; ++j)
    for (SparseMat::InnerIterator it(w.Csparse, j); it; ++it) it.valueRef() *= s(it.row()) * d(j);
}

// Factors D M D: per body (w.blocks) where M couples no bodies, whole (w.whole, w.Ms) otherwise.
// False when M is not symmetric positive definite with pivots that pass pivot_tolerance.
bool factor_mass(const Model& model, const MatX& M, Workspace& w) {
  const VecX& d = w.d;
  if (w.per_body) {
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
    return smallest > pivot_tolerance * largest;
  }
  w.Ms.noalias() = d.asDiagonal() * M * d.asDiagonal();
  if (!symmetric(w.Ms) || w.whole.compute(w.Ms).info() != Eigen::Success) return false;
  const auto pivots = w.whole.matrixLLT().diagonal().cwiseAbs2();
  return pivots.minCoeff() > pivot_tolerance * pivots.maxCoeff();
}

// z <- M^-1 z (scaled), with the factors of factor_mass().
void apply_mass_inverse(const Model& model, Workspace& w, VecX& z) {
  if (!w.per_body) {
    w.whole.solveInPlace(z);
    return;
  }
  for (int b = 0; b < model.num_bodies(); ++b) {
    auto z_b = z.segment(model.offset(BodyId{b}), model.bodies()[b].num_coordinates());
    w.blocks[b].solveInPlace(z_b);
  }
}

// The pivots of the Schur complement's factor (D of LDL^T, or the squared diagonal of L), in w.pivots.
const VecX& schur_pivots(Workspace& w) {
  if (w.sparse)
    w.pivots = w.sparse_schur.vectorD();
  else
    w.pivots = w.schur.matrixLLT().diagonal().cwiseAbs2();
  return w.pivots;
}

// W = M^-1 C^T (scaled) in w.W, dense: a rigid body's block inverted at fixed size, or M's
// whole factor.
void dense_mass_inverse_times_transpose(const Model& model, Workspace& w) {
  const MatX& C = w.C;
  w.W.resize(C.cols(), C.rows());
  if (!w.per_body) {
    w.W = w.whole.solve(C.transpose());
    return;
  }
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
}

// The sparse Schur complement S = C M^-1 C^T in w.Ssparse (two rows are coupled only through a
// body both touch: a chain's S is banded), factored by a sparse LDL^T with a fill-reducing
// ordering, analysed again only when its pattern changes.
bool factor_sparse_schur(const Model& model, Workspace& w) {
  const Eigen::Index n = w.Csparse.cols();
  w.triplets.clear();
  for (int b = 0; b < model.num_bodies(); ++b) {
    const int first = static_cast<int>(model.offset(BodyId{b})), size = model.bodies()[b].num_coordinates();
    const MatX inverse = w.blocks[b].solve(MatX::Identity(size, size));
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) w.triplets.emplace_back(first + i, first + j, inverse(i, j));
  }
  w.Minv.resize(n, n);
  w.Minv.setFromTriplets(w.triplets.begin(), w.triplets.end());
  w.Wsparse = w.Minv * w.Csparse.transpose();
  w.Ssparse = w.Csparse * w.Wsparse;
  const SparseMat& S = w.Ssparse;
  std::vector<int> pattern(S.outerIndexPtr(), S.outerIndexPtr() + S.outerSize() + 1);
  pattern.insert(pattern.end(), S.innerIndexPtr(), S.innerIndexPtr() + S.nonZeros());
  if (pattern != w.pattern) {
    w.sparse_schur.analyzePattern(S);
    w.pattern.swap(pattern);
  }
  w.sparse_schur.factorize(S);
  return w.sparse_schur.info() == Eigen::Success;
}

// The Schur complement S = C M^-1 C^T (scaled) and its factor: sparse for large models with M
// per body (factor_sparse_schur), else W = M^-1 C^T and S dense, with an LL^T factor. False when
// the factor fails or has a pivot below pivot_tolerance: (nearly) dependent rows, for the
// general path to judge.
bool factor_schur(const Model& model, Workspace& w) {
  if (w.s.size() == 0) return true;
  if (w.sparse) {
    if (!factor_sparse_schur(model, w)) return false;
  } else {
    dense_mass_inverse_times_transpose(model, w);
    w.S.noalias() = w.C * w.W;
    if (w.schur.compute(w.S).info() != Eigen::Success) return false;
  }
  const VecX& pivots = schur_pivots(w);
  return pivots.minCoeff() > pivot_tolerance * pivots.maxCoeff();
}

// Solves the scaled system for the unscaled right-hand sides (f, g): (x, lambda) += ...
//   (C W) y = C z - S g,  x = z - W y,  z = M^-1 D f.
void structured_solve(const Model& model, const VecX& f, const VecX& g, VecX& x, VecX& lambda, Workspace& w) {
  const Eigen::Index m = w.s.size();
  VecX &z = w.z, &y = w.y, &r = w.r;
  z = w.d.cwiseProduct(f);
  apply_mass_inverse(model, w, z);
  y.setZero(m);
  if (m > 0) {
    if (w.sparse)
      r.noalias() = w.Csparse * z;
    else
      r.noalias() = w.C * z;
    r -= w.s.cwiseProduct(g);
    if (w.sparse) {
      y = w.sparse_schur.solve(r);
      z.noalias() -= w.Wsparse * y;
    } else {
      y = w.schur.solve(r);
      z.noalias() -= w.W * y;
    }
  }
  x += w.d.cwiseProduct(z);
  lambda += w.s.cwiseProduct(y);
}

// Step 1 of solve_augmented (see there); the result in w.x, w.lambda. False when it does not
// apply (M not SPD, dependent rows) or misses round-off after one step of refinement.
bool solve_structured(const Model& model, const MatX& M, const MatX& Cq, const VecX& top, const VecX& bottom,
                      double limit, Workspace& w) {
  w.per_body = couples_no_bodies(model, M);
  w.sparse = w.per_body && Cq.rows() >= kSparseRows;
  if (w.sparse) {
    sparse_by_bodies(model, Cq, false, w.Cq, w);
    sparse_by_bodies(model, M, true, w.M, w);
  }
  unit_free_scales(M, Cq, w);
  if (!factor_mass(model, M, w) || !factor_schur(model, w)) return false;
  w.x.setZero(M.rows());
  w.lambda.setZero(Cq.rows());
  auto error = [&] {
    return w.sparse ? backward_error(w.M, w.Cq, top, bottom, w.x, w.lambda, w.d, w.s, w)
                    : backward_error(M, Cq, top, bottom, w.x, w.lambda, w.d, w.s, w);
  };
  structured_solve(model, top, bottom, w.x, w.lambda, w);
  double e = error();
  if (e > limit && std::isfinite(e)) {  // one step of iterative refinement
    structured_solve(model, w.r1, w.r2, w.x, w.lambda, w);
    e = error();
  }
  return e <= limit;
}

// The smallest entry of |pivots| relative to the largest (1 for none).
double pivot_ratio(const VecX& pivots) {
  if (pivots.size() == 0) return 1.0;
  const double largest = pivots.cwiseAbs().maxCoeff();
  return largest > 0 ? pivots.cwiseAbs().minCoeff() / largest : 0.0;
}

// ---- 2. The general solve (step 3 in rank_revealing_given.cpp) ---------------------------------

// Step 2 of solve_augmented (see there), and step 3 where its LU finds the matrix singular, or
// passes with a pivot below suspicious_pivot and C_q is rank deficient.
Accelerations solve_general(const Model& model, const MatX& M, const MatX& Cq, const VecX& top, const VecX& bottom,
                            double limit, Workspace& w, const char* what) {
  const Eigen::Index n = M.rows(), m = Cq.rows(), size = n + m;
  const Equilibrated e = equilibrate(M, Cq);
  const VecX &row_scale = e.row_scale, &col_scale = e.col_scale;
  Eigen::FullPivLU<MatX> lu(e.A);
  lu.setThreshold(rank_tolerance);
  if (!lu.isInvertible()) {
    // With constraints, step 3 decides: C_q rank deficient, or of full rank but so ill-conditioned
    // (a linkage near a singular position) that the augmented matrix looks singular, or a motion
    // that the constraints allow carries no mass.
    if (m > 0) return solve_rank_revealing(model, M, Cq, top, bottom, e, what);
    // No constraints: M itself is singular. Its null vector's largest part (in the equilibrated
    // coordinates, which are comparable) names the culprit.
    const MatX kernel = lu.kernel();
    Eigen::Index k = 0;
    kernel.col(0).head(n).cwiseAbs().maxCoeff(&k);
    throw_massless(model, k,
                   std::string(what) + ": the augmented matrix [M C_q^T; C_q 0] is singular although C_q has full "
                                       "rank: the model is not well posed.");
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
  Accelerations a;
  const double ratio = m > 0 ? pivot_ratio(lu.matrixLU().diagonal()) : 1.0;
  if (ratio < suspicious_pivot && solve_if_rank_deficient(model, M, Cq, top, bottom, e, what, a)) return a;
  a.qdd = z.head(n);
  a.lambda = z.tail(m);
  a.rank_margin = ratio;  // the LU's pivots are of the first power
  return a;
}

}  // namespace

double augmented_round_off(Eigen::Index size) {
  return 4.0 * static_cast<double>(size + 1) * std::numeric_limits<double>::epsilon();
}

void solve_augmented(const Model& model, const MatX& M, const MatX& Cq, const VecX& top, const VecX& bottom,
                     const char* what, Accelerations& out) {
  check_inputs(model, M, Cq, top, bottom, what);
  Workspace& w = workspace();
  const double limit = augmented_round_off(M.rows() + Cq.rows());
  // 1. The structured solve, where M is symmetric positive definite: scaled free of units
  // (D = diag(1/sqrt(M_kk)) on the coordinates, so that D M D has a unit diagonal, and
  // S = diag(1/|row r of C_q D|) on the constraints), a Cholesky factor of M (per body where M
  // couples no bodies), and an LL^T factor of the Schur complement C W, W = M^-1 C^T:
  //   (C W) y = C z - b2,  x = z - W y,  z = M^-1 b1.
  // Its accuracy falls with the conditioning of C W, which grows as m L^2 / J for a body of
  // small inertia J: the result is kept only when its backward error, after at most one step
  // of refinement, is round-off; otherwise step 2 solves the system.
  if (solve_structured(model, M, Cq, top, bottom, limit, w)) {
    const Eigen::Index m = Cq.rows();
    const double ratio = m > 0 ? pivot_ratio(schur_pivots(w)) : 1.0;
    // the scales of step 3 are the general path's
    if (ratio < suspicious_pivot && solve_if_rank_deficient(model, M, Cq, top, bottom, equilibrate(M, Cq), what, out))
      return;
    out.qdd = w.x;
    out.lambda = w.lambda;
    out.rank_deficit = 0;
    out.dependent_rows.clear();
    out.rank_margin = std::sqrt(ratio);
    return;
  }
  // 2. Any other system: M singular (a point mass, a massless link), indefinite, non-symmetric
  // (an implicit integrator's), or a structured result that was not accurate. The whole matrix,
  // equilibrated (equilibrate()), is factored by LU with full pivoting; the result is refined
  // until its backward error is round-off.
  // 3. Where that LU finds the matrix singular (C_q rank deficient: redundant constraints, or an
  // instant of rank loss at a singular position; or C_q so ill-conditioned near one that the
  // augmented matrix looks singular; or M not positive definite on the null space of C_q), and
  // where step 1 or 2 passed with a pivot below suspicious_pivot and an SVD finds C_q rank
  // deficient (its zero pivot lifted by round-off; their lambda would be one of many): the
  // SVD of the equilibrated C_q gives its
  // null space Z and the minimum-norm solution x_p of C_q x = bottom (bottom must lie in the
  // range of C_q to within rank_tolerance, else the mechanism is locked: SingularJacobianError),
  // then q_ddot = x_p + Z (Z^T M Z)^-1 Z^T (top - M x_p) (Z^T M Z must be positive definite, else
  // MasslessMotionError) and lambda the minimum-norm multipliers.
  out = solve_general(model, M, Cq, top, bottom, limit, w, what);
}

Accelerations solve_augmented(const Model& model, const MatX& M, const MatX& Cq, const VecX& top,
                              const VecX& bottom, const char* what) {
  Accelerations a;
  solve_augmented(model, M, Cq, top, bottom, what, a);
  return a;
}

DynamicsData::DynamicsData(const Model& model)
    : constraints(constraint_storage(model)),
      M(MatX::Zero(model.num_coordinates(), model.num_coordinates())),
      Q_a(VecX::Zero(model.num_coordinates())),
      rhs(VecX::Zero(model.num_constraints())),
      zero(VecX::Zero(model.num_coordinates())),
      solution{VecX::Zero(model.num_coordinates()), VecX::Zero(model.num_constraints()), 0, {}} {}

Accelerations forward_dynamics(const Model& model, const VecX& q, const VecX& qd, double t,
                               const Baumgarte& baumgarte) {
  DynamicsData data(model);
  forward_dynamics(model, q, qd, t, baumgarte, data);
  return std::move(data.solution);
}

}  // namespace fmbd
