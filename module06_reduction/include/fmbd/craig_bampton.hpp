#pragma once
// Craig-Bampton reduction and a basis made ready for the FFRF (module 6, tasks T3 and T4), with
// the given helpers of those tasks (src/craig_bampton_given.cpp).

#include <Eigen/Cholesky>
#include <vector>

#include "fmbd/reduced_basis.hpp"
#include "fmbd/rigid_body_modes.hpp"

namespace fmbd {

/// M06T3. Craig-Bampton basis of (K, M) (n x n, any supports already removed) for the interface
/// DOFs b (indices into the vectors of K) and the `num_modes` lowest fixed-interface normal modes.
/// With i the other (interior) DOFs:
///   constraint modes  Psi = -K_ii^{-1} K_ib   (unit displacement of one interface DOF, the rest fixed)
///   normal modes      K_ii phi = omega^2 M_ii phi, mass-normalised, lowest num_modes
///   Phi = [[I, 0], [Psi, Phi_i]] in the rows (b, i), written back to the original DOF order.
/// Columns: the n_b constraint modes in the order of `interface`, then the normal modes;
/// num_rigid = 0. Throws std::invalid_argument for an empty, repeated or out-of-range interface
/// DOF, num_modes out of 0 .. n_i, or a singular K_ii (the fixed interface leaves rigid motion free).
ReducedBasis craig_bampton(const MatX& K, const MatX& M, const std::vector<int>& interface, int num_modes);

/// M06T4. A basis for the FFRF from any basis of a free-free model (for example craig_bampton of
/// the full matrices): remove its rigid-body content, P = I - Phi_r (Phi_r^T M Phi_r)^{-1} Phi_r^T M,
/// drop the columns that become dependent, and diagonalise the reduced eigenproblem, so that
/// Phi = [Phi_r, Phi_f] with the same diagonal M_bar and K_bar as modal_truncation.
/// num_rigid = 3. Throws std::invalid_argument if basis.Phi does not have n rows.
ReducedBasis ffrf_basis(const FeModel& fe, const FeMatrices& matrices, const ReducedBasis& basis);

// ---- Given code (src/craig_bampton_given.cpp) ------------------------------------------------------

/// The full DOF indices (3k, 3k+1, 3k+2) of the given nodes, in order: interface DOFs for
/// craig_bampton when whole nodes are interfaces.
std::vector<int> node_dofs(const std::vector<int>& nodes);

/// A(rows, cols): the rows.size() x cols.size() matrix of the entries A(rows[r], cols[c]).
MatX submatrix(const MatX& A, const std::vector<int>& rows, const std::vector<int>& cols);

/// A basis with its reduced matrices: Phi, M_bar = Phi^T M Phi, K_bar = Phi^T K Phi and num_rigid.
ReducedBasis with_matrices(MatX Phi, const MatX& K, const MatX& M, int num_rigid);

/// The partition of the DOFs of craig_bampton into interface DOFs b and interior DOFs i.
struct InterfaceSplit {
  std::vector<int> interior;  ///< every DOF 0 .. n-1 that is not an interface DOF, ascending (n_i)
  MatX K_ii;                  ///< submatrix(K, interior, interior), n_i x n_i
  Eigen::LLT<MatX> K_ii_llt;  ///< the Cholesky factor of K_ii
};

/// The arguments of craig_bampton(K, M, interface, num_modes), checked, and their partition.
/// Throws std::invalid_argument if K or M is not n x n, the interface is empty, an interface DOF
/// is out of 0 .. n-1 or listed twice, num_modes is outside 0 .. n_i, or K_ii is singular (the
/// interior can move rigidly with the interface fixed: a pivot of its Cholesky factor below 1e-12
/// of the largest one).
InterfaceSplit split_interface(const MatX& K, const MatX& M, const std::vector<int>& interface, int num_modes);

}  // namespace fmbd
