// Module 8, task T6: the capstone of the flexible half, Simeon's slider-crank built by the
// student (visible tests). The oracles are published: the data, the initial state and the
// reference solution at t = 0.1 s of Simeon (1996) and the Test Set for IVP Solvers
// (slider_crank_capstone_checks.hpp). Each check reads the model only through its named bodies,
// the FlexibleExample's rod and the rod's neutral axis, so any equivalent model scores full.
#include "fmbd/slider_crank_capstone.hpp"
#include "grading.hpp"
#include "slider_crank_capstone_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m08;

GRADED_TEST("capstone: crank, full FFRF rod and slider with the published data, no rigid degree of freedom, consistent",
            "[M08][T6][points=2]") {
  check_capstone_structure(flexible_slider_crank_capstone());
}

GRADED_TEST("capstone: the published initial state, with the rod's elastic rates", "[M08][T6][points=2]") {
  const FlexibleExample ex = flexible_slider_crank_capstone();
  if (check_capstone_structure(ex)) check_capstone_start(ex);
}

GRADED_TEST("capstone: the motion to t = 0.1 s against the published reference", "[M08][T6][points=4]") {
  const FlexibleExample ex = flexible_slider_crank_capstone();
  if (check_capstone_structure(ex)) check_capstone_motion(ex);
}

GRADED_TEST("capstone: the energy gained equals the driver's work", "[M08][T6][points=1]") {
  const FlexibleExample ex = flexible_slider_crank_capstone();
  if (check_capstone_structure(ex)) check_capstone_energy(ex);
}
