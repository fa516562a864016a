#pragma once
// Rigid-body modes of an FE model about its centroid (module 6, task T1).

#include "fmbd/modal.hpp"

namespace fmbd {

/// The rigid-body motion of an FE model about its centroid.
struct RigidBodyModes {
  double mass = 0.0;                ///< m, the total mass of M
  Vec2 centroid = Vec2::Zero();     ///< c, the mass centre (model coordinates)
  double inertia = 0.0;             ///< J, the mass moment of inertia about c
  MatX Phi_r;                       ///< n x 3: unit translation x, unit translation y, unit rotation about c
};

/// M06T1. Rigid-body modes about the centroid from node positions x_k and the mass matrix M:
/// node k gets (1, 0, 0) in column 0, (0, 1, 0) in column 1, (-(y_k - c_y), x_k - c_x, 1) in
/// column 2. m = t_x^T M t_x; the centroid follows from the first moments of M (README section 1);
/// J = r_c^T M r_c, with r_c the rotation column. Then Phi_r^T M Phi_r = diag(m, m, J) and
/// K Phi_r = 0.
RigidBodyModes rigid_body_modes(const FeModel& fe, const MatX& M);

}  // namespace fmbd
