#pragma once
// Joint equations (module 1, tasks T2-T4). Each function evaluates one joint from the
// coordinates of its two bodies, q_i = (x_i, y_i, phi_i) and q_j; a ground side is passed
// as q = (0, 0, 0). Point vectors s_i, s_j are in the body frames. See README section 2.

#include "fmbd/constraint_block.hpp"
#include "fmbd/planar.hpp"

namespace fmbd {

/// M01T2. Revolute joint, 2 rows (global frame):
///   C = r_Pi - r_Pj = R_i + A_i s_i - R_j - A_j s_j.
ConstraintBlock revolute_constraint(const Vec3& q_i, const Vec2& s_i, const Vec3& q_j, const Vec2& s_j);

/// M01T3. Translational joint, 2 rows. axis_i is a unit vector in the body-i frame;
/// n_i = A_i I~ axis_i is the normal of the sliding line and d = r_Pj - r_Pi:
///   C_1 = n_i^T d,     C_2 = phi_j - phi_i - phi0.
ConstraintBlock translational_constraint(const Vec3& q_i, const Vec2& s_i, const Vec3& q_j,
                                         const Vec2& s_j, const Vec2& axis_i, double phi0);

/// M01T4. Fixed joint, 3 rows: rows 1-2 as the revolute joint, row 3: phi_j - phi_i - phi0.
ConstraintBlock fixed_constraint(const Vec3& q_i, const Vec2& s_i, const Vec3& q_j, const Vec2& s_j,
                                 double phi0);

}  // namespace fmbd
