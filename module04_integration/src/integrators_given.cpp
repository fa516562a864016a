#include <cmath>

#include "fmbd/integrators.hpp"

namespace fmbd {

double error_norm(const VecX& error, const VecX& y, const VecX& y_new, double rtol, double atol) {
  if (error.size() == 0) return 0.0;
  const VecX scale = (atol + rtol * y.cwiseAbs().cwiseMax(y_new.cwiseAbs()).array()).matrix();
  return std::sqrt((error.cwiseQuotient(scale)).squaredNorm() / static_cast<double>(error.size()));
}

}  // namespace fmbd
