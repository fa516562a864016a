#pragma once
// Checks of the flexible capstone (task M08T6, Simeon's slider-crank; capstone/README.md),
// shared by the graded tests and the project's test that an equivalent model scores full.
//
// They read a model only through what every equivalent model has: the bodies "crank", "rod" and
// "slider" found by name, the FlexibleExample's flexible body (the rod) and its basis, and the
// rod's neutral axis through beam_point and deflection_at (module 7). Which end of the rod is
// node 0 is found from the crank pin, so the mesh's direction, its size, the basis, every
// frame, the order of bodies and points and the i/j order of joints do not matter.
//
// The oracles are published numbers: the data, the initial state and the reference solution
// at t = 0.1 s of Simeon (1996) and of the Test Set for IVP Solvers (F. Mazzia and C. Magherini,
// University of Bari, problem "crank"), in slider_crank_capstone.hpp. The Test Set's axial
// inertia is not a beam's (its axial mass entries are 15 times the consistent ones), so the
// axial motion, at the 1e-5 m level, is checked only through x3 with a tolerance above it.

#include "fmbd/slider_crank_capstone.hpp"

namespace fmbd::testing::m08 {

/// What the checks read off a state: the rod's chord from the crank pin to the wrist pin and
/// the deflection of its middle from that chord (the published phi2, x3 and q1).
struct CapstoneState {
  double phi1 = 0;   ///< the crank's frame angle (its orientation is free: differences only)
  double phi2 = 0;   ///< the chord's angle
  double x3 = 0;     ///< the wrist pin's x
  double y3 = 0;     ///< the wrist pin's y
  double w_mid = 0;  ///< deflection at mid-span, positive to the left of the chord
};

/// The state at q, and its rates along q_dot (central differences of q + e q_dot).
CapstoneState capstone_state(const FlexibleExample& ex, const VecX& q);
CapstoneState capstone_rates(const FlexibleExample& ex, const VecX& q, const VecX& qd);

/// The fixed step of the grader's RK4 for the model: 0.1 s divided into steps of at most 5e-5 s
/// with h omega_max <= 2 (omega_max: the highest frequency of the rod's basis, from K_ff and
/// M_ff), below RK4's stability limit of 2.8.
double capstone_step(const FlexibleExample& ex);

// ---- the checks, on any equivalent model ----------------------------------------------------

/// The names the grader reads, the masses, the crank's inertia about O, the rod a full FFRF
/// body, no degree of freedom with the driver but the rod's elastic ones, q0 and qd0
/// consistent. Returns false (after failing) when the model cannot be graded further.
bool check_capstone_structure(const FlexibleExample& ex);
/// The published initial state: the chord along the x axis, x3(0), the chord's rate, no
/// deflection at mid-span and its published rate, the crank's rate.
void check_capstone_start(const FlexibleExample& ex);
/// Simulated to t = 0.1 s (RK4 with capstone_step, projection): the crank's turn, phi2, x3, the
/// mid-span deflection and the rates against the published reference.
void check_capstone_motion(const FlexibleExample& ex);
/// Along the same run: the energy gained equals the driver's work.
void check_capstone_energy(const FlexibleExample& ex);

}  // namespace fmbd::testing::m08
