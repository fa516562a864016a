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
// implement this interface; modules 1 to 4 only call it: a flexible body enters the system's
// constraints through its node markers (node_marker, add_node_columns, node_gamma_term) and the
// system's M and Q_a through add_mass, add_forces and add_node_force.

#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "fmbd/constraint_block.hpp"
#include "fmbd/planar.hpp"

namespace fmbd {

/// Kinematics of one node of a flexible body at (q_j, q_j_dot).
struct NodeMarker {
  Vec3 pose = Vec3::Zero();        ///< p_k = (r_k, phi_k), global
  Vec3 velocity = Vec3::Zero();    ///< p_k_dot = G_k q_j_dot
  MatX G;                          ///< G_k = dp_k/dq_j, 3 x (3 + n_f)
  Vec3 convective = Vec3::Zero();  ///< c_k = G_k_dot q_j_dot
};

/// Storage for the node markers of one body, a set per thread, kept from call to call so that a
/// node's G keeps its heap memory (given code). Scratch: a copy of a body starts with none.
class NodeMarkerStore {
 public:
  NodeMarkerStore() = default;
  NodeMarkerStore(const NodeMarkerStore&) {}
  NodeMarkerStore& operator=(const NodeMarkerStore&) { return *this; }
  /// This thread's marker of node k (of num_nodes): the same object at every call.
  NodeMarker& slot(int node, int num_nodes) const;

 private:
  mutable std::mutex mutex_;
  mutable std::vector<std::pair<std::thread::id, std::vector<NodeMarker>>> per_thread_;
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
  /// The same into `out`, whose G keeps its memory when it has the size already (no heap
  /// allocation). By default node_marker()'s value; module 7's bodies write in place.
  virtual void write_node_marker(int node, const VecX& q, const VecX& qd, NodeMarker& out) const {
    out = node_marker(node, q, qd);
  }
  /// write_node_marker into storage the body keeps for node k in this thread: the marker that
  /// module 1's point_marker refers to. The reference stays valid while the body lives; its
  /// contents are those of the latest call for node k in this thread.
  const NodeMarker& kept_node_marker(int node, const VecX& q, const VecX& qd) const {
    NodeMarker& m = kept_.slot(node, num_nodes());
    write_node_marker(node, q, qd, m);
    return m;
  }

  /// The chain rule of node k's marker into the system's equations (module 7 writes it: no given
  /// code applies G_k or c_k). `node` is node_marker()'s result; the body's coordinates start at
  /// `at` in the system's q. add_node_columns adds a joint's or driver's block B (rows x 3) on the
  /// node's pose to C_q at the rows first_row .. and the body's 3 + n_f columns; node_gamma_term
  /// is the term that the node's convective acceleration adds to that constraint's gamma;
  /// add_node_force adds a force's kernel Q (3) on the node's pose to Q_a at the body's rows.
  /// Modules 1 to 3 call them from your assembly for a marker on a node (marker.hpp).
  virtual void add_node_columns(const NodeMarker& node, const RowBlock& B, int first_row, int at, MatX& Cq) const = 0;
  virtual RowVector node_gamma_term(const NodeMarker& node, const RowBlock& B) const = 0;
  virtual void add_node_force(const NodeMarker& node, const Vec3& Q, int at, VecX& Q_a) const = 0;

  /// The body's terms of the system's equations of motion (eq. (3) of module 3): they add into
  /// the system's mass matrix M (n x n) and applied forces Q_a (n) at the body's coordinates,
  /// rows (and columns) at .. at + 3 + n_f; q and q_dot are the system's (n). Module 3's given
  /// mass_matrix(model, q) and applied_forces call them for each flexible body; module 7's
  /// exercises implement them (M_bar in M, -K_bar q in Q_a), module 8's correct them (M(q) in M,
  /// Q_v added).
  virtual void add_mass(const VecX& q, int at, MatX& M) const = 0;
  /// Gravity g (global) on the body's distributed mass, its elastic forces and, in module 8, the
  /// quadratic velocity vector.
  virtual void add_forces(const VecX& q, const VecX& qd, const Vec2& g, int at, VecX& Q_a) const = 0;

  /// The body's own block of M at its coordinates q_j (3 + n_f): add_mass into a zero matrix.
  MatX mass_matrix(const VecX& q_j) const {
    MatX M = MatX::Zero(q_j.size(), q_j.size());
    add_mass(q_j, 0, M);
    return M;
  }
  /// The body's own forces at (q_j, q_j_dot): add_forces into a zero vector.
  VecX body_forces(const VecX& q_j, const VecX& qd_j, const Vec2& g) const {
    VecX Q = VecX::Zero(q_j.size());
    add_forces(q_j, qd_j, g, 0, Q);
    return Q;
  }
  /// Kinetic energy 1/2 q_dot^T M q_dot at (q_j, q_j_dot).
  virtual double kinetic_energy(const VecX& q, const VecX& qd) const = 0;
  /// Strain energy 1/2 q_f^T K_ff q_f plus the potential of gravity g.
  virtual double potential_energy(const VecX& q, const Vec2& g) const = 0;

 private:
  NodeMarkerStore kept_;
};

}  // namespace fmbd
