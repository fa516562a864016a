// Exercise file of module 1, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory and the hints.
// Module 1, task T1: planar rotation and the position of a body-fixed point.
#include <cmath>

#include "fmbd/errors.hpp"
#include "fmbd/planar.hpp"

namespace fmbd {

Mat2 rotation(double phi) {
  // TODO(M01T1): rotation matrix from the body frame to the global frame,
  //   A(phi) = [[cos phi, -sin phi],
  //             [sin phi,  cos phi]].
  unused(phi);
  throw NotImplemented("M01T1 rotation");
}

Mat2 rotation_derivative(double phi) {
  // TODO(M01T1): dA/dphi = A(phi) I~, with I~ = [[0, -1], [1, 0]] (see I_tilde()).
  //   Check yourself: the result is [[-sin, -cos], [cos, -sin]].
  unused(phi);
  throw NotImplemented("M01T1 rotation_derivative");
}

Vec2 point_position(const Vec3& q_i, const Vec2& s_bar) {
  // TODO(M01T1): global position of a body-fixed point, r_P = R_i + A(phi_i) s_bar,
  //   where R_i = q_i.head<2>() and phi_i = q_i(2).
  unused(q_i, s_bar);
  throw NotImplemented("M01T1 point_position");
}

PointJacobian point_jacobian(const Vec3& q_i, const Vec2& s_bar) {
  // TODO(M01T1): Jacobian of r_P with respect to q_i = (x_i, y_i, phi_i):
  //   dr_P/dq_i = [ I_2 | A(phi_i) I~ s_bar ]   (2x3).
  //   Hint: the rotation column is the derivative of A s_bar, not A s_bar itself.
  unused(q_i, s_bar);
  throw NotImplemented("M01T1 point_jacobian");
}

}  // namespace fmbd
