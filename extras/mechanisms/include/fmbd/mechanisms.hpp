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

#include <vector>

#include "fmbd/model.hpp"
#include "fmbd/simulation.hpp"

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

/// The N-four-bar mechanism, problem A02 of the IFToMM library of computational benchmark
/// problems of multibody dynamics: 2N + 1 slender rods of 1 m and 1 kg, N + 1 cranks on ground
/// pivots A_k = (k, 0) joined at their heads B_k by N couplers, under gravity 9.81 m/s^2 along -y.
/// At t = 0 the cranks stand vertical and every B_k moves at 1 m/s along +x. Bodies: crank k (k = 0..N), then
/// coupler k (k = 0..N-1). Every half turn the mechanism lies flat (theta = 0 or pi), where C_q
/// loses N ranks for an instant. `origin` moves the whole chain (the pivots at origin + (k, 0)),
/// the same mechanism seen from another ground frame.
struct FourBarChain {
  Model model;
  VecX q0, qd0;  ///< consistent at t = 0
  int windows = 0;
};
FourBarChain four_bar_chain(int windows, const Vec2& origin = Vec2::Zero());

/// The exact motion of the chain: on its branch the couplers translate, so theta, the angle of
/// every crank from +x, obeys the one-degree-of-freedom equation J theta'' = -G cos(theta) with
/// J = (N + 1)/3 + N and G = 9.81 ((N + 1)/2 + N), theta(0) = pi/2, theta'(0) = -1 rad/s.
/// theta at t = 0, dt, ..., T (T a multiple of dt), from classical RK4 with steps of at most
/// 1e-5 s (its global error below 1e-13 rad over 20 s).
std::vector<double> four_bar_chain_theta(int windows, double dt, double T);

/// The largest distance (max norm) of B_0 in a run recorded at t = 0, dt, ..., T from the exact
/// motion, and the largest |E - E0| of the recorded energy.
struct FourBarChainError {
  double position = 0.0;  ///< [m]
  double energy = 0.0;    ///< [J]
};
FourBarChainError four_bar_chain_error(const Trajectory& run, const std::vector<double>& theta);

}  // namespace fmbd::mechanisms
