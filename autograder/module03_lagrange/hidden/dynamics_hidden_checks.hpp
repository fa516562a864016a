#pragma once
// Helpers of the hidden module 3 tests only: the models of their scenarios. They live with the
// hidden tests, which a student release leaves out, so that the released checks do not show
// what the hidden tests try.
//
// The definitions are in dynamics_hidden_checks.cpp, compiled once for the module's hidden tests.

#include "dynamics_checks.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/model.hpp"

namespace fmbd::testing::m03 {

// ---- a four-bar with gravity, rotational spring-dampers and a welded bob ------------------
//
// Constraints: revolutes O2 (ground on side i), B, C, O4 (ground on side j), the crank-angle
// driver, then the fixed joint "weld" between the coupler and a bob (12 coordinates).

inline constexpr double kWeldAngle = 0.4;

examples::FourBarParameters four_bar_parameters(double a, double b, double c, double d, double theta0,
                                                double omega);

/// Exact configuration (12 coordinates) at crank angle theta on the open branch.
VecX four_bar_bob_configuration(const examples::FourBarParameters& p, double theta);

Model four_bar_with_bob(const examples::FourBarParameters& p);

}  // namespace fmbd::testing::m03
