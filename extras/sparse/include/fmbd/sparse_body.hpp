#pragma once
// A flexible body from an imported FE model (extras/sparse; it builds on the fast FFRF body of
// extras/fast_ffrf).
//
// An FE package exports sparse M and K with a node table (SparseFeModel, matrix_market.hpp);
// sparse_craig_bampton (module 6) reduces them. This header makes the full FFRF body of module 8
// in its fast form (ModalFfrfBody) from the two, without a dense n x n matrix anywhere:
//
//   const SparseFeModel model = load_sparse_fe_model("mass.mtx", "stiffness.mtx", "nodes.txt");
//   const ReducedBasis cb = sparse_craig_bampton(model.K, model.M, interface_dofs, 10);
//   const auto body = make_sparse_modal_ffrf_body(model, sparse_ffrf_basis(model, cb));
//   const BodyId rod = m.add_flexible_body("rod", body, frame_for_placement(model, Vec2::Zero(), 0.0));
//   m.add_node_point(rod, 7, "hinge");        // node 7 of the node table
//
// The steps are those of the dense route for a beam FeModel, flexible_body_data(fe, mass_type,
// basis) of module 7 with rigid_body_modes and ffrf_basis of module 6, with every product with M
// or K taken as sparse times dense (M Phi, then Phi^T (M Phi)), and with the DOF numbers of the
// node table in place of 3k + d:
//
//   rigid-body modes   t_x, t_y, r_o over the rows the table names (u_x: (1, 0, -y_k), u_y:
//                      (0, 1, x_k), psi: (0, 0, 1)); m = t_x^T M t_x, the centroid c from the
//                      first moments, J about c (as rigid_body_modes, task M06T1);
//   FFRF basis         any basis with its rigid content removed, M-orthonormalised and
//                      diagonalised on K (as ffrf_basis, task M06T4);
//   body data          ImportedBodyData: the nodes moved by -c; the rigid columns of the basis replaced by the
//                      rigid-body modes about c; M_bar, K_bar, M_ff, K_ff, S_f; and the rows
//                      (Phi_t,k, Phi_psi,k) of each node (as flexible_body_data, module 7);
//   invariants         FfrfInvariants from the sparse M and the DOF numbers (ffrf_invariants.hpp).
//
// Given the same basis (rows in the same DOF order), the body equals the dense route's
// ModalFfrfBody and FfrfBody to round-off (project test project.sparse_body).
//
// DOFs that are not in the matrices (node table number -1, for example the rotation psi of a
// plane-stress node, or a DOF a support removed before the export) get zero rows in the node's
// Phi_t,k / Phi_psi,k: that DOF moves with the floating frame, and has no mass of its own. A node
// without any DOF in the matrices is a point fixed in the frame at its x_bar_k, still usable for
// joints and markers.
//
// Limits:
//  - Every row of M and K must belong to a node: internal DOFs (allowed by load_sparse_fe_model)
//    have no known motion with the frame and are refused.
//  - The translational masses must agree, t_x^T M t_x = t_y^T M t_y and t_x^T M t_y = 0 (to
//    1e-10 m): a node with only one of u_x, u_y in the matrices breaks that and is refused.
//  - K should be free-free (K Phi_r = 0): the body's elastic forces use K_ff = Phi_f^T K Phi_f
//    only. Supports removed before the export tie those DOFs to the frame (above), which is a
//    valid FFRF body, but a different one from the supported structure.
//  - The body data (ImportedBodyData) has no beam FeModel and no dense matrices, so the nodal
//    form of module 8 (FfrfBody, ffrf_mass_matrix, ...) does not take it; ModalFfrfBody and
//    module 7's IntuitiveBody do (both read ModalBodyData).
//  - The basis Phi is dense, n x (3 + n_f), as is Phi_f in the data: about 2 n (3 + n_f) numbers
//    for the body, and 5 n n_f more while the invariants are made.
//
// Cost: sparse_ffrf_basis about 4 nnz(M) m + 2 nnz(K) m + O(n m^2) flops for a basis of m
// columns; the body about 2 (nnz(M) + nnz(K)) (3 + n_f) + 2 nnz(M) (2 n_f + 3) + 14 n n_f^2.
//
// Why make_sparse_modal_ffrf_body is not an overload of make_modal_ffrf_body: that name is passed
// as a BodyFactory (flexible_examples.hpp), which an overloaded name cannot be.

