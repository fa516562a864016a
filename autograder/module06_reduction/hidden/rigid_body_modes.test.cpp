// Module 6, task T1: rigid-body modes of other frames (hidden tests).
#include <string>

#include "fmbd/fe_assembly.hpp"
#include "fmbd/reduction.hpp"
#include "grading.hpp"
#include "reduction_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m06;

GRADED_TEST("rigid_body_modes random triangular frames with consistent and lumped mass", "[M06][T1][points=2]") {
  Random rnd(6151);
  for (int trial = 0; trial < 6; ++trial) {
    const FeModel fe = random_triangle(rnd);
    const MassMatrixType type = trial < 3 ? MassMatrixType::consistent : MassMatrixType::lumped;
    const FeMatrices fm = assemble(fe, type);
    const RigidOracle o = rigid_oracle(fe, type);
    CAPTURE(trial, fe.num_nodes(), o.mass, o.centroid.transpose(), o.inertia);

    const RigidBodyModes rb = rigid_body_modes(fe, fm.M);
    check_rigid_body_modes(fe, rb, o);
  }
  // A mass matrix of the wrong size is an argument error.
  const FeModel fe = random_triangle(rnd);
  const FeMatrices fm = assemble(fe, MassMatrixType::consistent);
  const MatX too_small = fm.M.topLeftCorner(fe.num_dofs() - 3, fe.num_dofs() - 3);
  check_throws_mentioning<std::invalid_argument>([&] { rigid_body_modes(fe, too_small); }, "",
                                                 "rigid_body_modes: an M that is not n x n (n = 3 N) is an error");
}
