#pragma once
// The capstone of the rigid half (module 4, task T5; capstone/README.md): Andrews' squeezing
// mechanism, built by the student with the Model API from its drawing and its table of published
// data.
//
// The mechanism (E. Hairer and G. Wanner, Solving Ordinary Differential Equations II, 2nd ed.,
// Springer 1996, section VII.7, after Giles 1978, Manning 1981 and Schiehlen 1990) lies in one
// plane, without gravity. Seven rigid bodies are pinned to each other and to the fixed points O,
// A, B of the ground; a constant torque drives the crank (body 1) about O, and a spring pulls the
// point D of the triangle (body 3) towards the fixed point C. With the published angles (beta,
// Theta, gamma, Phi, delta, Omega, epsilon), O at the origin, e(a) = (cos a, sin a) and
// n(a) = (sin a, -cos a):
//
//   body 1 (crank)     F = rr e(beta);  centroid ra e(beta)
//   body 2 (rod)       E = F - d e(beta + Theta);  centroid F - da e(beta + Theta)
//   body 3 (triangle)  E = B + ss n(gamma),  D = B + sc n(gamma) + sd e(gamma);
//                      centroid B + sa n(gamma) + sb e(gamma)
//   body 5             G = A + zt e(delta);  centroid A + ta e(delta) + tb e(delta + pi/2)
//   body 4             E = G + e n(Phi + delta);  centroid E - ea n(Phi + delta)
//   body 7             H = A + u n(epsilon);  centroid A + ua n(epsilon) + ub e(epsilon)
//   body 6             E = H + zf e(Omega + epsilon);  centroid E - fa e(Omega + epsilon)
//
// Bodies 2, 3, 4 and 6 meet at the one point E; 3 turns about B, 1 about O, 5 and 7 about A.
// (Bodies 3, 5 and 7 turn about fixed pivots: the side of their centroid's offset does not change
// the motion, since there is no gravity.)

#include "fmbd/model.hpp"

namespace fmbd {

/// The published data of the squeezer, SI units (Hairer and Wanner, table of section VII.7).
namespace squeezer {
inline constexpr double mass[7] = {0.04325, 0.00365, 0.02373, 0.00706, 0.07050, 0.00706, 0.05498};  ///< [kg]
inline constexpr double inertia[7] = {2.194e-6, 4.410e-7, 5.255e-6, 5.667e-7,
                                      1.169e-5, 5.667e-7, 1.912e-5};  ///< about the centroid [kg m^2]
inline constexpr double xa = -0.06934, ya = -0.00227;  ///< fixed point A [m]
inline constexpr double xb = -0.03635, yb = 0.03273;   ///< fixed point B [m]
inline constexpr double xc = 0.014, yc = 0.072;        ///< fixed point C, the spring's ground end [m]
inline constexpr double rr = 0.007, ra = 0.00092;      ///< crank [m]
inline constexpr double d = 0.028, da = 0.0115;        ///< rod [m]
inline constexpr double ss = 0.035, sa = 0.01874, sb = 0.01043, sc = 0.018, sd = 0.02;  ///< triangle [m]
inline constexpr double e = 0.02, ea = 0.01421;        ///< body 4 [m]
inline constexpr double zt = 0.04, ta = 0.02308, tb = 0.00916;  ///< body 5 [m]
inline constexpr double zf = 0.02, fa = 0.01421;       ///< body 6 [m]
inline constexpr double u = 0.04, ua = 0.01228, ub = 0.00449;   ///< body 7 [m]
inline constexpr double torque = 0.033;                ///< motor torque on the crank [N m]
inline constexpr double stiffness = 4530.0;            ///< spring c0 [N/m]
inline constexpr double rest_length = 0.07785;         ///< spring l0 [m]
/// The published initial configuration, consistent and at rest at t = 0 [rad].
inline constexpr double beta0 = -0.0617138900142764496358948458001;
inline constexpr double Theta0 = 0.0;
inline constexpr double gamma0 = 0.455279819163070380255912382449;
inline constexpr double Phi0 = 0.222668390165885884674473185609;
inline constexpr double delta0 = 0.487364979543842550225598953530;
inline constexpr double Omega0 = -0.222668390165885884674473185609;
inline constexpr double epsilon0 = 1.23054744454982119249735015568;
}  // namespace squeezer

/// The squeezer as a model, with its configuration at t = 0.
struct SqueezerModel {
  Model model;
  VecX q0;   ///< satisfies the constraints, crank angle beta0
  VecX qd0;  ///< zero: the mechanism starts at rest
};

/// M04T5. Andrews' squeezer built with the Model API: the seven bodies (each frame's origin at the
/// body's centroid, its orientation free), the revolute joints, the motor torque on the crank and
/// the spring from C to D, with no driver. Names the grader reads: the bodies "body1" ... "body7"
/// and the points "F" (on body 1), "E" (on body 2), "D" (on body 3), "G" (on body 5) and "H" (on
/// body 7). Body and point order, the other names, the orientation of each body frame and which
/// body is i or j in a joint are the builder's choice.
SqueezerModel andrews_squeezer();

}  // namespace fmbd
