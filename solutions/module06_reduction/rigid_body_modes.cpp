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
  // TASK(M06T1): the rigid-body modes about the centroid, README section 1, rigid_body_modes.hpp:
  //   m, c, J and Phi_r = [t_x, t_y, r_c] (n x 3; node k at rows 3k .. 3k+2, x_k = fe.nodes()[k]),
  //   all from M alone. Stuck? ./workbook hint M06T1
  // BEGIN SOLUTION
  RigidBodyModes rigid;
  MatX& Phi = rigid.Phi_r;
  Phi = MatX::Zero(n, 3);
  VecX r_o = VecX::Zero(n);
  for (int k = 0; k < fe.num_nodes(); ++k) {
    const Vec2& x = fe.nodes()[k];
    Phi(3 * k, 0) = 1.0;
    Phi(3 * k + 1, 1) = 1.0;
    r_o.segment<3>(3 * k) << -x.y(), x.x(), 1.0;
  }
  rigid.mass = Phi.col(0).dot(M * Phi.col(0));
  const VecX M_ro = M * r_o;
  rigid.centroid = Vec2(Phi.col(1).dot(M_ro), -Phi.col(0).dot(M_ro)) / rigid.mass;
  for (int k = 0; k < fe.num_nodes(); ++k) {
    const Vec2 d = fe.nodes()[k] - rigid.centroid;
    Phi.block<3, 1>(3 * k, 2) << -d.y(), d.x(), 1.0;
  }
  rigid.inertia = Phi.col(2).dot(M * Phi.col(2));
  return rigid;
  // END SOLUTION
  // STUB: unused(fe, M);
  // STUB: throw NotImplemented("M06T1 rigid_body_modes");
}

}  // namespace fmbd
