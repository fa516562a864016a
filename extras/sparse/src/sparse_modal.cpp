// The sparse modal path: shift-invert Lanczos, sparse assembly, a large lattice (given code,
// module 5).
#include "fmbd/sparse_modal.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsShiftSolver.h>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "fmbd/beam_element.hpp"

namespace fmbd {

namespace {

constexpr double kSymmetryTolerance = 1e-10;  // |a_ij - a_ji| <= tol * max |a|
constexpr double kPivotTolerance = 1e-11;     // |d_j| below this times its diagonal entry: singular

double max_abs(const SparseMat& A) {
  double m = 0.0;
  for (int c = 0; c < A.outerSize(); ++c)
    for (SparseMat::InnerIterator it(A, c); it; ++it) m = std::max(m, std::abs(it.value()));
  return m;
}

void check_symmetric(const SparseMat& A, const char* name, Eigen::Index n) {
  std::ostringstream s;
  s << "sparse_lowest_modes: " << name;
  if (A.rows() != n || A.cols() != n) {
    s << " is " << A.rows() << "x" << A.cols() << ", expected " << n << "x" << n;
    throw std::invalid_argument(s.str());
  }
  const double scale = max_abs(A);
  if (!std::isfinite(scale)) throw std::invalid_argument(s.str() + " is not finite");
  const SparseMat At = A.transpose();
  const double asym = max_abs(SparseMat(A - At));
  if (asym > kSymmetryTolerance * std::max(scale, 1e-300)) {
    s << " is not symmetric (max |A - A^T| = " << asym << ")";
    throw std::invalid_argument(s.str());
  }
}

std::string shift_text(double sigma) {
  std::ostringstream s;
  s.precision(6);
  s << sigma;
  return s.str();
}

// The shift-invert operator y = (K - sigma M)^{-1} x for Spectra, factorised by a sparse LDL^T.
// It is factorised for one shift in the constructor (with its checks); Spectra's set_shift then
// only confirms that shift. After lock(Phi), it returns P y with P = I - Phi Phi^T M, which maps
// the M-orthonormal modes Phi to zero: a later run finds only modes that are not yet in Phi.
class ShiftedInverse {
 public:
  using Scalar = double;

  ShiftedInverse(const SparseMat& K, const SparseMat& M, double sigma) : n_(K.rows()), sigma_(sigma) {
    const SparseMat A = K - sigma * M;
    ldlt_.compute(A);
    const std::string hint = sigma == 0.0
                                 ? "; K alone is singular: use a negative shift for a model with rigid-body motions"
                                 : "; choose another shift";
    if (ldlt_.info() != Eigen::Success)
      throw SingularShiftedMatrix("sparse_lowest_modes: K - sigma M is singular for sigma = " + shift_text(sigma) +
                                  " (a zero pivot in its LDL^T factorisation); sigma is an eigenvalue" + hint);
    // Pivots of P A P^T = L D L^T against the diagonal of P A P^T.
    const VecX diagonal = ldlt_.permutationP() * VecX(A.diagonal());
    const VecX& d = ldlt_.vectorD();
    Eigen::Index negative = 0, smallest = 0;
    double smallest_ratio = 1.0;
    for (Eigen::Index j = 0; j < n_; ++j) {
      const double ratio = std::abs(d(j)) / std::max(std::abs(diagonal(j)), 1e-300);
      if (ratio < smallest_ratio) {
        smallest_ratio = ratio;
        smallest = j;
      }
      if (d(j) < 0.0) ++negative;
    }
    if (smallest_ratio < kPivotTolerance)
      throw SingularShiftedMatrix("sparse_lowest_modes: K - sigma M is singular to working precision for sigma = " +
                                  shift_text(sigma) + " (pivot " + shift_text(d(smallest)) +
                                  " against the diagonal entry " + shift_text(diagonal(smallest)) +
                                  "); sigma is (nearly) an eigenvalue" + hint);
    if (negative > 0)
      throw std::invalid_argument("sparse_lowest_modes: the shift sigma = " + shift_text(sigma) + " lies above " +
                                  std::to_string(negative) +
                                  " eigenvalue(s) of K phi = lambda M phi (negative pivots of K - sigma M), so the "
                                  "modes nearest sigma are not the lowest; choose a shift below the lowest "
                                  "eigenvalue (or the default)");
  }

  Eigen::Index rows() const { return n_; }
  Eigen::Index cols() const { return n_; }
  double shift() const { return sigma_; }
  Eigen::Index locked() const { return Phi_.cols(); }

  void set_shift(double sigma) {
    if (sigma != sigma_) throw std::logic_error("sparse_lowest_modes: the operator is factorised for another shift");
  }

