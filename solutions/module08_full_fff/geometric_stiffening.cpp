// Module 8, tasks T7 and T8: geometric stiffening by the foreshortening of the beam axis.
#include "fmbd/errors.hpp"
#include "fmbd/geometric_stiffening.hpp"

namespace fmbd {

NodeShortening shortening_across_element(const NodeShortening& parent, const MatX& H_e, const Vec2& t_e,
                                         const VecX& q_f, const VecX& q_f_dot) {
  Model::check_size(q_f, static_cast<int>(H_e.rows()), "q_f", "shortening_across_element");
  Model::check_size(q_f_dot, static_cast<int>(H_e.rows()), "q_f_dot", "shortening_across_element");
  // TASK(M08T7): the node's foreshortening f_k, its Jacobian J_k = df_k/dq_f (2 x n_f) and c_k, the
  //   part of d^2 f_k/dt^2 at q_f_ddot = 0, from the parent node's, README section 6,
  //   geometric_stiffening.hpp. Stuck? ./workbook hint M08T7
  // BEGIN SOLUTION
  const VecX Hq = H_e * q_f;
  NodeShortening s;
  s.f = parent.f - 0.5 * q_f.dot(Hq) * t_e;
  s.J = parent.J - t_e * Hq.transpose();
  s.c = parent.c - q_f_dot.dot(H_e * q_f_dot) * t_e;
  return s;
  // END SOLUTION
  // STUB: unused(parent, H_e, t_e, q_f, q_f_dot);
  // STUB: throw NotImplemented("M08T7 shortening_across_element");
}

void add_shortening_rows(const NodeShortening& s, const VecX& qd, MatX& L_k, Vec3& b_k) {
  Model::check_size(qd, static_cast<int>(L_k.cols()), "q_dot", "add_shortening_rows");
  // TASK(M08T8): add the terms of the foreshortening f_k (with J_k, c_k) to your rows L_k and b_k
  //   of M08T1 and M08T2: redo README section 1 with the node at x_bar_k + Phi_t,k q_f + f_k,
  //   README section 6, geometric_stiffening.hpp. Stuck? ./workbook hint M08T8
  // BEGIN SOLUTION
  const Eigen::Index n_f = L_k.cols() - 3;
  const double w = qd(2);
  L_k.block<2, 1>(0, 2) += I_tilde() * s.f;
  L_k.block(0, 3, 2, n_f) += s.J;
  b_k.head<2>() += -w * w * s.f + 2 * w * I_tilde() * (s.J * qd.tail(n_f)) + s.c;
  // END SOLUTION
  // STUB: unused(s, qd, L_k, b_k);
  // STUB: throw NotImplemented("M08T8 add_shortening_rows");
}

}  // namespace fmbd
