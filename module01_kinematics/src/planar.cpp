// Exercise file of module 1, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 1, task T1: planar rotation and the position of a body-fixed point.
#include <cmath>

#include "fmbd/errors.hpp"
#include "fmbd/planar.hpp"

namespace fmbd {

Mat2 rotation(double phi) {
  // TODO(M01T1): the rotation matrix A(phi) (2x2) that turns body-frame coordinates into
  //   global ones, for the body angle phi, counter-clockwise (README section 1, planar.hpp).
  //   Stuck? ./workbook hint M01T1
  unused(phi);
  throw NotImplemented("M01T1 rotation");
}

Mat2 rotation_derivative(double phi) {
  // TODO(M01T1): dA/dphi (2x2), the derivative of rotation(phi) with respect to phi
  //   (README section 1, planar.hpp). I_tilde() returns I~.
  unused(phi);
  throw NotImplemented("M01T1 rotation_derivative");
}

Vec2 point_position(const Vec3& q_i, const Vec2& s_bar) {
  // TODO(M01T1): the global position r_P of the point with body-frame coordinates s_bar (from
  //   the centroid to P) on the body with coordinates q_i (README section 1, planar.hpp).
  //   R_i = q_i.head<2>() and phi_i = q_i(2).
  unused(q_i, s_bar);
  throw NotImplemented("M01T1 point_position");
}

PointJacobian point_jacobian(const Vec3& q_i, const Vec2& s_bar) {
  // TODO(M01T1): the Jacobian dr_P/dq_i (2x3) of point_position() with respect to
  //   q_i = (x_i, y_i, phi_i), one column per coordinate in that order (README section 1,
  //   planar.hpp).
  unused(q_i, s_bar);
  throw NotImplemented("M01T1 point_jacobian");
}

}  // namespace fmbd
