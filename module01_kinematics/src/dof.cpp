// Exercise file of module 1, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 1, task T7: rank of the constraint Jacobian and the degrees of freedom.
#include <Eigen/SVD>

#include "fmbd/constraints.hpp"
#include "fmbd/dof.hpp"
#include "fmbd/errors.hpp"

namespace fmbd {

int jacobian_rank(const MatX& Cq) {
  // TODO(M01T7): the rank of C_q (m x n), robust to round-off: the number of singular values
  //   above rank_tolerance times the largest one (README section 2, dof.hpp); 0 for an empty
  //   matrix. Do not count rows: redundant equations do not raise the rank.
  //   Stuck? ./workbook hint M01T7
  unused(Cq);
  throw NotImplemented("M01T7 jacobian_rank");
}

int degrees_of_freedom(const Model& model, const VecX& q, double t) {
  // TODO(M01T7): the degrees of freedom n - rank C_q(q, t) at (q, t) (README section 2,
  //   dof.hpp), with n = model.num_coordinates(); constraint_jacobian() assembles C_q.
  unused(model, q, t);
  throw NotImplemented("M01T7 degrees_of_freedom");
}

}  // namespace fmbd
