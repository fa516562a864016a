#pragma once
// Mass matrix of the planar rigid bodies (module 3, task T1).

#include "fmbd/model.hpp"

namespace fmbd {

/// M03T1. Constant mass matrix M (n x n, n = 3 n_b) in centroidal coordinates:
/// block k is diag(m_k, m_k, J_k), so that T = 1/2 q_dot^T M q_dot.
MatX mass_matrix(const Model& model);

}  // namespace fmbd
