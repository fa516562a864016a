// Exercise file of module 6, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
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
  // TODO(M06T1): the rigid-body modes about the centroid, README section 1, rigid_body_modes.hpp:
  //   m, c, J and Phi_r = [t_x, t_y, r_c] (n x 3; node k at rows 3k .. 3k+2, x_k = fe.nodes()[k]),
  //   all from M alone. Stuck? ./workbook hint M06T1
  unused(fe, M);
  throw NotImplemented("M06T1 rigid_body_modes");
}

}  // namespace fmbd
