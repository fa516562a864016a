// Module 1, task T7: rank of the constraint Jacobian and the degrees of freedom.
#include <Eigen/SVD>

#include "fmbd/constraints.hpp"
#include "fmbd/dof.hpp"
#include "fmbd/errors.hpp"

namespace fmbd {

int jacobian_rank(const MatX& Cq) {
  // TASK(M01T7): the rank of C_q (m x n), robust to round-off: the number of singular values
  //   above rank_tolerance times the largest one (README section 2, dof.hpp); 0 for an empty
  //   matrix. Do not count rows: redundant equations do not raise the rank.
  //   Stuck? ./workbook hint M01T7
  // BEGIN SOLUTION
  if (Cq.size() == 0) return 0;
  const VecX sigma = Eigen::JacobiSVD<MatX>(Cq).singularValues();
  if (sigma(0) == 0.0) return 0;
  return static_cast<int>((sigma.array() > rank_tolerance * sigma(0)).count());
  // END SOLUTION
  // STUB: unused(Cq);
  // STUB: throw NotImplemented("M01T7 jacobian_rank");
}

int degrees_of_freedom(const Model& model, const VecX& q, double t) {
  // TASK(M01T7): the degrees of freedom n - rank C_q(q, t) at (q, t) (README section 2,
  //   dof.hpp), with n = model.num_coordinates(); constraint_jacobian() assembles C_q.
  // BEGIN SOLUTION
  return model.num_coordinates() - jacobian_rank(constraint_jacobian(model, q, t));
  // END SOLUTION
  // STUB: unused(model, q, t);
  // STUB: throw NotImplemented("M01T7 degrees_of_freedom");
}

}  // namespace fmbd
