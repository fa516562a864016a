#pragma once
// The equations of one joint or driver between body i and body j, evaluated at one instant:
// its rows of C (eq. 1), of the Jacobian C_q (split into the 3 columns of body i and the 3
// of body j) and of C_t = dC/dt. At most 3 rows, so the block lives on the stack.

#include <Eigen/Core>

namespace fmbd {

using RowVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;   ///< up to 3 rows
using RowBlock = Eigen::Matrix<double, Eigen::Dynamic, 3, 0, 3, 3>;    ///< up to 3 rows x 3

struct ConstraintBlock {
  RowVector C;    ///< C (rows)
  RowBlock Cq_i;  ///< dC/dq_i, rows x 3, columns (x_i, y_i, phi_i)
  RowBlock Cq_j;  ///< dC/dq_j, rows x 3 (ignored when body j is the ground)
  RowVector Ct;   ///< dC/dt (rows); zero for joints, -(time derivative of f) terms for drivers

  /// A block of `rows` equations, all entries zero.
  static ConstraintBlock zero(int rows) {
    ConstraintBlock b;
    b.C.setZero(rows);
    b.Cq_i.setZero(rows, 3);
    b.Cq_j.setZero(rows, 3);
    b.Ct.setZero(rows);
    return b;
  }
};

}  // namespace fmbd
