#pragma once
// Where a joint, driver or force element grips a body (given code, module 1).
//
// The kernels of modules 1 to 3 (joints.hpp, drivers.hpp, gamma.hpp, applied_forces.hpp) see a
// point at body-frame coordinates s_bar on a rigid body with coordinates q = (x, y, phi). A
// marker provides exactly that, plus the chain rule to the coordinates of the real body:
//
//   rigid body:     q, s_bar of the point,    G = I (3 x 3, implied), c = 0
//   flexible body:  q = pose of the FE node,  s_bar = 0,            G = dp/dq_body, c (convective)
//                   (deformable.hpp, from module 7's node_pose, node_jacobian and
//                   node_convective_acceleration); a body-level marker (angle drivers, torques) is
//                   the frame.
//   ground:         q = 0, s_bar = the point's global position, no columns.
//
// A kernel's Jacobian block, gamma and generalised force on a node's pose then reach the body's
// 3 + n_f coordinates by the chain rule with G and c: the body's own hooks do that
// (DeformableBody::add_node_columns, node_gamma_term, add_node_force, which module 7 writes),
// called from your assembly of modules 1 to 3.

#include "fmbd/constraint_block.hpp"
#include "fmbd/model.hpp"

namespace fmbd {

struct Marker {
  BodyId body = ground;
  /// Coordinates the kernel sees: a rigid body's pose (x, y, phi), an FE node's pose, or zero on
  /// the ground. Not where the point is: for a point on a rigid body it is the body frame's
  /// origin. The point's global position is point_position().
  Vec3 q = Vec3::Zero();
  Vec3 qd = Vec3::Zero();          ///< their rates, G q_body_dot
  Vec2 s_bar = Vec2::Zero();       ///< point coordinates the kernel sees
  int offset = 0;                  ///< first column of the body in q (unused for the ground)
  Vec3 convective = Vec3::Zero();  ///< G_dot q_body_dot
  int node = -1;                   ///< the FE node of a flexible body's point; -1 elsewhere
  const DeformableBody* deformable = nullptr;  ///< that body, whose chain rule a node's block takes
  /// A node's kinematics, with its chain rule G = dp/dq_body (3 x (3 + n_f)), kept by its body
  /// (DeformableBody::kept_node_marker): a marker holds no heap memory and copies cheaply. Null
  /// elsewhere: a marker on a rigid body or on a body's frame takes the body's first 3 columns
  /// (G = [I 0], implied), and the ground has no columns. It shows the latest marker of that node
  /// in this thread: a marker of the same node at another q replaces it.
  const NodeMarker* kinematics = nullptr;

  /// Whether the marker is a node of a flexible body (its G spans the body's 3 + n_f columns).
  bool on_node() const { return node >= 0; }
  /// The node's kinematics (pose, velocity, G, convective term) as its body's hooks take them.
  const NodeMarker& node_kinematics() const { return *kinematics; }
};

/// The marker of point P at (q, q_dot).
Marker point_marker(const Model& model, PointId P, const VecX& q, const VecX& qd);
/// Global position of point P at q: R + A(phi) s_bar on a rigid body, the node position on a
/// flexible body, s_bar on the ground (M01T1's point_position on the marker's pose). This, not
/// point_marker(...).q, is where a point is drawn.
Vec2 point_position(const Model& model, PointId P, const VecX& q);
/// The marker of a body's own frame (angle drivers, torques, rotational spring-dampers).
Marker body_marker(const Model& model, BodyId body, const VecX& q, const VecX& qd);

/// The two markers of a constraint: its points, or its bodies for angle drivers; the second is
/// the ground for one-body drivers.
struct ConstraintMarkers {
  Marker i, j;
};
ConstraintMarkers constraint_markers(const Model& model, const Constraint& constraint, const VecX& q,
                                     const VecX& qd);
/// The same at rest (zero rates), for C, C_q and C_t, which do not depend on q_dot.
ConstraintMarkers constraint_markers(const Model& model, const Constraint& constraint, const VecX& q);

/// The block of a marker on a node of a flexible body, handed to its body's chain rule
/// (DeformableBody::add_node_columns, module 7): what add_jacobian_columns does for such a marker.
void add_node_jacobian_columns(MatX& Cq, int first_row, const Marker& marker, const RowBlock& block);

/// A kernel's force on a marker on a node of a flexible body, handed to its body's chain rule
/// (DeformableBody::add_node_force, module 7): what module 3's add_generalised_force does for it.
void add_node_generalised_force(VecX& target, const Marker& marker, const Vec3& Q);

}  // namespace fmbd
