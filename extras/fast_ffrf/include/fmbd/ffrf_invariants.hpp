#pragma once
// The full FFRF body in its fast form: inertia invariants (given code, module 8).
//
// The nodal form of ffrf.hpp evaluates M(q) = L^T M_FE L and the forces with products over all
// 3N nodal DOFs at every call: O(N^2 n_f) flops with the dense M_FE. Everything in L and in the
// acceleration bias b that depends on the state is a frame rotation, theta_dot or an affine
// function of q_f, so the products with M_FE can be taken once, when the body is made. What is
// left per call works on n_f-sized quantities only: O(n_f^2) flops, independent of the mesh.
//
// Notation (flexible_body.hpp, ffrf.hpp): n = 3N nodal DOFs, M = M_FE (n x n, any symmetric
// matrix: lumped or consistent, psi rows included), Phi = Phi_f (n x n_f, the rows Phi_t,k and
// Phi_psi,k of every node), I~ = [[0, -1], [1, 0]], A = A(theta), w = theta_dot. Stacked over the
// nodes in the DOF order of the FE model (two translations and psi per node):
//
//   T   (n x 2)    node k: [I_2; 0 0]                the translation selector
//   X0  (n)        node k: (x_bar_k, 0)              the undeformed positions
//   X1  (n x n_f)  node k: [Phi_t,k; 0]              Phi with its psi rows zeroed
//   c0  (n)        node k: (I~ x_bar_k, 1)           the rotation field of the undeformed body
//   C1  (n x n_f)  node k: [I~ Phi_t,k; 0]           its change with q_f
//
// Then the node map and the bias of ffrf.hpp are
//
//   L = [ T A^T ,  c0 + C1 q_f ,  Phi ],      b = -w^2 (X0 + X1 q_f) + 2 w C1 q_f_dot.
//
// The invariants, each computed once with M:
//
//   M_tt = T^T M T    (2 x 2)       S_t0 = T^T M c0   (2)        S_t1 = T^T M C1  (2 x n_f)
//   S_f  = T^T M Phi  (2 x n_f)     U_0  = T^T M X0   (2)        U_1  = T^T M X1  (2 x n_f)
//   J_0  = c0^T M c0  (scalar)      j_1  = C1^T M c0  (n_f)      J_2  = C1^T M C1 (n_f x n_f)
//   p_0  = Phi^T M c0 (n_f)         P_1  = Phi^T M C1 (n_f x n_f)
//   M_ff = Phi^T M Phi (n_f x n_f)  e_0  = Phi^T M X0 (n_f)      E_1  = Phi^T M X1 (n_f x n_f)
//   h_0  = c0^T M X0  (scalar)      h_1  = X1^T M c0 + C1^T M X0 (n_f)    H_1 = C1^T M X1 (n_f x n_f)
//
// and K_ff. With them, for q = (R, theta, q_f) and q_dot = (v, w, q_f_dot):
//
//   mass matrix M(q) = L^T M L (symmetric; the lower blocks are the transposes):
//     M_RR     = A M_tt A^T                                  (m I_2 when M_tt = m I_2)
//     M_Rtheta = A (S_t0 + S_t1 q_f)
//     M_Rf     = A S_f
//     M_thth   = J_0 + 2 j_1^T q_f + q_f^T J_2 q_f
//     M_ftheta = p_0 + P_1 q_f
//     M_ff     = M_ff                                        (constant)
//
//   L^T M b, whose negative is the quadratic velocity vector Q_v:
//     R:      A ( -w^2 (U_0 + U_1 q_f) + 2 w S_t1 q_f_dot )
//     theta:  -w^2 (h_0 + h_1^T q_f + q_f^T H_1 q_f) + 2 w (j_1 + J_2 q_f)^T q_f_dot
//     f:      -w^2 (e_0 + E_1 q_f) + 2 w P_1 q_f_dot
//
//   gravity as module 7's flexible_gravity_force, minus the gradient of -g^T (m R + A S_f q_f),
//   with gamma = A^T g_glob (for a lumped M_FE it equals L^T M T gamma):
//     R: m g (the body's mass),   theta: gamma^T I~ S_f q_f,   f: S_f^T gamma
//
//   body forces  Q_v + gravity + (0, 0, 0, -K_ff q_f)   (ffrf_body_forces, whose -K_bar q has
//                rigid rows that are zero to round-off),
//   kinetic energy 1/2 q_dot^T M(q) q_dot from the blocks above with v_j = A^T v:
//     v_j^T M_tt v_j + 2 w v_j^T (S_t0 + S_t1 q_f) + 2 v_j^T S_f q_f_dot + w^2 M_thth
//       + 2 w (p_0 + P_1 q_f)^T q_f_dot + q_f_dot^T M_ff q_f_dot,   halved.
//
// These are identities, not approximations: the fast form equals the nodal one to round-off for
// any basis (M-orthogonal or not; for an M-orthogonal basis S_f = 0 and M_ff = I) and any
// symmetric M_FE.
//
// Cost per call (multiply-adds counted as 2 flops): the mass matrix about 4 n_f^2 (P_1 q_f and
// q_f^T J_2 q_f, plus copying M_ff), Q_v about 8 n_f^2, the body forces about 10 n_f^2 (with
// K_ff q_f), the kinetic energy about 6 n_f^2; everything else is O(n_f). The nodal form needs
// about 2 n^2 (3 + n_f) for M(q) and 4 n^2 for the body forces. Making the invariants costs
// about 2 n^2 (2 n_f + 3) + 10 n n_f^2 flops once, and they take about 6 n_f^2 numbers.
//
// Sparse M_FE in any DOF order: nothing above needs the nodal order (two translations and psi per
// node) or a dense M. The fields are vectors over the DOFs of M; node k's entries go to the rows
// that its DOF numbers (NodeDofNumbers, matrix_market.hpp) name, and a DOF that is not in the
// matrices (number -1) has no row: its field entries drop out, as a row of zeros in M would make
// them (the node's rows Phi_t,k / Phi_psi,k must then be zero there: it moves with the frame). The
// second constructor takes such an M as a SparseMat: the products M T, M Phi, M C1 and M c0 are
// sparse times dense, about 2 nnz(M) (2 n_f + 3) flops, and the rest 10 n n_f^2 as before, so an
// imported model of 10^5 DOFs or more gives its invariants without a dense n x n matrix
// (sparse_body.hpp makes the whole body from a SparseFeModel). The fields take about 5 n n_f
// numbers while they are made, nothing afterwards.
//
// Storage and threads: the evaluations into caller-provided storage (mass_matrix(q, out), ...)
// allocate nothing once `out` has the right size (they resize it otherwise). Intermediate values
// are fixed-size (2-vectors, 2 x 2) or are written straight into `out`, and the quadratic forms
// are taken column by column, so no workspace is needed: an FfrfInvariants is immutable after
// construction and may be shared between threads. ModalFfrfBody's add_mass and add_forces, which
// add M(q) and the body forces to the system's M and Q_a, evaluate them first into storage of
// their own: a matrix and a vector per thread and per body size (3 + n_f), sized at the first call
// and kept, so that a step of simulate allocates nothing once it has run (test
// extras.mechanisms.step_allocates_nothing). The sums are those of the value forms added, to the bit.

