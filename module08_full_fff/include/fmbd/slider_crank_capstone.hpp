#pragma once
// The capstone of the flexible half (module 8, task T6; capstone/README.md): Simeon's flexible
// slider-crank, built by the student from its published data and initial state, with the FE beam
// of module 5, a reduction basis of module 6 and the full FFRF body of module 8.
//
// The mechanism (B. Simeon, "Modelling a flexible slider crank mechanism by a mixed system of
// DAEs and PDEs", Mathematical Modelling of Systems 2 (1996) 1-18; problem "crank" of the Test
// Set for IVP Solvers, F. Mazzia and C. Magherini, University of Bari) lies in one plane,
// without gravity and damping. A rigid crank of length L1 turns about the origin O at the
// constant rate omega, phi1 = omega t. An elastic connecting rod (Euler-Bernoulli, linear
// elasticity) is pinned to the crank's tip and to a slider, a point mass that moves on the
// x axis.
//
// The published coordinates are (phi1, phi2, x3, q1, q2, q3, q4). The rod's own frame has its
// origin at the crank pin and its x axis along the chord to the wrist pin; phi2 is the chord's
// angle, x3 the slider's position, and the rod's displacements in that frame are
//
//   lateral  w(x) = q1 sin(pi x / L2) + q2 sin(2 pi x / L2),
//   axial    u(x) = q3 4 xi (1 - xi) + q4 xi (2 xi - 1),     xi = x / L2,
//
// so that w is the deflection from the chord, w(L2 / 2) = q1, and q4 is the chord's stretch:
// L1 sin(phi1) + (L2 + q4) sin(phi2) = 0 and x3 = L1 cos(phi1) + (L2 + q4) cos(phi2).

#include "fmbd/flexible_examples.hpp"

namespace fmbd {

/// The published data of Simeon's slider-crank, SI units (Simeon 1996; Test Set "crank").
namespace simeon {
inline constexpr double crank_length = 0.15;       ///< L1 [m]
inline constexpr double crank_mass = 0.36;         ///< m1 [kg]
inline constexpr double crank_inertia = 0.002727;  ///< J1 about the pivot O [kg m^2]
inline constexpr double crank_speed = 150.0;       ///< omega [rad/s]
inline constexpr double rod_length = 0.30;         ///< L2 [m]
inline constexpr double rod_width = 0.008;         ///< b, out of the plane [m]
inline constexpr double rod_height = 0.008;        ///< h, in the plane of motion [m]
inline constexpr double E = 2.0e11;                ///< Young's modulus [Pa]
inline constexpr double rho = 7870.0;              ///< density [kg/m^3]
inline constexpr double rod_mass = 0.151104;       ///< m2 = rho b h L2 [kg]
inline constexpr double slider_mass = 0.075552;    ///< m3, a point mass [kg]

/// The published initial state ("close to smooth motion"), in the order
/// (phi1, phi2, x3, q1, q2, q3, q4), and its rates.
inline constexpr double q0[7] = {0.0, 0.0, 0.450016933, 0.0, 0.0, 1.03339863e-5, 1.69327969e-5};
inline constexpr double qd0[7] = {150.0,         -74.9957670,    -2.68938672e-6, 0.444896105,
                                  4.63434311e-3, -1.78591076e-6, -2.68938672e-6};

/// The published reference solution at t_end, same order.
inline constexpr double t_end = 0.1;  ///< [s], 2.4 turns of the crank
inline constexpr double q_end[7] = {15.0,
                                    -0.3311734987910881,
                                    0.1697373326718410,
                                    1.893192460247178e-4,
                                    2.375751865617931e-5,
                                    -5.323907988763734e-6,
                                    -8.363283141616840e-6};
inline constexpr double qd_end[7] = {150.0,
                                     60.25346682645789,
                                     -8.753116989887888,
                                     -3.005536801092212e-2,
                                     -5.500488291932075e-3,
                                     4.978243404809343e-4,
                                     1.104933470696396e-3};
}  // namespace simeon

/// M08T6. Simeon's slider-crank as a model with the full FFRF rod, in its published initial
/// state at t = 0 (q0 and qd0 consistent). Names the grader reads: the bodies "crank", "rod" and
/// "slider"; the rod is the FlexibleExample's flexible body (`flexible`, with its `data`), a
/// straight beam whose first and last FE nodes are its two pins. The crank is driven at
/// phi1 = omega t. The mesh, the basis (and so the rod's frame), the frame of every body, the
/// node numbering, the order of bodies and points and which body is i or j in a joint are the
/// builder's choice, as long as the motion meets the published reference (capstone/README.md).
FlexibleExample flexible_slider_crank_capstone();

}  // namespace fmbd
