#pragma once
// Oracles of the hidden module 5 tests that restate the solutions of T3 and T4 (an assembly and a
// removal of supported DOFs written out here), and the hints built on them, which name the likely
// mistake by reproducing it. They live with the hidden tests, which a student release leaves out:
// the visible tests check properties instead (rigid motions, closed forms, beam theory). Below
// them, the helpers that only the hidden tests use.
//
// The definitions are in fe_oracles.cpp, compiled once for the module's hidden tests.

#include <cmath>
#include <string>
#include <vector>

#include "fe_checks.hpp"

namespace fmbd::testing::m05 {

/// Slips of an assembly, for hints.
enum class Slip { none, unrotated, T_transposed, node_b_after_a };

/// M_FE and K_FE assembled here from the quadrature element matrices and the element axes.
FeMatrices assemble_by_hand(const FeModel& fe, MassMatrixType type, Slip slip = Slip::none);

/// The likely mistake behind a wrong assembled matrix (K if `stiffness`, else M).
std::string assembly_hint(const MatX& actual, const FeModel& fe, MassMatrixType type, bool stiffness);

/// Free DOFs of a model with supports, computed here.
std::vector<int> free_dofs_by_hand(int num_nodes, const std::vector<NodeSupport>& supports);
DofMap map_by_hand(int num_nodes, const std::vector<NodeSupport>& supports);

/// The likely mistake behind a wrong DofMap::free.
std::string free_list_hint(int num_nodes, const std::vector<NodeSupport>& supports, const std::vector<int>& actual);

// ---- helpers of the hidden tests only --------------------------------------------------------

/// The name of an end condition, for messages.
const char* name_of(Ends e);

/// Relative error |a - e| / e.
inline double rel_error(double a, double e) { return std::abs(a - e) / std::abs(e); }

}  // namespace fmbd::testing::m05
