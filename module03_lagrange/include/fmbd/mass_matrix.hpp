#pragma once
// The system's mass matrix (module 3, task T1).

#include "fmbd/model.hpp"

namespace fmbd {

/// M03T1. The system's mass matrix M (n x n) at q in centroidal coordinates, written into `M`,
/// which the caller provides n x n with whatever entries (every entry is overwritten): rigid body
/// k's block, at rows and columns offset(k) .. offset(k) + 2, is diag(m_k, m_k, J_k), so that
/// T = 1/2 q_dot^T M q_dot; a flexible body adds its own block at its coordinates through its
/// DeformableBody::add_mass (module 7's M_bar, module 8's M(q)); every other entry is zero.
/// Throws std::invalid_argument if q or M has the wrong size.
void mass_matrix(const Model& model, const VecX& q, MatX& M);
/// The precondition of mass_matrix(model, q, M), which checks it first: q has n entries, M n x n.
void check_mass_storage(const Model& model, const VecX& q, const MatX& M);

/// M at q in new storage.
MatX mass_matrix(const Model& model, const VecX& q);
/// M of a model of rigid bodies, constant (taken at its initial guess). Throws
/// std::invalid_argument for a model with a flexible body, whose M is taken at a q.
MatX mass_matrix(const Model& model);

}  // namespace fmbd
