#pragma once
// Boundary conditions by removal of degrees of freedom (module 5, task T4).
//
// Supports fix nodal DOFs to zero. The remaining (free) DOFs form the reduced vector u_f, in
// increasing order of their full index. Reduced matrices are the free rows and columns,
// K_ff = K(free, free); a reduced vector maps back to the full one with zeros at fixed DOFs.

#include <vector>

#include "fmbd/fe_model.hpp"

namespace fmbd {

/// clamped: u_x = u_y = psi = 0. hinged: u_x = u_y = 0, psi free. free: nothing fixed.
enum class Support { clamped, hinged, free };

struct NodeSupport {
  int node = 0;
  Support support = Support::clamped;
};

/// The free DOFs of a supported model.
struct DofMap {
  int num_dofs = 0;           ///< size of the full vector u (3 N)
  std::vector<int> free;      ///< full indices of the free DOFs, strictly increasing
  int num_free() const { return static_cast<int>(free.size()); }
};

/// M05T4. The DofMap of a model with the given supports. A node may appear more than once; its
/// fixed DOFs are then the union. Throws ModelError if a node index is out of range.
DofMap apply_supports(const FeModel& fe, const std::vector<NodeSupport>& supports);

/// M05T4. A_ff = A(free, free): the reduced square matrix (num_free x num_free).
MatX reduce(const MatX& A, const DofMap& map);

/// M05T4. F_f = F(free): the reduced vector (num_free).
VecX reduce(const VecX& F, const DofMap& map);

/// M05T4. The full vector (num_dofs) with u_f at the free DOFs and 0 at the fixed ones.
VecX expand(const VecX& u_free, const DofMap& map);

/// Column-wise expand of a matrix whose columns are reduced vectors (mode shapes), given code.
MatX expand(const MatX& columns, const DofMap& map);

/// Eigen expressions (K * x, shapes.col(i), MatX::Zero(n, n)) go to the vector overloads if they
/// have one column at compile time, else to the matrix ones.
template <typename Derived>
auto reduce(const Eigen::MatrixBase<Derived>& A, const DofMap& map) {
  if constexpr (Derived::ColsAtCompileTime == 1) return reduce(VecX(A), map);
  else return reduce(MatX(A), map);
}
template <typename Derived>
auto expand(const Eigen::MatrixBase<Derived>& u, const DofMap& map) {
  if constexpr (Derived::ColsAtCompileTime == 1) return expand(VecX(u), map);
  else return expand(MatX(u), map);
}

}  // namespace fmbd