  void lock(const MatX& Phi, const SparseMat& M) {
    Phi_ = Phi;
    MPhi_ = M * Phi;
  }

  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<const VecX> x(x_in, n_);
    Eigen::Map<VecX> y(y_out, n_);
    y = ldlt_.solve(x);
    if (Phi_.cols() > 0) y -= Phi_ * (MPhi_.transpose() * y);
  }

 private:
  Eigen::Index n_;
  double sigma_;
  Eigen::SimplicialLDLT<SparseMat, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt_;
  MatX Phi_, MPhi_;  // locked modes and M Phi
};

// `wanted` eigenvectors of the largest nu of the operator (the lowest lambda not locked), by
// Spectra's shift-invert Lanczos with M as the inner product.
MatX lanczos(ShiftedInverse& op, const SparseMat& M, int wanted, Eigen::Index subspace,
             const ShiftInvertOptions& options) {
  using MassProduct = Spectra::SparseSymMatProd<double>;
  MassProduct mass(M);
  Spectra::SymGEigsShiftSolver<ShiftedInverse, MassProduct, Spectra::GEigsMode::ShiftInvert> solver(
      op, mass, wanted, subspace, op.shift());
  solver.init();
  const Eigen::Index converged = solver.compute(Spectra::SortRule::LargestMagn, options.max_restarts,
                                                options.tolerance, Spectra::SortRule::SmallestAlge);
  if (solver.info() != Spectra::CompInfo::Successful) {
    std::ostringstream s;
    s << "sparse_lowest_modes: the Lanczos iteration found " << converged << " of " << wanted << " modes in "
      << solver.num_iterations() << " restarts (subspace " << subspace << ", tolerance " << options.tolerance
      << "); allow more restarts or a larger subspace";
    throw EigenSolverNotConverged(s.str());
  }
  return solver.eigenvectors();
}

// Rayleigh-Ritz on the span of V: lambda ascending, shapes M-orthonormal and K-orthogonal to
// round-off (also within clusters such as the rigid-body modes).
struct Ritz {
  VecX lambda;
  MatX shapes;
};

Ritz rayleigh_ritz(const SparseMat& K, const SparseMat& M, const MatX& V) {
  const MatX G = V.transpose() * (M * V), H = V.transpose() * (K * V);
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatX> ritz(0.5 * (H + H.transpose()), 0.5 * (G + G.transpose()));
  if (ritz.info() != Eigen::Success)
    throw EigenSolverNotConverged("sparse_lowest_modes: the Rayleigh-Ritz step on the Lanczos vectors failed "
                                  "(dependent vectors)");
  Ritz out{ritz.eigenvalues(), V * ritz.eigenvectors()};
  for (Eigen::Index i = 0; i < out.shapes.cols(); ++i)
    out.shapes.col(i) /= std::sqrt(out.shapes.col(i).dot(M * out.shapes.col(i)));
  return out;
}

// Sturm count: the number of eigenvalues below tau, the negative pivots of K - tau M = L D L^T
// (Sylvester's law of inertia). tau is nudged upwards if it hits an eigenvalue exactly.
Eigen::Index eigenvalues_below(const SparseMat& K, const SparseMat& M, double tau) {
  for (int attempt = 0; attempt < 4; ++attempt) {
    Eigen::SimplicialLDLT<SparseMat, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt(K - tau * M);
    if (ldlt.info() == Eigen::Success) return (ldlt.vectorD().array() < 0.0).count();
    tau += 1e-6 * std::max(std::abs(tau), 1e-300);
  }
  throw EigenSolverNotConverged("sparse_lowest_modes: the Sturm count of K - tau M failed for tau = " +
                                shift_text(tau));
}

// max_j K_jj / M_jj over the DOFs with both positive; 0 if there is none.
double largest_diagonal_ratio(const SparseMat& K, const SparseMat& M) {
  const VecX k = K.diagonal(), m = M.diagonal();
  double ratio = 0.0;
  for (Eigen::Index j = 0; j < k.size(); ++j)
    if (m(j) > 0.0 && k(j) > 0.0) ratio = std::max(ratio, k(j) / m(j));
  return ratio;
}

}  // namespace

double default_shift(const SparseMat& K, const SparseMat& M) {
  if (K.rows() != M.rows() || K.cols() != M.cols())
    throw std::invalid_argument("default_shift: K and M differ in size");
  const double ratio = largest_diagonal_ratio(K, M);
  if (!(ratio > 0.0) || !std::isfinite(ratio))
    throw std::invalid_argument("default_shift: no DOF with K_jj > 0 and M_jj > 0; give the shift explicitly");
  return -1e-9 * ratio;
}

