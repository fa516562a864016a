#pragma once
// Benchmark mechanisms built with the public API only, for speed and accuracy comparisons of
// simulate() against other codes.
//
// The seven-body loop: a four-bar (crank, coupler, rocker) driving two more dyads, each a link
// and a rocker pinned to the ground, in one plane under gravity. 7 bodies and 10 revolute
// joints: 21 coordinates, 20 constraint equations, 1 degree of freedom. A constant motor
// torque drives the crank, and a spring-damper (TSDA) pulls the last rocker to the ground.
//
//        B-------------C-------------D          joints of the links, given at global positions
//       /|            /|            /|          (Model::add_point_at); every link is a slender
//      A |           E |           F |          rod, 2 kg per metre, its centroid at the mean of
//     /  |          /  |          /  |          its joints
//   G1   G2       (links)  G3          G4       ground pivots on y = 0

#include "fmbd/model.hpp"

namespace fmbd::mechanisms {

struct SevenBodyLoop {
  Model model;
  VecX q0, qd0;  ///< consistent at t = 0: the initial configuration, at rest
};

/// Parameters of the seven-body loop in SI units; `mass_scale` multiplies every mass and
/// inertia (and the spring's stiffness and damping, and the torque, so that the motion stays
/// the same), a test of numerics that do not depend on units.
struct SevenBodyLoopParameters {
  double torque = 0.5;       ///< motor torque on the crank [N m]
  double stiffness = 40.0;   ///< spring [N/m]
  double damping = 0.2;      ///< [N s/m]
  double gravity = 9.81;     ///< [m/s^2], along -y
  double mass_scale = 1.0;
};

SevenBodyLoop seven_body_loop(const SevenBodyLoopParameters& p = {});

}  // namespace fmbd::mechanisms
