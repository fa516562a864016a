#pragma once
// Example mechanisms with their builders and closed-form geometry (given code, module 1).

#include "fmbd/model.hpp"

namespace fmbd::examples {

// ---------------------------------------------------------------------------------------
// Slider-crank
//
//                  B
//                  o
//         r      /   \   l
//              /       \  (rod)
//   ground  O o  A        \  C
//            ///            o [slider] --> x
//                        ===============  guide
//
// Crank O-B (length r) turns about the ground pivot O = (0, 0) at angle A(t) = A0 + omega t;
// the connecting rod B-C (length l) drives the slider C along the global x axis.
// Bodies: 0 crank, 1 rod, 2 slider, with centroids at the middle of each link.
// Joints: revolute O (ground-crank), revolute B (crank-rod), revolute C (rod-slider),
// translational "slider guide" (ground-slider, axis x), driver "crank angle" (absolute).
// q has 9 entries, C has 9 rows, so the driven mechanism has 0 DOF (1 without the driver).
// ---------------------------------------------------------------------------------------
struct SliderCrankParameters {
  double r = 0.1;      ///< crank length [m]
  double l = 0.3;      ///< rod length [m], > r
  double A0 = 0.0;     ///< crank angle at t = 0 [rad]
  double omega = 2.0;  ///< crank speed [rad/s]
  bool driven = true;  ///< add the crank-angle driver
};

Model slider_crank(const SliderCrankParameters& p = {});

/// Closed-form slider position x(A) = r cos A + sqrt(l^2 - r^2 sin^2 A) and its first and
/// second derivatives with respect to the crank angle A.
struct SliderCrankClosedForm {
  double x, dx_dA, d2x_dA2;
};
SliderCrankClosedForm slider_crank_closed_form(double r, double l, double A);

/// Exact coordinates q (9) of the slider-crank at crank angle A.
VecX slider_crank_configuration(const SliderCrankParameters& p, double A);

// ---------------------------------------------------------------------------------------
// Four-bar linkage
//
//                  B  o---------------o  C
//                    /    coupler b     \  rocker c
//          crank a  /                    \  .
//                  /                      \ .
//            O2  o                         o  O4
//              ///          ground d        ///
//
// Ground pivots O2 = (0, 0) and O4 = (d, 0). Bodies: 0 crank O2-B, 1 coupler B-C,
// 2 rocker C-O4, centroids at mid-link. Four revolute joints (8 rows) and, if driven,
// the crank angle theta2(t) = theta0 + omega t: 0 DOF (1 without the driver).
// The defaults form a Grashof crank-rocker: the crank turns fully.
// ---------------------------------------------------------------------------------------
struct FourBarParameters {
  double a = 0.10;      ///< crank [m]
  double b = 0.30;      ///< coupler [m]
  double c = 0.25;      ///< rocker [m]
  double d = 0.30;      ///< ground [m]
  double theta0 = 0.5;  ///< crank angle at t = 0 [rad]
  double omega = 1.0;   ///< crank speed [rad/s]
  bool driven = true;
};

/// Builds the four-bar. The bodies' initial guesses come from the closed-form assembly
/// (open branch) at theta0; if the linkage cannot close there, a rough straight-line guess is
/// used and the position analysis reports the unreachable configuration.
Model four_bar(const FourBarParameters& p = {});

/// Position of joint C (coupler-rocker) for crank angle theta on the open branch, or false
/// if the loop cannot close at that angle.
bool four_bar_joint_C(const FourBarParameters& p, double theta, Vec2& C);

}  // namespace fmbd::examples