Modes sparse_lowest_modes(const SparseMat& K, const SparseMat& M, int count, double shift) {
  ShiftInvertOptions options;
  options.shift = shift;
  return sparse_lowest_modes(K, M, count, options);
}

Modes sparse_lowest_modes(const SparseMat& K, const SparseMat& M, int count, const ShiftInvertOptions& options) {
  const Eigen::Index n = K.rows();
  check_symmetric(K, "K", n);
  check_symmetric(M, "M", n);
  if (count < 1 || count > n - 1)
    throw std::invalid_argument("sparse_lowest_modes: count must be between 1 and n - 1 = " + std::to_string(n - 1) +
                                ", got " + std::to_string(count));
  const VecX m_diagonal = M.diagonal();
  for (Eigen::Index j = 0; j < n; ++j)
    if (!(m_diagonal(j) > 0.0))
      throw std::invalid_argument("sparse_lowest_modes: M is not positive definite: M(" + std::to_string(j) + ", " +
                                  std::to_string(j) + ") = " + std::to_string(m_diagonal(j)) +
                                  " (a DOF without mass?)");
  const double sigma = options.shift ? *options.shift : default_shift(K, M);
  if (!std::isfinite(sigma)) throw std::invalid_argument("sparse_lowest_modes: the shift is not finite");
  auto default_subspace = [n](Eigen::Index wanted, Eigen::Index locked) {
    return std::min<Eigen::Index>(n - locked, std::max<Eigen::Index>(2 * wanted + 1, wanted + 20));
  };
  const Eigen::Index ncv = options.subspace > 0 ? options.subspace : default_subspace(count, 0);
  if (ncv <= count || ncv > n)
    throw std::invalid_argument("sparse_lowest_modes: the subspace size must lie in count + 1 .. n = " +
                                std::to_string(count + 1) + " .. " + std::to_string(n) + ", got " + std::to_string(ncv));
  if (options.max_restarts < 1 || !(options.tolerance > 0.0))
    throw std::invalid_argument("sparse_lowest_modes: max_restarts must be positive and tolerance > 0");

  ShiftedInverse op(K, M, sigma);
  Ritz ritz = rayleigh_ritz(K, M, lanczos(op, M, count, ncv, options));

  // Lanczos sees a repeated eigenvalue (the three rigid-body modes, or the twin modes of a
  // symmetric structure) only through round-off and may return too few copies. The Sturm count
  // just above lambda_count says how many eigenvalues lie below it; missing ones are found by
  // another run with the modes found so far locked.
  for (int round = 0; options.sturm_check; ++round) {
    const double top = ritz.lambda(count - 1);
    // Above top by a margin that clears round-off also when top is a zero eigenvalue.
    const double tau = top + std::max(1e-3 * (top - sigma), 1e-9 * largest_diagonal_ratio(K, M));
    const Eigen::Index below = eigenvalues_below(K, M, tau);
    const Eigen::Index found = (ritz.lambda.array() < tau).count();
    if (below <= found) break;
    const Eigen::Index locked = ritz.shapes.cols();
    const Eigen::Index missing = below - found;
    if (round == 3 || locked + missing > n - 1)
      throw EigenSolverNotConverged("sparse_lowest_modes: the Sturm count finds " + std::to_string(below) +
                                    " eigenvalues below " + shift_text(tau) + ", the Lanczos runs only " +
                                    std::to_string(found));
    op.lock(ritz.shapes, M);
    const MatX extra = lanczos(op, M, static_cast<int>(missing), default_subspace(missing, locked), options);
    MatX V(n, locked + extra.cols());
    V << ritz.shapes, extra;
    ritz = rayleigh_ritz(K, M, V);
  }

  Modes modes;
  modes.omega = ritz.lambda.head(count).cwiseMax(0.0).cwiseSqrt();
  modes.shapes = ritz.shapes.leftCols(count);
  return modes;
}

