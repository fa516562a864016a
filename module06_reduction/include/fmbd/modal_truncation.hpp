#pragma once
// Modal truncation on free-free modes, made ready for the FFRF (module 6, task T2).

#include "fmbd/reduced_basis.hpp"
#include "fmbd/rigid_body_modes.hpp"

namespace fmbd {

/// M06T2. Modal truncation on free-free modes for the FFRF: Phi = [Phi_r, Phi_f], Phi_r from
/// rigid_body_modes, Phi_f the `num_elastic` lowest elastic free-free modes (mass-normalised; the
/// three zero modes of K phi = omega^2 M phi are skipped). num_rigid = 3, and
///   M_bar = diag(m, m, J, 1, ..., 1),   K_bar = diag(0, 0, 0, omega_1^2, ..., omega_k^2)
/// up to round-off. Throws std::invalid_argument unless 0 <= num_elastic <= n - 3.
ReducedBasis modal_truncation(const FeModel& fe, const FeMatrices& matrices, int num_elastic);

}  // namespace fmbd