#include <memory>

#include "fmbd/ffrf_invariants.hpp"
#include "fmbd/matrix_market.hpp"
#include "fmbd/reduction.hpp"

namespace fmbd {

/// The modal data of a body from an imported model (ModalBodyData: basis, Phi_f, M_ff, K_ff, S_f,
/// m, J and the rows of each node), with the rows of basis.Phi and Phi_f in the DOF order of the
/// model's matrices, and the DOF numbers of the node table that gave each node its rows.
struct ImportedBodyData : ModalBodyData {
  std::vector<NodeDofNumbers> dofs;  ///< dofs[k]: the rows of u_x, u_y, psi of node k (-1: not in M)
};

/// The rigid-body modes of an imported model about its centroid, as rigid_body_modes (M06T1) from
/// the node coordinates and the sparse M: Phi_r is n x 3 in the rows of the model's matrices. Throws
/// std::invalid_argument if the model is inconsistent (see make_sparse_modal_ffrf_body) or has no
/// translational mass.
RigidBodyModes sparse_rigid_body_modes(const SparseFeModel& model);

/// An FFRF basis (num_rigid = 3) from any basis of an imported free-free model, for example
/// sparse_craig_bampton(model.K, model.M, ...): the steps of ffrf_basis (M06T4) with sparse M and
/// K and the rigid-body modes above. Phi = [Phi_r, Phi_f] with Phi^T M Phi = diag(m, m, J, I) and
/// Phi^T K Phi = diag(0, 0, 0, omega_1^2, ...) (ascending) to round-off. Throws
/// std::invalid_argument if basis.Phi does not have model.num_dofs() rows, and as
/// sparse_rigid_body_modes.
ReducedBasis sparse_ffrf_basis(const SparseFeModel& model, const ReducedBasis& basis);

/// The data of a body from an imported model and an FFRF basis (num_rigid = 3, rows in the DOF
/// order of model's matrices): the modal data that flexible_body_data(fe, mass_type, basis) of
/// module 7 gives for a beam model. Throws std::invalid_argument as make_sparse_modal_ffrf_body.
ImportedBodyData imported_body_data(const SparseFeModel& model, const ReducedBasis& basis);

/// The full FFRF body in its fast form (ModalFfrfBody) of an imported model and an FFRF basis,
/// ready for Model::add_flexible_body; its data() is imported_body_data(model, basis). Throws
/// std::invalid_argument, with a message that names the fault, for: M and K not square or of
/// different sizes; a node table without nodes, with coordinates and DOF numbers of different
/// lengths, a coordinate that is not finite, a DOF number outside -1 .. n-1 or used twice, or a
/// row of the matrices that no node names; translational masses that differ (above) or are not
/// positive; a basis with num_rigid != 3, fewer than 3 columns or not n rows; a basis whose
/// columns are dependent in the M-norm (Phi^T M Phi singular, for example a zero column).
std::shared_ptr<const ModalFfrfBody> make_sparse_modal_ffrf_body(const SparseFeModel& model,
                                                                 const ReducedBasis& basis);

/// The frame (R, theta) that puts the model's own node coordinates at global position `origin`
/// turned by `angle` (R = origin + A(angle) c): q0 for Model::add_flexible_body, as module 7's
/// frame_for_placement for a beam model. Throws as sparse_rigid_body_modes.
Vec3 frame_for_placement(const SparseFeModel& model, const Vec2& origin, double angle);

}  // namespace fmbd
