#pragma once
// Reaction forces and driver efforts from the Lagrange multipliers (module 3, task T5).
//
// Constraint c with rows r..r+k-1 of C and multipliers lambda_c exerts on its body i the
// generalised force Q_i = -(C_q,i)^T lambda_c = (F_x, F_y, M_centroid): a force F through the
// centroid plus a moment. Moved to the joint point P_i = R_i + A_i s_i, the same action is the
// force F at P_i plus the moment M_P = M_centroid - (A_i s_i) x F  (planar cross product
// a x b = a_x b_y - a_y b_x). Likewise for body j.

#include "fmbd/model.hpp"

namespace fmbd {

/// The reaction of one joint on one body, at that body's joint point.
struct Reaction {
  Vec2 force = Vec2::Zero();       ///< F in the global frame [N]
  Vec2 force_body = Vec2::Zero();  ///< the same F in the body frame, A^T F [N]
  double moment = 0.0;             ///< moment about the joint point [N m] (0 for a revolute)
};

/// Reactions of a joint on its body i and on its body j (ground side: zero).
struct JointReaction {
  Reaction on_i, on_j;
};

/// M03T5. Reaction of the joint `constraint` (index into model.constraints(); a revolute,
/// translational or fixed joint) at configuration q, from the full multiplier vector lambda (m).
/// Throws std::invalid_argument for a driver or a wrong index.
JointReaction joint_reaction(const Model& model, int constraint, const VecX& q, const VecX& lambda);

/// M03T5. Effort of the driver `constraint`: the generalised force that the driver applies
/// along the coordinate it drives, -lambda dC/d(driven quantity):
///   absolute angle: torque on its body;          relative angle: torque on body j;
///   point coordinate: force on the point along the axis;
///   distance: force pushing P_j away from P_i (-lambda |d|).
/// Its power is effort x (rate of the driven quantity). Throws std::invalid_argument for a joint.
double driver_effort(const Model& model, int constraint, const VecX& q, const VecX& lambda);

}  // namespace fmbd
