// Exercise file of module 8, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 8, task T6: the capstone of the flexible half, Simeon's flexible slider-crank
// (capstone/README.md).
#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>
#include <memory>
#include <vector>

#include "fmbd/constraints.hpp"
#include "fmbd/craig_bampton.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/fe_assembly.hpp"
#include "fmbd/ffrf.hpp"
#include "fmbd/slider_crank_capstone.hpp"

namespace fmbd {

FlexibleExample flexible_slider_crank_capstone() {
  // TODO(M08T6): build Simeon's slider-crank (capstone/README.md, slider_crank_capstone.hpp):
  //   the rod as a beam FE model (module 5) reduced by a basis of your choice (module 6) into a
  //   full FFRF body (make_ffrf_body); the crank with its inertia about O, the rod and the point
  //   mass slider, named "crank", "rod" and "slider"; the pins at the rod's end nodes, the slider
  //   on the x axis and the crank driven at omega. Then the published initial state: the rod's
  //   elastic coordinates and rates that carry the published fields u, w and their rates at t = 0
  //   (your basis holds them only approximately: fit them), the frames that close the joints
  //   with them, and the rigid rates from the velocity equation. Return the FlexibleExample.
  //   Stuck? ./workbook hint M08T6
  throw NotImplemented("M08T6 flexible_slider_crank_capstone");
}

}  // namespace fmbd
