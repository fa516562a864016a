#pragma once
// The interface of a flexible body as the rigid-body code of modules 1 to 4 sees it (given code).
//
// A flexible body j has a floating frame (R, theta) and elastic coordinates q_f: its coordinates
// are q_j = (R_x, R_y, theta, q_f), size 3 + n_f. Joints, drivers and force elements attach to
// its FE nodes. Each node k behaves, at one instant, like a small rigid marker with the pose
//
//   p_k = (r_k, phi_k),   r_k = R + A(theta) (x_bar_k + u_bar_k),   phi_k = theta + psi_k,
//
// with the elastic displacement u_bar_k and section rotation psi_k of the node (frame j). The
// joint kernels of modules 1 and 2 are evaluated on that marker (a point at s_bar = 0 of a
// "body" at p_k) and chained with
//
//   G_k = dp_k/dq_j  (3 x (3 + n_f)),     p_k_ddot = G_k q_j_ddot + c_k,   c_k = G_k_dot q_j_dot.
//
// Modules 7 (the intuitive form) and 8 (the full floating frame of reference formulation)
// implement this interface; module 1 only calls it.

#include "fmbd/planar.hpp"

namespace fmbd {

/// Kinematics of one node of a flexible body at (q_j, q_j_dot).
struct NodeMarker {
  Vec3 pose = Vec3::Zero();        ///< p_k = (r_k, phi_k), global
  Vec3 velocity = Vec3::Zero();    ///< p_k_dot = G_k q_j_dot
  MatX G;                          ///< G_k = dp_k/dq_j, 3 x (3 + n_f)
  Vec3 convective = Vec3::Zero();  ///< c_k = G_k_dot q_j_dot
};

class DeformableBody {
 public:
  virtual ~DeformableBody() = default;

  virtual int num_modes() const = 0;                 ///< n_f
  virtual int num_nodes() const = 0;                 ///< FE nodes that joints may attach to
  virtual Vec2 node_position(int node) const = 0;    ///< x_bar_k: undeformed, in the floating frame
  virtual double mass() const = 0;                   ///< m
  virtual double inertia() const = 0;                ///< J of the undeformed body about its centroid

  /// The marker of node k at (q_j, q_j_dot) (both of size 3 + n_f).
  virtual NodeMarker node_marker(int node, const VecX& q, const VecX& qd) const = 0;

  /// Constant mass matrix of the body, (3 + n_f)^2: the intuitive M_bar. It is the metric of
  /// coordinate projection and the mass matrix of mass_matrix(model) without q.
  virtual MatX reference_mass_matrix() const = 0;
  /// Mass matrix at q_j: M_bar in module 7, M(q) in module 8.
  virtual MatX mass_matrix(const VecX& q) const = 0;
  /// The body's own generalised forces at (q_j, q_j_dot) under gravity g (global): gravity on its
  /// distributed mass, the elastic force -K_ff q_f, and in module 8 the quadratic velocity vector.
  virtual VecX body_forces(const VecX& q, const VecX& qd, const Vec2& g) const = 0;
  /// Kinetic energy 1/2 q_dot^T M q_dot at (q_j, q_j_dot).
  virtual double kinetic_energy(const VecX& q, const VecX& qd) const = 0;
  /// Strain energy 1/2 q_f^T K_ff q_f plus the potential of gravity g.
  virtual double potential_energy(const VecX& q, const Vec2& g) const = 0;
};

}  // namespace fmbd
