#include <algorithm>
#include <cmath>

#include "fmbd/integrators.hpp"

namespace fmbd {

double error_norm(const Eigen::Ref<const VecX>& error, const Eigen::Ref<const VecX>& y,
                  const Eigen::Ref<const VecX>& y_new, double rtol, double atol) {
  if (error.size() == 0) return 0.0;
  double sum = 0.0;
  for (Eigen::Index k = 0; k < error.size(); ++k) {
    const double scale = atol + rtol * std::max(std::abs(y(k)), std::abs(y_new(k)));
    sum += (error(k) / scale) * (error(k) / scale);
  }
  return std::sqrt(sum / static_cast<double>(error.size()));
}

namespace {

// f as a right-hand side that writes into dy.
OdeRhsInto into(const OdeRhs& f) {
  return [&f](double t, const VecX& y, VecX& dy) { dy = f(t, y); };
}

}  // namespace

VecX euler_step(const OdeRhs& f, double t, const VecX& y, double h) {
  Stages stages;
  VecX y_new;
  euler_step(into(f), t, y, h, stages, y_new);
  return y_new;
}

VecX rk4_step(const OdeRhs& f, double t, const VecX& y, double h) {
  Stages stages;
  VecX y_new;
  rk4_step(into(f), t, y, h, stages, y_new);
  return y_new;
}

EmbeddedStep dormand_prince_step(const OdeRhs& f, double t, const VecX& y, double h) {
  Stages stages;
  EmbeddedStep step;
  dormand_prince_step(into(f), t, y, h, stages, step);
  return step;
}

}  // namespace fmbd