SparseFeMatrices sparse_fe_matrices(const FeModel& fe, MassMatrixType type) {
  fe.validate();
  const int n = fe.num_dofs();
  std::vector<Eigen::Triplet<double>> k_entries, m_entries;
  k_entries.reserve(36 * static_cast<std::size_t>(fe.num_elements()));
  m_entries.reserve(36 * static_cast<std::size_t>(fe.num_elements()));
  for (int e = 0; e < fe.num_elements(); ++e) {
    // The element's matrices in global axes, and the global DOF of each of its six.
    const Mat6 rotate = beam_transformation(fe.angle(e));
    const Section& section = fe.elements()[e].section;
    const Mat6 k = rotate.transpose() * beam_stiffness(section, fe.length(e)) * rotate;
    const Mat6 m = rotate.transpose() * beam_mass(section, fe.length(e), type) * rotate;
    const int nodes[2] = {fe.elements()[e].node_a, fe.elements()[e].node_b};
    const auto dof = [&](int local) { return 3 * nodes[local / 3] + local % 3; };
    // Exactly symmetric entries (the mean of (r, c) and (c, r)); round-off of T^T m T where m is
    // diagonal is left out: |a_rc| <= 1e-14 sqrt(a_rr a_cc), far below any entry of a real element.
    auto add = [&](std::vector<Eigen::Triplet<double>>& entries, const Mat6& a) {
      for (int c = 0; c < 6; ++c)
        for (int r = c; r < 6; ++r) {
          const double v = r == c ? a(r, r) : 0.5 * (a(r, c) + a(c, r));
          if (v == 0.0 || (r != c && std::abs(v) <= 1e-14 * std::sqrt(std::abs(a(r, r) * a(c, c))))) continue;
          const int row = dof(r), col = dof(c);
          entries.emplace_back(row, col, v);
          if (r != c) entries.emplace_back(col, row, v);
        }
    };
    add(k_entries, k);
    add(m_entries, m);
  }
  SparseFeMatrices out;
  out.K.resize(n, n);
  out.M.resize(n, n);
  out.K.setFromTriplets(k_entries.begin(), k_entries.end());
  out.M.setFromTriplets(m_entries.begin(), m_entries.end());
  out.K.makeCompressed();
  out.M.makeCompressed();
  return out;
}

FeMatrices to_dense(const SparseFeMatrices& matrices) { return FeMatrices{MatX(matrices.M), MatX(matrices.K)}; }

SparseMat sparse_block(const SparseMat& A, const std::vector<int>& rows, const std::vector<int>& cols) {
  auto selection = [](const std::vector<int>& index, Eigen::Index size, const char* what) {
    std::vector<Eigen::Triplet<double>> ones;
    ones.reserve(index.size());
    for (std::size_t k = 0; k < index.size(); ++k) {
      if (index[k] < 0 || index[k] >= size)
        throw std::invalid_argument(std::string("sparse_block: ") + what + " index " + std::to_string(index[k]) +
                                    " (entry " + std::to_string(k) + ") is outside 0 .. " + std::to_string(size - 1));
      ones.emplace_back(static_cast<int>(k), index[k], 1.0);
    }
    SparseMat S(static_cast<Eigen::Index>(index.size()), size);
    S.setFromTriplets(ones.begin(), ones.end());
    return S;
  };
  const SparseMat R = selection(rows, A.rows(), "row");
  const SparseMat C = selection(cols, A.cols(), "column");
  SparseMat out = R * A * SparseMat(C.transpose());
  out.makeCompressed();
  return out;
}

SparseMat reduce_sparse(const SparseMat& A, const DofMap& map) {
  if (A.rows() != map.num_dofs || A.cols() != map.num_dofs)
    throw std::invalid_argument("reduce_sparse: the matrix is " + std::to_string(A.rows()) + "x" +
                                std::to_string(A.cols()) + ", the DofMap has " + std::to_string(map.num_dofs) + " DOFs");
  return sparse_block(A, map.free, map.free);
}

FeModel frame_lattice(int cells_x, int cells_y, double cell_width, double cell_height, const Section& section) {
  if (cells_x < 1 || cells_y < 1)
    throw ModelError("frame_lattice: needs at least one cell in each direction, got " + std::to_string(cells_x) +
                     " x " + std::to_string(cells_y));
  if (!(cell_width > 0.0 && cell_height > 0.0 && std::isfinite(cell_width) && std::isfinite(cell_height)))
    throw ModelError("frame_lattice: the cell size must be positive and finite");
  FeModel fe;
  const int columns = cells_x + 1;
  for (int j = 0; j <= cells_y; ++j)
    for (int i = 0; i <= cells_x; ++i) fe.add_node(Vec2(i * cell_width, j * cell_height));
  auto node = [columns](int i, int j) { return j * columns + i; };
  for (int j = 0; j <= cells_y; ++j)
    for (int i = 0; i <= cells_x; ++i) {
      if (i < cells_x) fe.add_element(node(i, j), node(i + 1, j), section);
      if (j < cells_y) fe.add_element(node(i, j), node(i, j + 1), section);
      if (i < cells_x && j < cells_y) {
        if ((i + j) % 2 == 0) fe.add_element(node(i, j), node(i + 1, j + 1), section);
        else fe.add_element(node(i + 1, j), node(i, j + 1), section);
      }
    }
  return fe;
}

}  // namespace fmbd
