#pragma once
// A flexible body of the floating frame of reference formulation (modules 7 and 8, given code).
//
// Body j carries a floating frame (R, theta) at its undeformed centroid, with axes parallel to
// the axes of its FE model, and elastic coordinates q_f of a reduction basis Phi = [Phi_r Phi_f]
// (module 6). Its coordinates are
//
//   q_j = (R_x, R_y, theta, q_f),   size 3 + n_f,
//
// and the nodal displacements relative to the frame are u_bar = Phi_f q_f (frame j). Node k is at
//
//   r_k = R + A(theta) (x_bar_k + u_bar_k),    u_bar_k = Phi_t,k q_f,    psi_k = Phi_psi,k q_f,
//
// with x_bar_k its undeformed position in the frame and Phi_t,k (2 x n_f), Phi_psi,k (1 x n_f)
// the translational and rotational rows of node k in Phi_f.
//
// ModalBodyData is what every modal form of the body reads; FlexibleBodyData adds the beam FE
// model with its sparse (banded) matrices, which module 8's nodal form needs. (A body from an imported FE
// model has its own ImportedBodyData: extras/sparse.)

#include <functional>
#include <memory>
#include <stdexcept>

#include "fmbd/model.hpp"
#include "fmbd/reduction.hpp"

namespace fmbd {

/// The rows of one node in the elastic basis.
struct NodeModes {
  Vec2 x_bar = Vec2::Zero();  ///< undeformed position in the floating frame (from the centroid)
  MatX Phi_t;                 ///< 2 x n_f: translational rows (u_x, u_y) of the node
  MatX Phi_psi;               ///< 1 x n_f: rotational row (psi) of the node
};

/// The reduced description of a flexible body in its floating frame, computed once: everything
/// the modal forms of the body read (module 7's IntuitiveBody, the node markers of its joints,
/// M_bar, forces and energies). The rows of basis.Phi and Phi_f are the DOFs of the FE model the
/// body was reduced from (3k + d for a beam model).
struct ModalBodyData {
  ReducedBasis basis;         ///< Phi = [Phi_r Phi_f], num_rigid = 3
  MatX Phi_f;                 ///< n x n_f, the elastic columns of basis.Phi
  MatX M_ff, K_ff;            ///< Phi_f^T M_FE Phi_f and Phi_f^T K_FE Phi_f (n_f x n_f)
  MatX S_f;                   ///< 2 x n_f: first moment of the elastic shapes, T_xy^T M_FE Phi_f (0 if M-orthogonal)
  double mass = 0.0;          ///< m
  double inertia = 0.0;       ///< J about the centroid, undeformed
  std::vector<NodeModes> nodes;

  int num_modes() const { return static_cast<int>(Phi_f.cols()); }
};

/// A flexible body reduced from a beam FE model: its modal data and the FE model itself with its
/// matrices, from which module 8's nodal form computes M(q) = L^T M_FE L. The matrices are
/// sparse (banded): L^T M_FE L then costs O(N (3 + n_f)^2) instead of O(N^2 (3 + n_f)).
struct FlexibleBodyData : ModalBodyData {
  FeModel fe;                 ///< the FE model, nodes moved so that the centroid is the origin
  SparseFeMatrices matrices;  ///< M_FE, K_FE (3N x 3N)
};

/// Data of a body reduced by modal truncation on its free-free modes (num_modes elastic ones).
/// The FE model may sit anywhere; its nodes are moved to the centroid frame.
FlexibleBodyData flexible_body_data(const FeModel& fe, MassMatrixType mass_type, int num_modes);

/// Data of a body with a given basis for the FFRF (num_rigid = 3, for example ffrf_basis of a
/// Craig-Bampton basis). fe and basis belong together. Throws std::invalid_argument otherwise.
FlexibleBodyData flexible_body_data(const FeModel& fe, MassMatrixType mass_type, const ReducedBasis& basis);

/// Data of a body whose frame is clamped at `node`: its elastic shapes are the `num_modes` lowest
/// cantilever modes of that node (the fixed-interface modes of craig_bampton with the node's three
/// DOFs as interface), which leave the node's displacement and rotation zero, so the frame turns
/// and moves rigidly with the node. Its origin stays at the undeformed centroid, a fixed point of
/// the node's frame. The alternative, flexible_body_data(fe, type, num_modes), puts the frame at
/// the centroid with free-free modes, M-orthogonal to the rigid motions (module 8 README, section 5,
/// compares the two). Throws std::invalid_argument for a node outside the model.
FlexibleBodyData clamped_frame_body_data(const FeModel& fe, MassMatrixType mass_type, int node, int num_modes);

/// The intuitive form (module 7) stands on elastic shapes M-orthogonal to the rigid motions, such
/// as free-free modes: their first moment S_f is zero. In another basis an elastic coordinate moves
/// the centre of mass, the (R, q_f) block of the mass matrix is A(theta) S_f, and the constant M_bar
/// keeps it at theta = 0: wrong to first order, not only by the terms the course leaves out.
/// Thrown when an IntuitiveBody is made from such a basis.
class IntuitiveBasisError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// The largest |S_f| of the intuitive form: S_f's entries, each divided by its bound
/// sqrt(m (M_ff)_ii) (the cosine of the M-angle between shape i and a translation), at most this.
constexpr double kIntuitiveBasisTolerance = 1e-6;

/// The intuitive flexible body of module 7 (a DeformableBody for the Model): node kinematics from
/// tasks M07T1-T3, its mass matrix M_bar in the system's M (M07T4) and its gravity and elastic
/// forces in Q_a (M07T5, M07T6).
class IntuitiveBody : public DeformableBody {
 public:
  /// Throws IntuitiveBasisError if data's basis is not M-orthogonal to the rigid motions
  /// (kIntuitiveBasisTolerance), std::invalid_argument without data.
  explicit IntuitiveBody(std::shared_ptr<const ModalBodyData> data);

