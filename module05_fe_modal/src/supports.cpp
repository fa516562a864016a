// Exercise file of module 5, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 5, task T4: boundary conditions by removal of DOFs, and the way back.
#include <string>

#include "fmbd/errors.hpp"
#include "fmbd/supports.hpp"

namespace fmbd {

DofMap apply_supports(const FeModel& fe, const std::vector<NodeSupport>& supports) {
  for (std::size_t s = 0; s < supports.size(); ++s) fe.check_node(supports[s].node, "support " + std::to_string(s));
  // TODO(M05T4): the DofMap of the supports, README section 3, supports.hpp: num_dofs =
  //   fe.num_dofs() and free = every DOF that no support fixes, ascending. Node k owns DOFs 3k (u_x),
  //   3k+1 (u_y), 3k+2 (psi); clamped fixes all three, hinged u_x and u_y, free none. A node may be
  //   listed more than once. Stuck? ./workbook hint M05T4
  unused(fe, supports);
  throw NotImplemented("M05T4 apply_supports");
}

MatX reduce(const MatX& A, const DofMap& map) {
  if (A.rows() != map.num_dofs || A.cols() != map.num_dofs)
    throw std::invalid_argument("reduce: the matrix is " + std::to_string(A.rows()) + "x" + std::to_string(A.cols()) +
                                ", the DofMap has " + std::to_string(map.num_dofs) + " DOFs");
  // TODO(M05T4): A_ff = A(free, free) (num_free x num_free, rows and columns in the order of
  //   map.free), README section 3.
  unused(A, map);
  throw NotImplemented("M05T4 reduce");
}

VecX reduce(const VecX& F, const DofMap& map) {
  if (F.size() != map.num_dofs)
    throw std::invalid_argument("reduce: the vector has " + std::to_string(F.size()) + " entries, the DofMap has " +
                                std::to_string(map.num_dofs) + " DOFs");
  // TODO(M05T4): F_f = F(free) (num_free, in the order of map.free), README section 3.
  unused(F, map);
  throw NotImplemented("M05T4 reduce");
}

VecX expand(const VecX& u_free, const DofMap& map) {
  if (u_free.size() != map.num_free())
    throw std::invalid_argument("expand: the vector has " + std::to_string(u_free.size()) +
                                " entries, the DofMap has " + std::to_string(map.num_free()) + " free DOFs");
  // TODO(M05T4): the full vector (map.num_dofs) with u_free at the free DOFs and 0 at the fixed
  //   ones, README section 3.
  unused(u_free, map);
  throw NotImplemented("M05T4 expand");
}

MatX expand(const MatX& columns, const DofMap& map) {
  MatX out(map.num_dofs, columns.cols());
  for (Eigen::Index c = 0; c < columns.cols(); ++c) out.col(c) = expand(VecX(columns.col(c)), map);
  return out;
}

}  // namespace fmbd
