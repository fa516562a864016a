// Given code of Craig-Bampton (declared in fmbd/craig_bampton.hpp): the helpers of its tasks.
#include <string>
#include <utility>

#include "fmbd/craig_bampton.hpp"

namespace fmbd {

std::vector<int> node_dofs(const std::vector<int>& nodes) {
  std::vector<int> dofs;
  for (int k : nodes)
    for (int d = 0; d < 3; ++d) dofs.push_back(3 * k + d);
  return dofs;
}

MatX submatrix(const MatX& A, const std::vector<int>& rows, const std::vector<int>& cols) {
  MatX out(rows.size(), cols.size());
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (std::size_t c = 0; c < cols.size(); ++c) out(r, c) = A(rows[r], cols[c]);
  return out;
}

ReducedBasis with_matrices(MatX Phi, const MatX& K, const MatX& M, int num_rigid) {
  ReducedBasis basis;
  basis.M_bar = Phi.transpose() * M * Phi;
  basis.K_bar = Phi.transpose() * K * Phi;
  basis.Phi = std::move(Phi);
  basis.num_rigid = num_rigid;
  return basis;
}

InterfaceSplit split_interface(const MatX& K, const MatX& M, const std::vector<int>& interface, int num_modes) {
  const int n = static_cast<int>(K.rows());
  if (K.cols() != n || M.rows() != n || M.cols() != n)
    throw std::invalid_argument("craig_bampton: K and M must both be n x n");
  if (interface.empty()) throw std::invalid_argument("craig_bampton: the interface has no DOFs");
  std::vector<bool> is_interface(n, false);
  for (std::size_t r = 0; r < interface.size(); ++r) {
    const int b = interface[r];
    if (b < 0 || b >= n)
      throw std::invalid_argument("craig_bampton: interface DOF " + std::to_string(b) + " (entry " +
                                  std::to_string(r) + ") is out of range 0 .. " + std::to_string(n - 1));
    if (is_interface[b])
      throw std::invalid_argument("craig_bampton: interface DOF " + std::to_string(b) + " is listed twice");
    is_interface[b] = true;
  }
  InterfaceSplit split;
  for (int i = 0; i < n; ++i)
    if (!is_interface[i]) split.interior.push_back(i);
  const int n_i = static_cast<int>(split.interior.size());
  if (num_modes < 0 || num_modes > n_i)
    throw std::invalid_argument("craig_bampton: num_modes must be between 0 and the " + std::to_string(n_i) +
                                " interior DOFs, got " + std::to_string(num_modes));
  split.K_ii = submatrix(K, split.interior, split.interior);
  split.K_ii_llt.compute(split.K_ii);
  // A singular K_ii may factor with a tiny positive pivot after round-off: check the pivots too.
  const VecX pivots = split.K_ii_llt.matrixLLT().diagonal().cwiseAbs2();
  if (split.K_ii_llt.info() != Eigen::Success ||
      (pivots.size() > 0 && !(pivots.minCoeff() > 1e-12 * pivots.maxCoeff())))
    throw std::invalid_argument(
        "craig_bampton: K_ii is singular: with the interface DOFs fixed the interior can still move "
        "rigidly; choose interface DOFs that hold the body (for example all three DOFs of one node)");
  return split;
}

}  // namespace fmbd
