#pragma once
// Assembly of the constraint equations of a whole model (given code, module 1).
//
//   C(q, t) = 0                       eq. (1), m rows
//   C_q = dC/dq                       m x n Jacobian, n = 3 n_b
//   C_t = dC/dt                       m rows (non-zero only for drivers)
//
// Each constraint's block (joints.hpp, drivers.hpp) is scattered into its rows and into the
// columns of its two bodies; ground columns are dropped.

#include "fmbd/constraint_block.hpp"
#include "fmbd/model.hpp"

namespace fmbd {

/// C, C_q and C_t of the whole model at (q, t).
struct ConstraintEvaluation {
  VecX C;   ///< m
  MatX Cq;  ///< m x n
  VecX Ct;  ///< m
};

/// The block of one constraint at (q, t): dispatches on its type.
ConstraintBlock evaluate_constraint(const Model& model, const Constraint& constraint, const VecX& q,
                                    double t);

/// C, C_q and C_t of all constraints. Throws std::invalid_argument if q.size() != 3 n_b.
ConstraintEvaluation evaluate_constraints(const Model& model, const VecX& q, double t);

VecX constraints(const Model& model, const VecX& q, double t);                 ///< C (m)
MatX constraint_jacobian(const Model& model, const VecX& q, double t);         ///< C_q (m x n)
VecX constraint_time_derivative(const Model& model, const VecX& q, double t);  ///< C_t (m)

}  // namespace fmbd
