#pragma once
// Fixed steps across a singular position (given code, module 4): where C_q loses rank for an
// instant (a linkage that lies flat), simulate() places its fixed steps so that no evaluation of
// the model comes close to that instant.
//
// Why: near the instant t_c the smallest singular value of C_q falls linearly, sigma ~ a |t - t_c|,
// and the augmented system amplifies whatever in a state is not consistent with the constraints
// by 1/sigma. A stage of RK4 lies off the constraint manifold by O(h^2) by construction, and a
// projected state by round-off; the direction across the branch, which C_q barely sees there,
// turns that into a spurious acceleration. A stage or a projection within a small fraction of a
// step from t_c (a matter of chance: where the grid happens to fall) can change the energy by
// more than the whole run's truncation error, or lock the linkage (module 4 README, section 4).
//
// How: every evaluation reports Accelerations::rank_margin (sigma_min / sigma_max of the unit-free
// C_q). From the last two evaluations at distinct times, a margin that falls predicts t_c by
// linear extrapolation. When the next step would come within a safe distance d of t_c, the step
// stops at t_c - d, and the one after it spans the instant with t_c at a quarter of its length:
// its stages lie at t_c - d, t_c + d and t_c + 3d, none closer than d. The steps after it return to
// the grid t0 + j h. d keeps the margin at kSafeMargin where it can (d = kSafeMargin / a), at least
// a quarter of a step and at most two: below that the steps across the instant do not change as
// the step shrinks. The spanning step is up to 8.5 steps long, and it is not taken again in
// halves (a half would end at the instant). A margin that does not fall (no singular position, or
// a redundant constraint that is always dependent, margin 0), or that stays above kWatch, changes
// nothing.

#include <cmath>

namespace fmbd {

class SingularInstant {
 public:
  /// The smallest margin a fixed step aims to keep from a rank loss.
  static constexpr double kSafeMargin = 1e-3;
  /// Margins above this do not foretell a rank loss (a well-conditioned C_q whose margin varies).
  static constexpr double kWatch = 0.05;

  /// The end of a step, and whether the step spans a rank loss.
  struct Step {
    double end;
    bool spans = false;
    double instant = 0.0;  ///< where it spans: the predicted instant of the rank loss
  };

  /// For the fixed steps of size `step` of a run from t0.
  SingularInstant(double t0, double step) : t0_(t0), h_(step) {}

  /// The rank margin of an evaluation at time t. Several may come at the same time (the latest
  /// counts); one before the latest time is ignored (a look back: the extension of a step to an
  /// output point, or a step taken again in halves).
  void observe(double t, double margin);

  /// The step that starts at t and would end at t_grid: t_grid where no rank loss is near; an
  /// earlier end where the step stops short of one; a later one where the step spans it.
  Step step_from(double t, double t_grid) const;

  /// The grid point a step from t aims for: the first t0 + j h at least a sixteenth of a step
  /// after t.
  double next_grid_point(double t) const;

 private:
  const double t0_, h_;
  double t_last_ = -HUGE_VAL, margin_last_ = 1.0;      // the latest evaluation
  double t_before_ = -HUGE_VAL, margin_before_ = 1.0;  // the latest one at an earlier time
};

}  // namespace fmbd
