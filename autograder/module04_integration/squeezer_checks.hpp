#pragma once
// Checks of the rigid capstone (task M04T5, Andrews' squeezer; capstone/README.md), shared by
// the graded tests and the project's test that an equivalent model scores full.
//
// They read a model only through what every equivalent model has: the named bodies and points
// of squeezer.hpp, positions of points, the angles and rates of bodies (whose frame orientation
// is free, so only differences and rates), and the reactions of joints on a named body summed
// over the joints at one place (how the four bodies at E are joined is free). Body and point
// order, frames and the i/j order of joints do not matter.
//
// The oracles are published numbers and plain geometry:
// - the published configuration at t = 0 and the multipliers of Hairer and Wanner (Solving
//   Ordinary Differential Equations II, 2nd ed., section VII.7): the force of the rod on the
//   triangle at E is (lambda_1, lambda_2), the triangle is at rest and unaccelerated at t = 0;
// - the reference solution at t = 0.03 s of the Test Set for IVP Solvers (F. Mazzia and C.
//   Magherini, University of Bari, problem "andrews", computed with PSIDE at tolerances 1e-14);
// - the position analysis by circle intersections, written out here.

#include <vector>

#include "fmbd/squeezer.hpp"

namespace fmbd::testing::m04 {

/// Hairer's angles of the squeezer (squeezer.hpp).
struct SqueezerAngles {
  double beta, Theta, gamma, Phi, delta, Omega, epsilon;
};

/// The named points of squeezer.hpp.
struct SqueezerPoints {
  Vec2 F, E, D, G, H;
};

/// Published: the configuration at t = 0 and the reference at t = 0.03 s with its rates.
SqueezerAngles squeezer_angles_at_start();
SqueezerAngles squeezer_angles_at_end();
SqueezerAngles squeezer_rates_at_end();

/// The points at given angles, the formulas of squeezer.hpp written out.
SqueezerPoints squeezer_points(const SqueezerAngles& a);

/// The points at crank angle beta by circle intersections (E from F and B, G and H from A and
/// E, D from the triangle's angle), on the branch of the published configuration.
SqueezerPoints squeezer_points_at_crank_angle(double beta);

/// Energy of the spring from C to D [J].
double squeezer_spring_energy(const Vec2& D);

// ---- the checks, on any equivalent model ----------------------------------------------------

/// The names the grader reads, the masses, one degree of freedom, q0 consistent, at rest.
/// Returns false (after failing) when the model cannot be graded further.
bool check_squeezer_structure(const SqueezerModel& s);
/// The named points at their published places at t = 0.
void check_squeezer_start(const SqueezerModel& s);
/// The crank turned by the grader's own driver to each angle beta0 + turn: the points against
/// the circle intersections.
void check_squeezer_positions(const SqueezerModel& s, const std::vector<double>& turns);
/// At t = 0: the crank's and the rod's angular accelerations, the force on the triangle at E
/// and at B.
void check_squeezer_reactions(const SqueezerModel& s);
/// Simulated to t = 0.03 s (RK4, 600 steps, projection): the points and the crank's rate
/// against the reference, the kinetic energy against the work of the torque less the spring's
/// energy, and the energy balance along the way.
void check_squeezer_motion(const SqueezerModel& s);

}  // namespace fmbd::testing::m04
