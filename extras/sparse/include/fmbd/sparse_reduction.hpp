#pragma once
// Craig-Bampton reduction of a large sparse FE model (module 6, given code).
//
// The same basis as craig_bampton (task M06T3), computed without dense n x n matrices: with the
// interface DOFs b and the interior i,
//
//   constraint modes  Psi = -K_ii^{-1} K_ib     by one sparse LDL^T of K_ii (n_b solves),
//   normal modes      K_ii phi = omega^2 M_ii phi, the lowest num_modes, by shift-invert Lanczos
//                     (sparse_lowest_modes of module 5),
//   Phi = [[I, 0], [Psi, Phi_i]] in the rows (b, i), written back to the original DOF order.
//
// Phi itself is dense, n x (n_b + num_modes): a tall thin matrix that fits in memory for models
// of millions of DOFs. The result is the module-6 ReducedBasis, so ffrf_basis and
// flexible_body_data (modules 6 and 7) take it unchanged where the FE model is small enough for
// their dense matrices; for an imported or large model, sparse_ffrf_basis and
// make_sparse_modal_ffrf_body (module 8, sparse_body.hpp) make it a body without them.

#include <vector>

#include "fmbd/reduction.hpp"
#include "fmbd/sparse_modal.hpp"

namespace fmbd {

/// Craig-Bampton basis of sparse (K, M) (n x n, any supports already removed) for the interface
/// DOFs `interface` (indices into the vectors of K) and the `num_modes` lowest fixed-interface
/// normal modes, with the columns, rows and M_bar = Phi^T M Phi, K_bar = Phi^T K Phi of
/// craig_bampton; num_rigid = 0. `options` go to sparse_lowest_modes for the normal modes (the
/// default shift suits them: K_ii is positive definite). Throws std::invalid_argument for K and M
/// that are not n x n, an empty, repeated or out-of-range interface DOF, num_modes outside
/// 0 .. n_i - 1 (n_i interior DOFs), or a singular K_ii (the fixed interface leaves rigid motion
/// free), and what sparse_lowest_modes throws.
ReducedBasis sparse_craig_bampton(const SparseMat& K, const SparseMat& M, const std::vector<int>& interface,
                                  int num_modes, const ShiftInvertOptions& options = {});

}  // namespace fmbd
