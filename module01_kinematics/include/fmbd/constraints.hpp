#pragma once
// Assembly of the constraint equations of a whole model (given code, module 1).
//
//   C(q, t) = 0                       eq. (1), m rows
//   C_q = dC/dq                       m x n Jacobian, n = model.num_coordinates() (3 n_b if rigid)
//   C_t = dC/dt                       m rows (non-zero only for drivers)
//
// Each constraint's block (joints.hpp, drivers.hpp) is scattered into its rows and into the
// columns of its two bodies; ground columns are dropped. On a flexible body the block is
// evaluated on the node's marker and chained with its G (marker.hpp).

#include "fmbd/constraint_block.hpp"
#include "fmbd/marker.hpp"
#include "fmbd/model.hpp"

namespace fmbd {

/// C, C_q and C_t of the whole model at (q, t).
struct ConstraintEvaluation {
  VecX C;   ///< m
  MatX Cq;  ///< m x n
  VecX Ct;  ///< m
};

/// The block of one constraint at (q, t): dispatches on its type. Its Jacobian columns are
/// those of the markers' q (the body's own for rigid bodies).
ConstraintBlock evaluate_constraint(const Model& model, const Constraint& constraint, const VecX& q,
                                    double t);
/// The same on given markers.
ConstraintBlock evaluate_constraint(const Constraint& constraint, const ConstraintMarkers& markers, double t);
/// Cq(first_row.., offset..) += block G: a kernel block chained into the body's columns.
void add_jacobian_columns(MatX& Cq, int first_row, const Marker& marker, const RowBlock& block);

/// C, C_q and C_t of all constraints. Throws std::invalid_argument if q.size() != n.
ConstraintEvaluation evaluate_constraints(const Model& model, const VecX& q, double t);

VecX constraints(const Model& model, const VecX& q, double t);                 ///< C (m)
MatX constraint_jacobian(const Model& model, const VecX& q, double t);         ///< C_q (m x n)
VecX constraint_time_derivative(const Model& model, const VecX& q, double t);  ///< C_t (m)

}  // namespace fmbd
