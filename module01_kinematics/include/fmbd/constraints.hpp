#pragma once
// Assembly of the constraint equations of a whole model (module 1, task M01T6: assembly.cpp).
//
//   C(q, t) = 0                       eq. (1), m rows
//   C_q = dC/dq                       m x n Jacobian, n = model.num_coordinates() (3 n_b if rigid)
//   C_t = dC/dt                       m rows (non-zero only for drivers)
//
// Each constraint k owns the rows first_row .. first_row + rows - 1 (Constraint::first_row, ::rows)
// and each body the columns of its coordinates, from model.offset(body) (Marker::offset): a
// constraint's block (joints.hpp, drivers.hpp) is scattered into its rows and into the columns of
// its two bodies; the ground has no columns. A point on a node of a flexible body is evaluated on
// the node's marker and its block chained with the node's G (marker.hpp, module 7).

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
/// The same on given markers. Throws std::logic_error naming the constraint when the block's
/// sizes are not the constraint's rows (a kernel that did not start from ConstraintBlock::zero).
ConstraintBlock evaluate_constraint(const Constraint& constraint, const ConstraintMarkers& markers, double t);

/// M01T6: C, C_q and C_t of all constraints at (q, t), written into `out`, which the caller
/// provides with its sizes (m, m x n, m; constraint_storage()) and whatever entries: every entry is
/// overwritten (C_q's zeros too), so one `out` serves call after call. Throws
/// std::invalid_argument if q.size() != n or out's sizes are not these.
void evaluate_constraints(const Model& model, const VecX& q, double t, ConstraintEvaluation& out);
/// M01T6: Cq(first_row .., the columns of marker's body) += block: the 3 columns of a rigid body
/// from marker.offset, none for the ground. A marker on a node of a flexible body
/// (marker.on_node()) chains the block with the node's G over the body's 3 + n_f columns (module 7).
void add_jacobian_columns(MatX& Cq, int first_row, const Marker& marker, const RowBlock& block);

/// The precondition of evaluate_constraints, which checks it first: q has n entries and out the
/// sizes above. Throws std::invalid_argument naming what differs.
void check_constraint_storage(const Model& model, const VecX& q, const ConstraintEvaluation& out);
/// Storage for evaluate_constraints of `model`: C (m), C_q (m x n) and C_t (m), all zero.
ConstraintEvaluation constraint_storage(const Model& model);
/// C, C_q and C_t of all constraints in new storage. Throws std::invalid_argument if q.size() != n.
ConstraintEvaluation evaluate_constraints(const Model& model, const VecX& q, double t);

VecX constraints(const Model& model, const VecX& q, double t);                 ///< C (m)
MatX constraint_jacobian(const Model& model, const VecX& q, double t);         ///< C_q (m x n)
VecX constraint_time_derivative(const Model& model, const VecX& q, double t);  ///< C_t (m)

}  // namespace fmbd
