// Exercise file of module 1, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 1, task T6: the system's constraint equations C, their Jacobian C_q and C_t, assembled
// from the blocks of the joints and drivers.
#include "fmbd/constraints.hpp"
#include "fmbd/errors.hpp"

namespace fmbd {

void add_jacobian_columns(MatX& Cq, int first_row, const Marker& marker, const RowBlock& block) {
  if (marker.on_node()) {  // a node of a flexible body: its block chained with the node's G (module 7)
    add_node_jacobian_columns(Cq, first_row, marker, block);
    return;
  }
  // TODO(M01T6): add the block (rows x 3) of the rigid body `marker.body` to C_q at the rows
  //   first_row .. and at the body's 3 columns, which start at marker.offset (README section 4,
  //   constraints.hpp). The ground (marker.body.is_ground()) has no columns.
  //   Stuck? ./workbook hint M01T6
  unused(Cq, first_row, block);
  throw NotImplemented("M01T6 add_jacobian_columns");
}

void evaluate_constraints(const Model& model, const VecX& q, double t, ConstraintEvaluation& out) {
  check_constraint_storage(model, q, out);
  // TODO(M01T6): C, C_q and C_t of the whole model into out (README section 4, constraints.hpp):
  //   for each constraint c of model.constraints(), its markers (constraint_markers(model, c, q),
  //   at rest) and its block (evaluate_constraint(c, markers, t)); the block's rows go to c's rows
  //   c.first_row .. c.first_row + c.rows - 1, its C_q blocks to the columns of its two bodies
  //   (your add_jacobian_columns). out holds the entries of an earlier call: overwrite them all.
  unused(t);
  throw NotImplemented("M01T6 evaluate_constraints");
}

}  // namespace fmbd
