#pragma once
// Driver equations (module 1, task T5): one row each, C = (measured quantity) - f(t) and
// C_t = dC/dt. `f` holds f(t), f'(t), f''(t) at the current time.

#include "fmbd/constraint_block.hpp"
#include "fmbd/drive_function.hpp"
#include "fmbd/model.hpp"
#include "fmbd/planar.hpp"

namespace fmbd {

/// M01T5. C = phi_i - f(t).
ConstraintBlock absolute_angle_constraint(const Vec3& q_i, const DriveValue& f);

/// M01T5. C = phi_j - phi_i - f(t).
ConstraintBlock relative_angle_constraint(const Vec3& q_i, const Vec3& q_j, const DriveValue& f);

/// M01T5. C = e_axis^T r_P - f(t), r_P = R_i + A_i s_i, e_axis = (1, 0) or (0, 1).
ConstraintBlock point_coordinate_constraint(const Vec3& q_i, const Vec2& s_i, Axis axis,
                                            const DriveValue& f);

/// M01T5. C = 1/2 (d^T d - f(t)^2), d = r_Pj - r_Pi.
ConstraintBlock distance_constraint(const Vec3& q_i, const Vec2& s_i, const Vec3& q_j, const Vec2& s_j,
                                    const DriveValue& f);

}  // namespace fmbd
