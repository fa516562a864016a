#pragma once
// Right-hand side of the acceleration equation (module 2, tasks T3-T4):
//
//   C_q q_ddot = gamma,    gamma = -(C_q q_dot)_q q_dot - 2 C_qt q_dot - C_tt     eq. (2)
//
// gamma collects every term of d2C/dt2 that does not multiply q_ddot, with the opposite sign;
// README section 2 derives it for every joint and driver type.
//
// Each function takes the coordinates q and velocities qd = (x_dot, y_dot, phi_dot) of the
// two bodies (zero for the ground) and returns gamma for that constraint's rows.

#include "fmbd/constraint_block.hpp"
#include "fmbd/drive_function.hpp"
#include "fmbd/marker.hpp"
#include "fmbd/model.hpp"

namespace fmbd {

/// M02T3. Revolute joint (2 rows): gamma = A_i s_i phi_dot_i^2 - A_j s_j phi_dot_j^2.
RowVector revolute_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j,
                         const Vec3& qd_j, const Vec2& s_j);

/// M02T3. Translational joint (2 rows): see the README for the derivation of row 1; row 2 is 0.
RowVector translational_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j,
                              const Vec3& qd_j, const Vec2& s_j, const Vec2& axis_i);

/// M02T3. Fixed joint (3 rows): the revolute rows, then 0.
RowVector fixed_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j,
                      const Vec3& qd_j, const Vec2& s_j);

/// M02T4. Absolute-angle driver (1 row): gamma = f''(t).
RowVector absolute_angle_gamma(const DriveValue& f);

/// M02T4. Relative-angle driver (1 row): gamma = f''(t).
RowVector relative_angle_gamma(const DriveValue& f);

/// M02T4. Point-coordinate driver (1 row): gamma = e_axis^T A_i s_i phi_dot_i^2 + f''(t).
RowVector point_coordinate_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, Axis axis,
                                 const DriveValue& f);

/// M02T4. Distance driver (1 row), d = r_Pj - r_Pi:
///   gamma = -d_dot^T d_dot + d^T (A_j s_j phi_dot_j^2 - A_i s_i phi_dot_i^2) + f'^2 + f f''.
RowVector distance_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j,
                         const Vec3& qd_j, const Vec2& s_j, const DriveValue& f);

/// gamma of one constraint (c.rows) from the function above for its type, in the coordinates of
/// its two markers (given code). A marker with a convective acceleration (an FE node) still has
/// to be accounted for, as constraint_gamma does.
RowVector kernel_gamma(const Constraint& c, const ConstraintMarkers& markers, double t);

/// gamma of the whole model (m), assembled from the functions above (given code).
VecX constraint_gamma(const Model& model, const VecX& q, const VecX& qd, double t);

}  // namespace fmbd
