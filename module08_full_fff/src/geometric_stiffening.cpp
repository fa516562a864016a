// Exercise file of module 8, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 8, tasks T7 and T8: geometric stiffening by the foreshortening of the beam axis.
#include "fmbd/errors.hpp"
#include "fmbd/geometric_stiffening.hpp"

namespace fmbd {

NodeShortening shortening_across_element(const NodeShortening& parent, const MatX& H_e, const Vec2& t_e,
                                         const VecX& q_f, const VecX& q_f_dot) {
  Model::check_size(q_f, static_cast<int>(H_e.rows()), "q_f", "shortening_across_element");
  Model::check_size(q_f_dot, static_cast<int>(H_e.rows()), "q_f_dot", "shortening_across_element");
  // TODO(M08T7): the node's foreshortening f_k, its Jacobian J_k = df_k/dq_f (2 x n_f) and c_k, the
  //   part of d^2 f_k/dt^2 at q_f_ddot = 0, from the parent node's, README section 6,
  //   geometric_stiffening.hpp. Stuck? ./workbook hint M08T7
  unused(parent, H_e, t_e, q_f, q_f_dot);
  throw NotImplemented("M08T7 shortening_across_element");
}

void add_shortening_rows(const NodeShortening& s, const VecX& qd, MatX& L_k, Vec3& b_k) {
  Model::check_size(qd, static_cast<int>(L_k.cols()), "q_dot", "add_shortening_rows");
  // TODO(M08T8): add the terms of the foreshortening f_k (with J_k, c_k) to your rows L_k and b_k
  //   of M08T1 and M08T2: redo README section 1 with the node at x_bar_k + Phi_t,k q_f + f_k,
  //   README section 6, geometric_stiffening.hpp. Stuck? ./workbook hint M08T8
  unused(s, qd, L_k, b_k);
  throw NotImplemented("M08T8 add_shortening_rows");
}

}  // namespace fmbd