  const ModalBodyData& data() const { return *data_; }

  int num_modes() const override { return data_->num_modes(); }
  int num_nodes() const override { return static_cast<int>(data_->nodes.size()); }
  Vec2 node_position(int node) const override { return data_->nodes.at(node).x_bar; }
  double mass() const override { return data_->mass; }
  double inertia() const override { return data_->inertia; }
  NodeMarker node_marker(int node, const VecX& q, const VecX& qd) const override;
  /// Your node_pose, node_jacobian and node_convective_acceleration into `out` (no heap
  /// allocation once its G has the size).
  void write_node_marker(int node, const VecX& q, const VecX& qd, NodeMarker& out) const override;
  void add_node_columns(const NodeMarker& node, const RowBlock& B, int first_row, int at, MatX& Cq) const override;
  RowVector node_gamma_term(const NodeMarker& node, const RowBlock& B) const override;
  void add_node_force(const NodeMarker& node, const Vec3& Q, int at, VecX& Q_a) const override;
  void add_mass(const VecX& q, int at, MatX& M) const override;
  void add_forces(const VecX& q, const VecX& qd, const Vec2& g, int at, VecX& Q_a) const override;
  double kinetic_energy(const VecX& q, const VecX& qd) const override;
  double potential_energy(const VecX& q, const Vec2& g) const override;

 protected:
  /// For the full FFRF bodies of module 8 and the extras, which take any basis.
  struct AnyBasis {};
  IntuitiveBody(std::shared_ptr<const ModalBodyData> data, AnyBasis);
  void check_state(const VecX& q, const char* what, const char* where) const;
  std::shared_ptr<const ModalBodyData> data_;
};

/// Makes the DeformableBody of a formulation from the body's data: module 7's intuitive one
/// (make_intuitive_body) or module 8's full FFRF (make_ffrf_body).
/// make_intuitive_body throws IntuitiveBasisError for a basis that is not M-orthogonal.
using BodyFactory = std::function<std::shared_ptr<const DeformableBody>(std::shared_ptr<const FlexibleBodyData>)>;
std::shared_ptr<const DeformableBody> make_intuitive_body(std::shared_ptr<const FlexibleBodyData> data);

/// Checks that a body's coordinates at .. at + 3 + n_f lie inside the system's q and that M (its
/// rows) or Q_a has q's size: the precondition of the functions that add a body's terms to the
/// system's M and Q_a. Throws std::invalid_argument naming `where` otherwise.
void check_body_block(const ModalBodyData& data, const VecX& q, int at, Eigen::Index size, const char* where);

/// The undeformed global position of node k of a flexible body at frame coordinates (R, theta):
/// R + A(theta) x_bar_k.
Vec2 undeformed_node_position(const ModalBodyData& data, int node, const Vec3& frame);

/// The frame (R, theta) that puts the FE model's own coordinates (before the centroid shift) at
/// global position `origin` turned by `angle`: what to pass as q0 to Model::add_flexible_body.
Vec3 frame_for_placement(const FeModel& fe, MassMatrixType mass_type, const Vec2& origin, double angle);

}  // namespace fmbd
