#pragma once
// Helpers of the hidden module 2 tests only: the models of their scenarios. They live with the
// hidden tests, which a student release leaves out, so that the released checks do not show
// what the hidden tests try.
//
// The definitions are in kinematic_hidden_checks.cpp, compiled once for the module's hidden tests.

#include "fmbd/drive_function.hpp"
#include "fmbd/model.hpp"
#include "kinematic_checks.hpp"

namespace fmbd::testing::m02 {

// ---- arm and collar: a custom model with a distance and a point-coordinate driver ---------
//
// An arm (pivot-to-tip length 2 h, centroid mid-arm) turns about the ground point O = (0, 0);
// a collar slides along it (translational joint, no relative rotation). The y coordinate of
// the arm tip is driven by f_y(t), the distance from O to the collar by f_d(t). Closed form:
//   phi(t) = asin(f_y / 2h),  arm centroid h (cos phi, sin phi),  collar f_d (cos phi, sin phi).

struct ArmCollar {
  Model model;
  double h = 0.2;
  DriveFunction tip_y = DriveFunction::constant(0.0);
  DriveFunction radius = DriveFunction::constant(0.0);

  VecX exact(double t) const;
};

ArmCollar arm_collar(double h, DriveFunction tip_y, DriveFunction radius, double t_guess = 0.0);

}  // namespace fmbd::testing::m02
