// Definitions of the hidden module 8 checks (see ffrf_hidden_checks.hpp).
#include "ffrf_hidden_checks.hpp"

namespace fmbd::testing::m08 {

MatX stacked_tilde(int nodes) {
  MatX T = MatX::Zero(3 * nodes, 3 * nodes);
  for (int k = 0; k < nodes; ++k) T.block<2, 2>(3 * k, 3 * k) = I_tilde();
  return T;
}

}  // namespace fmbd::testing::m08
