// Module 4, task T5: the capstone of the rigid half, Andrews' squeezer built by the student
// (visible tests). The oracles are published (Hairer and Wanner's configuration and multipliers
// at t = 0, the Test Set for IVP Solvers' reference at t = 0.03 s) and the position analysis by
// circle intersections (squeezer_checks.hpp). Each check reads the model only through its named
// bodies and points, so any equivalent model scores full.
#include "fmbd/squeezer.hpp"
#include "grading.hpp"
#include "squeezer_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m04;

GRADED_TEST("squeezer: seven named bodies with the published masses, one degree of freedom, consistent at rest",
            "[M04][T5][points=2]") {
  check_squeezer_structure(andrews_squeezer());
}

GRADED_TEST("squeezer: the points F, E, D, G, H where the published configuration puts them", "[M04][T5][points=1]") {
  const SqueezerModel s = andrews_squeezer();
  if (check_squeezer_structure(s)) check_squeezer_start(s);
}

GRADED_TEST("squeezer: position analysis over a turn of the crank against circle intersections",
            "[M04][T5][points=2]") {
  const SqueezerModel s = andrews_squeezer();
  if (check_squeezer_structure(s)) check_squeezer_positions(s, {0.5, 1.7, 3.0, 4.4, 5.9});
}

GRADED_TEST("squeezer: accelerations and the reactions at E and B at t = 0 against the published multipliers",
            "[M04][T5][points=2]") {
  const SqueezerModel s = andrews_squeezer();
  if (check_squeezer_structure(s)) check_squeezer_reactions(s);
}

GRADED_TEST("squeezer: the motion to t = 0.03 s against the published reference, and its energy",
            "[M04][T5][points=3]") {
  const SqueezerModel s = andrews_squeezer();
  if (check_squeezer_structure(s)) check_squeezer_motion(s);
}
