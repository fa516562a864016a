#pragma once
// Geometric stiffening of the full FFRF body by the foreshortening of its beam axis (module 8,
// tasks T7 and T8; README section 6 derives the structure, the hints the entries).
//
// The body of tasks T1 to T5 is linear in q_f: node k sits at x_bar_k + Phi_t,k q_f in the body
// frame j. When the beam bends, a linear basis keeps the length of its projection on the axis, so
// the axis stretches by 1/2 int v'^2 ds, which costs no strain energy in the linear model: a
// spinning beam can bend outwards for free, and above a threshold it runs away (README section
// 5). A real beam does not stretch; its points move inwards by the foreshortening, and the
// centrifugal force does work against that motion. That work is the geometric stiffness of the
// centrifugal tension.
//
// The model keeps the axis length to second order (the "foreshortening" or "axial shortening"
// kinematics of Kane, Ryan and Banerjee 1987 and of Sharf 1996), for an inextensible axis and any
// FE beam model whose elements form a tree. Element e of length l_e, with the unit tangent t_e
// (frame j, pointing away from the anchor node) shortens its chord by
//
//   delta_e(q_f) = 1/2 int_0^l_e v'^2 ds = 1/2 q_f^T H_e q_f,
//   H_e = (T_e Phi_f)^T G(l_e) (T_e Phi_f)      (n_f x n_f, symmetric positive semi-definite),
//
// with v the transverse displacement of the element (cubic Hermite in its DOFs (v_a, psi_a, v_b,
// psi_b) = T_e Phi_f q_f) and G(l) = int N'^T N' ds the element's geometric stiffness matrix per
// unit axial force (hermite_slope_matrix). Node k then sits at
//
//   p_k(q_f) = x_bar_k + Phi_t,k q_f + f_k(q_f),   f_k = f_parent - delta_e(q_f) t_e,
//
// where e is the element between node k and its parent (the next node towards the anchor), and
// f = 0 at the anchor. Tasks: M08T7 the node's foreshortening f_k with its derivatives (J_k, c_k
// below) from its parent's; M08T8 the terms they add to your L_k and b_k of M08T1 and M08T2.
// M(q) = L^T M_FE L and Q_v = -L^T M_FE b stay as in section 2, with the stiffened L and b. Gravity
// is the nodal load L^T M_FE g^j (g^j = (A^T g, 0) at every node), which now also works on the
// foreshortening; potential_energy() counts that work, exact for lumped mass (FfrfBody uses module
// 7's flexible_gravity_force instead, the exact gradient of its potential for any mass matrix,
// README section 2; with lumped mass the two agree). The strain
// energy stays 1/2 q_f^T K_ff q_f: the foreshortening is the axial motion that leaves the axis
// unstretched, so it adds no strain.
//
// Where the stiffening comes from: spinning at theta_dot = Omega about the anchor (the hub) with
// the beam along its radial line, the centrifugal terms give the elastic coordinates the extra
// stiffness K_g = sum_e N_e H_e, N_e = Omega^2 sum_{k beyond e} m_k r_k (lumped masses m_k at
// radius r_k): the classical geometric stiffness of the centrifugal tension N_e of each element.
// The tension is never computed: it is the force that keeps the axis from stretching, carried by
// the inertia of the foreshortening motion. So a basis of bending modes alone is enough.
//
// Energy. The kinematics p_k(q) are exact functions of q, so with a lumped mass matrix the
// equations are Lagrange's for T = 1/2 sum m_k |r_k_dot|^2 + rotary terms and V = 1/2 q_f^T K_ff
// q_f + gravity: a free motion conserves T + V to the integrator's tolerance.
//
// Limits. Second order in the slopes (1/2 int v'^2, not the exact int (1 - cos)); rotations psi_k
// stay linear; the axis is inextensible (no axial vibration, no centrifugal stretch). The FE model
// must be a tree of elements (a beam or a branched frame, no closed loop).

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "fmbd/ffrf.hpp"

