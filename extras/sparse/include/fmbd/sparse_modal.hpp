#pragma once
// The sparse modal path for large FE models (module 5, given code).
//
// The dense modal_analysis (task M05T5) computes every eigenpair of an n x n problem: O(n^3) time
// and O(n^2) memory, a few thousand DOFs at most. A large model needs only its lowest modes, which
// a Lanczos method finds from sparse matrices by shift-invert: with a shift sigma below the
// wanted eigenvalues lambda = omega^2 of K phi = lambda M phi,
//
//   (K - sigma M)^{-1} M phi = nu phi,       nu = 1 / (lambda - sigma),
//
// turns the lowest lambda into the largest nu, where Lanczos converges fastest. K - sigma M is
// factorised once by a sparse LDL^T (Eigen::SimplicialLDLT, fill-reducing AMD ordering) and every
// Lanczos step costs one pair of triangular solves and one product with M (Spectra's
// SymGEigsShiftSolver in shift-invert mode, with M as the inner product).
//
// Free-free models: K is singular (the three rigid motions have lambda = 0), so sigma = 0 is not
// allowed. A small negative shift makes K - sigma M = K + |sigma| M positive definite; the default,
// default_shift(K, M), is -1e-9 times the largest ratio K_jj / M_jj of the diagonals (each such
// ratio is a Rayleigh quotient, so it lies between the lowest and the highest eigenvalue): far
// below the elastic eigenvalues of practical models, yet well above the round-off of the
// factorisation of K.

#include <optional>
#include <stdexcept>
#include <vector>

#include "fmbd/matrix_market.hpp"
#include "fmbd/modal.hpp"

namespace fmbd {

/// The factorisation of K - sigma M broke down: sigma is (nearly) an eigenvalue, for example
/// sigma = 0 for a model whose supports leave a rigid-body motion free.
class SingularShiftedMatrix : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The Lanczos iteration did not find all the requested modes within its restarts.
class EigenSolverNotConverged : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Settings of sparse_lowest_modes. The defaults suit FE models of any size.
struct ShiftInvertOptions {
  std::optional<double> shift;   ///< sigma, below the lowest wanted eigenvalue; none: default_shift(K, M)
  int subspace = 0;              ///< Lanczos basis size (Spectra's ncv), count < subspace <= n;
                                 ///< 0: min(n, max(2 count + 1, count + 20))
  int max_restarts = 1000;       ///< implicit restarts before EigenSolverNotConverged
  double tolerance = 1e-10;      ///< relative accuracy of the eigenvalues nu of the shifted problem
  bool sturm_check = true;       ///< count the eigenvalues below the highest mode found (one more
                                 ///< factorisation) and find any that Lanczos missed
};

/// The default shift of sparse_lowest_modes: -1e-9 max_j (K_jj / M_jj) over the DOFs with
/// M_jj > 0 (see the top of this file). Throws std::invalid_argument if no such DOF has K_jj > 0.
double default_shift(const SparseMat& K, const SparseMat& M);

/// The `count` lowest modes of K phi = omega^2 M phi for sparse symmetric K (positive
/// semi-definite) and M (positive definite), by shift-invert Lanczos (top of this file). Returns
/// the same Modes as modal_analysis: omega ascending, with omega = sqrt(max(lambda, 0)) (the zero
/// modes of a free-free model come out as round-off of either sign), shapes mass-normalised,
/// phi_i^T M phi_j = delta_ij; the sign of each shape, and the basis within repeated eigenvalues
/// (such as the three rigid motions), are not specified.
///
/// Steps: factorise K - sigma M; Lanczos for `count` modes; a Rayleigh-Ritz step on the vectors
/// found, so that the shapes are M-orthonormal to round-off, also within repeated eigenvalues;
/// then, with options.sturm_check, a Sturm count: the number of negative pivots of
/// K - tau M = L D L^T for tau just above the highest mode found is the number of eigenvalues
/// below tau (law of inertia). Lanczos finds the copies of a repeated eigenvalue (the three
/// rigid-body modes, the twin modes of a symmetric frame) only through round-off and may miss one;
/// missing modes are then found by another Lanczos run with the modes found so far locked
/// (projected out).
///
/// Throws std::invalid_argument for: sizes that do not match; count outside 1 .. n - 1 (Lanczos
/// needs a larger space than the modes it returns); a matrix that is not finite or not symmetric
/// (|a_ij - a_ji| > 1e-10 max |a|); a diagonal entry of M that is not positive; a shift above an
/// eigenvalue (the factorisation of K - sigma M has negative pivots: the modes nearest sigma would
/// not be the lowest). Throws SingularShiftedMatrix if K - sigma M is singular to working
/// precision (a pivot below 1e-11 of its diagonal entry), and EigenSolverNotConverged if the
/// iteration does not converge or the Sturm count still disagrees after three more runs.
Modes sparse_lowest_modes(const SparseMat& K, const SparseMat& M, int count, const ShiftInvertOptions& options = {});

/// The same with an explicit shift sigma.
Modes sparse_lowest_modes(const SparseMat& K, const SparseMat& M, int count, double shift);

/// Assembles M_FE and K_FE of a module-5 model like assemble() does, from the element matrices
/// T^T k_e T and T^T m_e T of beam_element.hpp, into sparse matrices (entries that are exactly
/// zero are left out). Throws ModelError (FeModel::validate) like assemble().
SparseFeMatrices sparse_fe_matrices(const FeModel& fe, MassMatrixType type);

/// The dense FeMatrices of sparse ones, for the dense functions of modules 5 to 7 (small models).
FeMatrices to_dense(const SparseFeMatrices& matrices);

/// A(rows, cols) of a sparse matrix for lists of indices (each in range; order kept).
/// Throws std::invalid_argument for an index out of range.
SparseMat sparse_block(const SparseMat& A, const std::vector<int>& rows, const std::vector<int>& cols);

/// A_ff = A(free, free) of a supported model (supports.hpp), sparse.
SparseMat reduce_sparse(const SparseMat& A, const DofMap& map);

/// A rectangular planar frame lattice for large models: (cells_x + 1) x (cells_y + 1) nodes on a
/// grid of cell_width x cell_height from the origin, node (i, j) (column i, row j) numbered
/// j (cells_x + 1) + i; an element along every edge of every cell, and one diagonal per cell,
/// from the lower left to the upper right corner where i + j is even and from the lower right to
/// the upper left where it is odd. 3 (cells_x + 1)(cells_y + 1) DOFs. Throws ModelError for fewer
/// than one cell in a direction or a cell size that is not positive (and like add_element).
FeModel frame_lattice(int cells_x, int cells_y, double cell_width, double cell_height, const Section& section);

}  // namespace fmbd
