#pragma once
// Mass matrix of the planar rigid bodies (module 3, task T1).

#include "fmbd/model.hpp"

namespace fmbd {

/// M03T1. Constant mass matrix M (n x n) in centroidal coordinates: the block of rigid body k,
/// at rows and columns offset(k) .. offset(k) + 2, is diag(m_k, m_k, J_k), so that
/// T = 1/2 q_dot^T M q_dot. (From module 7 on, a flexible body adds its constant M_bar block.)
MatX mass_matrix(const Model& model);

/// The constant mass blocks of the flexible bodies (given code, module 7 on): an n x n matrix,
/// zero except for the block M_bar of each flexible body at its coordinates. mass_matrix(model)
/// starts from it and adds the rigid bodies; zero for rigid models.
MatX flexible_mass(const Model& model);

/// Mass matrix at q (given code): mass_matrix(model) with the block of each flexible body
/// replaced by its mass matrix at q (module 8's M(q)). Equal to mass_matrix(model) for rigid
/// models and for module 7's flexible bodies.
MatX mass_matrix(const Model& model, const VecX& q);

}  // namespace fmbd
