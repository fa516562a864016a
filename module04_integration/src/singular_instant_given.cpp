#include "fmbd/singular_instant.hpp"

#include <algorithm>

namespace fmbd {

void SingularInstant::observe(double t, double margin) {
  if (t < t_last_) return;  // a look back: an output point's extension, a step taken again
  if (t > t_last_) {
    t_before_ = t_last_;
    margin_before_ = margin_last_;
  }
  t_last_ = t;
  margin_last_ = margin;
}

SingularInstant::Step SingularInstant::step_from(double t, double t_grid) const {
  const Step plain{t_grid};
  if (!(t_before_ > -HUGE_VAL) || !(margin_last_ < margin_before_) || !(margin_last_ < kWatch)) return plain;
  const double slope = (margin_before_ - margin_last_) / (t_last_ - t_before_);  // a of sigma ~ a |t - t_c|
  const double t_c = t_last_ + margin_last_ / slope;
  const double d = std::clamp(kSafeMargin / slope, h_ / 4, 2 * h_);
  if (t_c > t_grid + d) return plain;         // the step ends at least d before the instant
  if (t_c - t > d + h_ / 8) return {t_c - d};  // stops d short of it
  const double lead = t_c - t;                 // the step starts within d + h / 8 of it
  if (lead < h_ / 16) return plain;            // too late to step over it
  return {t_c + 3 * lead, true, t_c};           // t_c at a quarter of the step
}

double SingularInstant::next_grid_point(double t) const {
  double j = std::floor((t - t0_) / h_) + 1;
  while (t0_ + j * h_ - t < h_ / 16) ++j;
  return t0_ + j * h_;
}

}  // namespace fmbd
