#pragma once
// Degrees of freedom (module 1, task T7).

#include "fmbd/model.hpp"

namespace fmbd {

/// Relative tolerance of the rank decisions: singular values below
/// rank_tolerance * (largest singular value) count as zero.
inline constexpr double rank_tolerance = 1e-9;

/// M01T7. Number of independent constraint equations: the rank of C_q (m x n) with the
/// threshold rank_tolerance relative to the largest singular value (0 for an empty matrix).
int jacobian_rank(const MatX& Cq);

/// M01T7. Degrees of freedom at (q, t): n - rank C_q(q, t), n = model.num_coordinates() (3 n_b
/// for rigid bodies). Redundant constraints do not remove freedom, so this can exceed n - m.
int degrees_of_freedom(const Model& model, const VecX& q, double t = 0.0);

}  // namespace fmbd
