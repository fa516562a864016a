// Exercise file of module 4, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 4, task T5: the capstone of the rigid half, Andrews' squeezer built with the Model API
// (capstone/README.md).
#include <cmath>
#include <string>

#include "fmbd/errors.hpp"
#include "fmbd/squeezer.hpp"

namespace fmbd {

namespace {

// The unit vectors of squeezer.hpp: e(a) along the angle a, n(a) = e(a - pi/2).
[[maybe_unused]] Vec2 e_of(double a) { return {std::cos(a), std::sin(a)}; }
[[maybe_unused]] Vec2 n_of(double a) { return {std::sin(a), -std::cos(a)}; }

}  // namespace

SqueezerModel andrews_squeezer() {
  // TODO(M04T5): build Andrews' squeezer of the drawing (capstone/README.md, squeezer.hpp):
  //   seven bodies named "body1" ... "body7" with the published masses and centroidal inertias,
  //   each placed at its centroid in the published configuration at t = 0 (add_body's q0); the
  //   points F, E, D, G, H with those names (add_point_at: the drawing gives global positions);
  //   the revolute joints at O, F, E (three joints join the four bodies there), B, A (twice), G
  //   and H; the torque on the crank and the spring from C to D. Return the model, q0 (its
  //   initial guess, consistent when every point was entered at its place) and qd0 = 0.
  //   Stuck? ./workbook hint M04T5
  throw NotImplemented("M04T5 andrews_squeezer");
}

}  // namespace fmbd