#include <memory>
#include <vector>

#include "fmbd/ffrf.hpp"
#include "fmbd/matrix_market.hpp"

namespace fmbd {

/// The constant inertia invariants of one reduced flexible body, and M(q), Q_v, the body forces
/// and the kinetic energy of the full FFRF evaluated from them (see above).
class FfrfInvariants {
 public:
  using Vec2X = Eigen::Matrix<double, 2, Eigen::Dynamic>;
  using ConstVec = Eigen::Ref<const VecX>;

  /// Computes the invariants from the body's FE mass matrix, K_ff and the rows of its nodes
  /// (x_bar_k, Phi_t,k, Phi_psi,k), exactly the data the nodal form uses. Throws
  /// std::invalid_argument if the sizes of the data do not match.
  explicit FfrfInvariants(const FlexibleBodyData& data);

  /// The same from a sparse M_FE (n x n, symmetric) whose rows are the DOFs named by `dofs`
  /// (dofs[k]: the rows of u_x, u_y, psi of node k, -1 for a DOF not in M; section "Sparse M_FE"
  /// above); K_ff and the rows of the nodes come from `data`.
  /// Throws std::invalid_argument, naming the node or row, if the sizes do not match, if dofs has
  /// not one entry per node of data, if a DOF number is outside -1 .. n-1 or used twice, if a row
  /// of M belongs to no node, or if a node has a non-zero elastic row for a DOF that is not in M.
  FfrfInvariants(const SparseMat& M, const std::vector<NodeDofNumbers>& dofs, const ModalBodyData& data);

  int num_modes() const { return n_f_; }
  int size() const { return 3 + n_f_; }  ///< of q, q_dot and the results

