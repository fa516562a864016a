#pragma once
// Planar kinematics of one rigid body (module 1, task T1).
//
// Body i has centroidal coordinates q_i = (x_i, y_i, phi_i): R_i = (x_i, y_i) is the centroid
// in the global frame, phi_i the angle of the body frame. A point P fixed on body i has
// constant body-frame coordinates s_bar (the vector from the centroid to P), and
//
//   r_P = R_i + A(phi_i) s_bar,        A(phi) = [[cos, -sin], [sin, cos]],
//   dA/dphi = A I~,                    I~ = [[0, -1], [1, 0]]  (rotation by +90 degrees).
//
// The ground is not a body of the model; where a function takes the coordinates of two bodies,
// a ground side is passed as q = (0, 0, 0).

#include <Eigen/Core>

namespace fmbd {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;  ///< one body's coordinates (x, y, phi) or their rates
using Mat2 = Eigen::Matrix2d;
using VecX = Eigen::VectorXd;
using MatX = Eigen::MatrixXd;
using PointJacobian = Eigen::Matrix<double, 2, 3>;  ///< dr_P/dq_i of a body-fixed point

/// I~ = [[0, -1], [1, 0]]: I~ v turns v by +90 degrees; A I~ = I~ A = dA/dphi.
inline Mat2 I_tilde() { return (Mat2() << 0.0, -1.0, 1.0, 0.0).finished(); }

/// M01T1. Rotation matrix A(phi) from the body frame to the global frame (2x2).
Mat2 rotation(double phi);

/// M01T1. dA/dphi = A(phi) I~ (2x2).
Mat2 rotation_derivative(double phi);

/// M01T1. Global position r_P = R_i + A(phi_i) s_bar of a point with body-frame
/// coordinates s_bar on the body with coordinates q_i = (x_i, y_i, phi_i).
Vec2 point_position(const Vec3& q_i, const Vec2& s_bar);

/// M01T1. Jacobian dr_P/dq_i = [ I_2 | A(phi_i) I~ s_bar ] (2x3) of point_position.
PointJacobian point_jacobian(const Vec3& q_i, const Vec2& s_bar);

}  // namespace fmbd