namespace fmbd {

using Mat4 = Eigen::Matrix<double, 4, 4>;

/// G(l) = int_0^l N'(s)^T N'(s) ds (4 x 4, symmetric) for the cubic Hermite shape functions in
/// the element DOFs (v_a, psi_a, v_b, psi_b) of an element of length l: int v'^2 ds = d^T G d,
/// the element's geometric stiffness matrix per unit axial force (given code). Throws ModelError
/// unless l > 0 and finite.
Mat4 hermite_slope_matrix(double length);

/// The foreshortening of a body reduced from a beam FE model (header comment): per element its
/// tangent t_e and H_e, per node the element that leads to it from the anchor.
struct Foreshortening {
  int anchor = 0;                   ///< the node whose foreshortening is zero
  std::vector<Vec2> tangent;        ///< t_e per element, frame j, unit, pointing away from the anchor
  std::vector<MatX> H;              ///< H_e per element (n_f x n_f): chord shortening 1/2 q_f^T H_e q_f
  std::vector<int> parent_element;  ///< per node: the element between it and its parent, -1 at the anchor
  std::vector<int> parent_node;     ///< per node: the next node towards the anchor, -1 at the anchor
  std::vector<int> order;           ///< the nodes in breadth-first order from the anchor
};

/// Builds the foreshortening of `data` (its FE model data.fe and basis data.Phi_f) with its
/// anchor at node `anchor` (given code). Throws ModelError if the anchor is not a node of the
/// model, or if the elements do not form a tree that reaches every node.
Foreshortening foreshortening(const FlexibleBodyData& data, int anchor);

/// The foreshortening of one node at (q_f, q_f_dot), frame j: f = f_k (2), J = J_k = df_k/dq_f
/// (2 x n_f) and c = c_k = J_k_dot q_f_dot (2), the part of the second time derivative of f_k that
/// remains at q_f_ddot = 0.
struct NodeShortening {
  Vec2 f = Vec2::Zero();
  MatX J;
  Vec2 c = Vec2::Zero();
};

/// M08T7. The foreshortening of node k from that of its parent node across element e (header
/// comment): f_k = f_parent - 1/2 (q_f^T H_e q_f) t_e, its Jacobian J_k and its c_k. H_e is
/// symmetric (n_f x n_f), t_e a unit vector; parent.J has n_f columns.
NodeShortening shortening_across_element(const NodeShortening& parent, const MatX& H_e, const Vec2& t_e,
                                         const VecX& q_f, const VecX& q_f_dot);

/// f_k, J_k and c_k of every node, in node order (given code): shortening_across_element along
/// the tree from the anchor, whose own are zero. q_f and q_f_dot have size n_f (ModelError
/// otherwise).
std::vector<NodeShortening> node_shortening(const Foreshortening& fs, const VecX& q_f, const VecX& q_f_dot);

/// M08T8. Adds the terms of node k's foreshortening s (at the body's q_f, q_f_dot) to its rows L_k
/// (3 x (3 + n_f)) and b_k (3) of M08T1 and M08T2: the absolute acceleration of the node at
/// p_k = x_bar_k + Phi_t,k q_f + f_k in frame j is then L_k q_ddot + b_k (README section 6).
/// qd is the body's q_dot (3 + n_f): theta_dot is qd(2), q_f_dot its tail.
void add_shortening_rows(const NodeShortening& s, const VecX& qd, MatX& L_k, Vec3& b_k);

/// The full FFRF body of tasks T1 to T5 with the foreshortening kinematics (given code): node
/// markers, mass matrix, body forces and energies all use p_k(q_f), through your T1, T2, T7 and
/// T8. Everything else (sizes, nodes) is FfrfBody's.
class StiffenedFfrfBody : public FfrfBody {
 public:
  /// Throws ModelError as foreshortening() does, and FfrfBody's std::invalid_argument.
  explicit StiffenedFfrfBody(std::shared_ptr<const FlexibleBodyData> data, int anchor = 0);

  const Foreshortening& shortening() const { return fs_; }

  /// L (3N x (3 + n_f)) and b (3N) of u_ddot^{j,o} = L q_ddot + b at the body's (q_j, q_j_dot):
  /// node_acceleration_map and node_acceleration_bias of every node with add_shortening_rows,
  /// stacked in the DOF order of the FE model.
  void acceleration_terms(const VecX& q, const VecX& qd, MatX& L, VecX& b) const;

  /// The marker of node k: G_k = diag(A, 1) L_k and c_k = diag(A, 1) b_k, the pose at p_k.
  NodeMarker node_marker(int node, const VecX& q, const VecX& qd) const override;
  /// node_marker's value into `out` (not module 7's node kinematics: the stiffened ones).
  void write_node_marker(int node, const VecX& q, const VecX& qd, NodeMarker& out) const override {
    out = node_marker(node, q, qd);
  }
  /// M(q) = L^T M_FE L with the stiffened L, at the body's rows and columns of the system's M.
  void add_mass(const VecX& q, int at, MatX& M) const override;
  /// Q_v + gravity L^T M_FE g^j - (0, 0, 0, K_ff q_f), at the body's rows of the system's Q_a.
  void add_forces(const VecX& q, const VecX& qd, const Vec2& g, int at, VecX& Q_a) const override;
  double kinetic_energy(const VecX& q, const VecX& qd) const override;
  /// 1/2 q_f^T K_ff q_f plus gravity: module 7's potential with the work of the nodal gravity
  /// forces (M_FE g^j) on the foreshortening added; exact for lumped mass.
  double potential_energy(const VecX& q, const Vec2& g) const override;

 private:
  MatX own_mass(const VecX& q) const;
  VecX own_forces(const VecX& q, const VecX& qd, const Vec2& g) const;
  std::shared_ptr<const FlexibleBodyData> fe_;
  Foreshortening fs_;
};

/// BodyFactory of the stiffened body with its anchor at node 0 (the root of the example beams):
/// pass it to spin_up_beam and the other builders of flexible_examples.hpp.
std::shared_ptr<const DeformableBody> make_stiffened_ffrf_body(std::shared_ptr<const FlexibleBodyData> data);

}  // namespace fmbd
