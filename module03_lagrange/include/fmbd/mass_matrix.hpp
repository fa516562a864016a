#pragma once
// Mass matrix of the planar rigid bodies (module 3, task T1).

#include "fmbd/model.hpp"

namespace fmbd {

/// M03T1. Constant mass matrix M (n x n) of the rigid bodies in centroidal coordinates: the
/// block of rigid body k, at rows and columns offset(k) .. offset(k) + 2, is diag(m_k, m_k, J_k),
/// so that T = 1/2 q_dot^T M q_dot. A flexible body's rows and columns stay zero here: from
/// module 7 on it adds its own block in mass_matrix(model, q).
MatX mass_matrix(const Model& model);

/// Mass matrix at q (given code): mass_matrix(model) plus the block that each flexible body adds
/// at its coordinates (DeformableBody::add_mass: module 7's M_bar, module 8's M(q)). Equal to
/// mass_matrix(model) for rigid models.
MatX mass_matrix(const Model& model, const VecX& q);

}  // namespace fmbd