  /// M(q) into `out` ((3 + n_f) x (3 + n_f), resized if needed), exactly symmetric.
  void mass_matrix(const ConstVec& q, MatX& out) const;
  /// Q_v = -L^T M_FE b into `out` (3 + n_f, resized if needed).
  void quadratic_velocity_vector(const ConstVec& q, const ConstVec& qd, VecX& out) const;
  /// Q_v + gravity (g global) + elastic forces into `out` (3 + n_f, resized if needed): the same
  /// as ffrf_body_forces.
  void body_forces(const ConstVec& q, const ConstVec& qd, const Vec2& g, VecX& out) const;
  /// 1/2 q_dot^T M(q) q_dot, without forming M(q).
  double kinetic_energy(const ConstVec& q, const ConstVec& qd) const;

  /// Value-returning forms of the above (they allocate their result).
  MatX mass_matrix(const ConstVec& q) const;
  VecX quadratic_velocity_vector(const ConstVec& q, const ConstVec& qd) const;
  VecX body_forces(const ConstVec& q, const ConstVec& qd, const Vec2& g) const;

  /// The invariants, named as in the table above.
  const Mat2& M_tt() const { return M_tt_; }
  const Vec2& S_t0() const { return S_t0_; }
  const Vec2X& S_t1() const { return S_t1_; }
  const Vec2X& S_f() const { return S_f_; }
  const Vec2& U_0() const { return U_0_; }
  const Vec2X& U_1() const { return U_1_; }
  double J_0() const { return J_0_; }
  const VecX& j_1() const { return j_1_; }
  const MatX& J_2() const { return J_2_; }
  const VecX& p_0() const { return p_0_; }
  const MatX& P_1() const { return P_1_; }
  const MatX& M_ff() const { return M_ff_; }
  const VecX& e_0() const { return e_0_; }
  const MatX& E_1() const { return E_1_; }
  double h_0() const { return h_0_; }
  const VecX& h_1() const { return h_1_; }
  const MatX& H_1() const { return H_1_; }
  const MatX& K_ff() const { return K_ff_; }

 private:
  void check(const ConstVec& v, const char* what, const char* where) const;
  // The fields of the header from data.nodes placed in the rows `dofs`, and their products with M
  // (MatX or SparseMat; defined and instantiated in ffrf_invariants.cpp only).
  template <typename Matrix>
  void build(const Matrix& M, const std::vector<NodeDofNumbers>& dofs, const ModalBodyData& data);

  int n_f_ = 0;
  Mat2 M_tt_ = Mat2::Zero();
  Vec2 S_t0_ = Vec2::Zero(), U_0_ = Vec2::Zero();
  Vec2X S_t1_, S_f_, U_1_;
  double J_0_ = 0.0, h_0_ = 0.0, mass_ = 0.0;
  VecX j_1_, p_0_, e_0_, h_1_;
  MatX J_2_, P_1_, M_ff_, E_1_, H_1_, K_ff_;
};

/// The full FFRF body for the Model in the fast form: the same node kinematics, mass matrix,
/// forces and energies as FfrfBody, evaluated from the invariants. Use it to simulate; FfrfBody
/// is the form that reads like the theory (and the exercises). add_mass and add_forces make no heap
/// allocation after their first call in a thread (section "Storage and threads" above).
class ModalFfrfBody : public IntuitiveBody {
 public:
  explicit ModalFfrfBody(std::shared_ptr<const FlexibleBodyData> data);
  /// The body of data whose invariants come from a sparse M_FE with the DOF numbers of its nodes
  /// (the second FfrfInvariants constructor): how make_sparse_modal_ffrf_body (extras/sparse)
  /// makes a body of an imported model. M and dofs must be those that data was made from.
  ModalFfrfBody(std::shared_ptr<const ModalBodyData> data, const SparseMat& M,
                const std::vector<NodeDofNumbers>& dofs);

  const FfrfInvariants& invariants() const { return invariants_; }

  void add_mass(const VecX& q, int at, MatX& M) const override;
  void add_forces(const VecX& q, const VecX& qd, const Vec2& g, int at, VecX& Q_a) const override;
  double kinetic_energy(const VecX& q, const VecX& qd) const override;

 private:
  FfrfInvariants invariants_;
};

/// BodyFactory of the fast full FFRF (flexible_examples.hpp). For an imported model (SparseFeModel)
/// see make_sparse_modal_ffrf_body in sparse_body.hpp (extras/sparse).
std::shared_ptr<const DeformableBody> make_modal_ffrf_body(std::shared_ptr<const FlexibleBodyData> data);

}  // namespace fmbd
