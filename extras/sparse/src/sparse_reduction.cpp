// Craig-Bampton on sparse matrices (given code, module 6).
#include "fmbd/sparse_reduction.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <string>

namespace fmbd {

namespace {

// Interior DOFs: every index of 0 .. n-1 that is not an interface DOF, ascending.
std::vector<int> interior_of(int n, const std::vector<int>& interface) {
  std::vector<bool> is_interface(n, false);
  for (std::size_t r = 0; r < interface.size(); ++r) {
    const int b = interface[r];
    if (b < 0 || b >= n)
      throw std::invalid_argument("sparse_craig_bampton: interface DOF " + std::to_string(b) + " (entry " +
                                  std::to_string(r) + ") is out of range 0 .. " + std::to_string(n - 1));
    if (is_interface[b])
      throw std::invalid_argument("sparse_craig_bampton: interface DOF " + std::to_string(b) + " is listed twice");
    is_interface[b] = true;
  }
  std::vector<int> interior;
  for (int i = 0; i < n; ++i)
    if (!is_interface[i]) interior.push_back(i);
  return interior;
}

}  // namespace

ReducedBasis sparse_craig_bampton(const SparseMat& K, const SparseMat& M, const std::vector<int>& interface,
                                  int num_modes, const ShiftInvertOptions& options) {
  const int n = static_cast<int>(K.rows());
  if (K.cols() != n || M.rows() != n || M.cols() != n)
    throw std::invalid_argument("sparse_craig_bampton: K and M must both be n x n");
  if (interface.empty()) throw std::invalid_argument("sparse_craig_bampton: the interface has no DOFs");
  const std::vector<int> interior = interior_of(n, interface);
  const int n_b = static_cast<int>(interface.size());
  const int n_i = static_cast<int>(interior.size());
  if (num_modes < 0 || (num_modes > 0 && num_modes > n_i - 1))
    throw std::invalid_argument("sparse_craig_bampton: num_modes must be between 0 and n_i - 1 = " +
                                std::to_string(n_i - 1) + " (n_i interior DOFs), got " + std::to_string(num_modes));

  MatX Phi = MatX::Zero(n, n_b + num_modes);
  for (int r = 0; r < n_b; ++r) Phi(interface[r], r) = 1.0;
  if (n_i > 0) {
    // Constraint modes: K_ii Psi = -K_ib; a (nearly) zero pivot of K_ii means rigid motion is free.
    const SparseMat K_ii = sparse_block(K, interior, interior);
    Eigen::SimplicialLDLT<SparseMat, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt(K_ii);
    const VecX diagonal = ldlt.permutationP() * VecX(K_ii.diagonal());
    bool singular = ldlt.info() != Eigen::Success;
    for (Eigen::Index j = 0; !singular && j < diagonal.size(); ++j)
      singular = !(ldlt.vectorD()(j) > 1e-11 * std::abs(diagonal(j)));  // as in sparse_lowest_modes
    if (singular)
      throw std::invalid_argument(
          "sparse_craig_bampton: K_ii is singular: with the interface DOFs fixed the interior can still move "
          "rigidly; choose interface DOFs that hold the body (for example all three DOFs of one node)");
    const MatX K_ib = MatX(sparse_block(K, interior, interface));
    const MatX Psi = -ldlt.solve(K_ib);
    for (int r = 0; r < n_i; ++r) Phi.row(interior[r]).head(n_b) = Psi.row(r);
    if (num_modes > 0) {
      const Modes fixed = sparse_lowest_modes(K_ii, sparse_block(M, interior, interior), num_modes, options);
      for (int r = 0; r < n_i; ++r) Phi.row(interior[r]).tail(num_modes) = fixed.shapes.row(r);
    }
  }

  ReducedBasis basis;
  basis.M_bar = Phi.transpose() * (M * Phi);
  basis.K_bar = Phi.transpose() * (K * Phi);
  basis.Phi = std::move(Phi);
  basis.num_rigid = 0;
  return basis;
}

}  // namespace fmbd
