#pragma once
// Helpers of the hidden module 8 tests only. They live with the hidden tests, which a student
// release leaves out, so that the released checks do not show what the hidden tests try.
//
// The definitions are in ffrf_hidden_checks.cpp, compiled once for the module's hidden tests.

#include "ffrf_checks.hpp"

namespace fmbd::testing::m08 {

/// The rotation operator on stacked nodal vectors: I~ on (u_x, u_y) of every node, 0 on psi.
MatX stacked_tilde(int nodes);

}  // namespace fmbd::testing::m08
