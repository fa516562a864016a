#pragma once
// Right-hand side of the acceleration equation (module 2, tasks T3-T5):
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

/// M02T3. Revolute joint (2 rows): gamma of C = r_Pi - r_Pj.
RowVector revolute_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j,
                         const Vec3& qd_j, const Vec2& s_j);

/// M02T3. Translational joint (2 rows): gamma of its two rows (module 1's translational C).
RowVector translational_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j,
                              const Vec3& qd_j, const Vec2& s_j, const Vec2& axis_i);

/// M02T3. Fixed joint (3 rows): gamma of its two point rows and its angle row.
RowVector fixed_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j,
                      const Vec3& qd_j, const Vec2& s_j);

/// M02T4. Absolute-angle driver (1 row): gamma of C = phi_i - f(t).
RowVector absolute_angle_gamma(const DriveValue& f);

/// M02T4. Relative-angle driver (1 row): gamma of C = phi_j - phi_i - f(t).
RowVector relative_angle_gamma(const DriveValue& f);

/// M02T4. Point-coordinate driver (1 row): gamma of C = e_axis^T r_P - f(t).
RowVector point_coordinate_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, Axis axis,
                                 const DriveValue& f);

/// M02T4. Distance driver (1 row): gamma of C = 1/2 (d^T d - f(t)^2), d = r_Pj - r_Pi.
RowVector distance_gamma(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j,
                         const Vec3& qd_j, const Vec2& s_j, const DriveValue& f);

/// gamma of one constraint (c.rows) from the function above for its type, in the coordinates of
/// its two markers (given code). A marker on an FE node also accelerates without q_ddot: its terms
/// are node_gamma_terms().
RowVector kernel_gamma(const Constraint& c, const ConstraintMarkers& markers, double t);
/// The terms of one constraint's gamma that come from its markers on FE nodes of flexible bodies:
/// a node also accelerates without q_ddot (its convective term c), and each node's body gives
/// the constraint's term from it (DeformableBody::node_gamma_term, module 7). Zero (c.rows) where
/// both markers are rigid bodies or the ground.
RowVector node_gamma_terms(const Constraint& c, const ConstraintMarkers& markers, double t);

/// M02T5: gamma of the whole model (m) at (q, q_dot, t), written into `gamma`, which the caller
/// provides with m entries holding anything (every entry is overwritten): each constraint's
/// gamma, from its markers at (q, q_dot), at its rows first_row .. first_row + rows - 1.
/// Throws std::invalid_argument if q, q_dot or gamma has the wrong size.
void constraint_gamma(const Model& model, const VecX& q, const VecX& qd, double t, VecX& gamma);
/// The precondition of constraint_gamma, which checks it first: q and q_dot have n entries and
/// gamma m. Throws std::invalid_argument naming what differs.
void check_gamma_storage(const Model& model, const VecX& q, const VecX& qd, const VecX& gamma);
/// gamma of the whole model (m) in new storage.
VecX constraint_gamma(const Model& model, const VecX& q, const VecX& qd, double t);

}  // namespace fmbd
