// Exercise file of module 6, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory and the hints.
// Module 6, task T1: rigid-body modes about the centroid.
#include <string>

#include "fmbd/errors.hpp"
#include "fmbd/reduction.hpp"

namespace fmbd {

RigidBodyModes rigid_body_modes(const FeModel& fe, const MatX& M) {
  const int n = fe.num_dofs();
  if (M.rows() != n || M.cols() != n)
    throw std::invalid_argument("rigid_body_modes: M is " + std::to_string(M.rows()) + "x" +
                                std::to_string(M.cols()) + ", the model has " + std::to_string(n) + " DOFs");
  // TODO(M06T1): build the rigid motions of the nodes x_k = fe.nodes()[k]:
  //   t_x: (1, 0, 0) at every node, t_y: (0, 1, 0), r_o: (-y_k, x_k, 1) (unit rotation about the origin).
  //   m = t_x^T M t_x. The first moments give the centroid: c_x = t_y^T M r_o / m, c_y = -t_x^T M r_o / m.
  //   The rotation about c is r_c: (-(y_k - c_y), x_k - c_x, 1), and J = r_c^T M r_c.
  //   Phi_r = [t_x, t_y, r_c].
  unused(fe, M);
  throw NotImplemented("M06T1 rigid_body_modes");
}

}  // namespace fmbd
