// Exercise file of module 1, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory and the hints.
// Module 1, task T6: rank of the constraint Jacobian and the degrees of freedom.
#include <Eigen/SVD>

#include "fmbd/constraints.hpp"
#include "fmbd/dof.hpp"
#include "fmbd/errors.hpp"

namespace fmbd {

int jacobian_rank(const MatX& Cq) {
  // TODO(M01T6): rank of C_q, robust to round-off: count the singular values sigma_k with
  //   sigma_k > rank_tolerance * sigma_max. Return 0 for an empty matrix.
  // Hint: Eigen::JacobiSVD<MatX>(Cq).singularValues() (sorted, largest first). Do not count
  //   rows: redundant equations have rank-deficient rows.
  unused(Cq);
  throw NotImplemented("M01T6 jacobian_rank");
}

int degrees_of_freedom(const Model& model, const VecX& q, double t) {
  // TODO(M01T6): degrees of freedom n - rank C_q(q, t), n = model.num_coordinates() (3 n_b for
  //   rigid bodies; constraint_jacobian() assembles C_q).
  unused(model, q, t);
  throw NotImplemented("M01T6 degrees_of_freedom");
}

}  // namespace fmbd
