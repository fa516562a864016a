// Reference solution (fixture for the mutate tests).
#include "joints.hpp"

namespace fmbd {

Vec2 revolute_jacobian_column(const Vec2& q, const Vec2& s) {
    const Vec2 dr_dphi = rotation_derivative(q(2)) * s;
    return dr_dphi;
}

double residual(double x) {
  double r = x * x;
  r -= 2.0;
  return r;
}

double twin_a(double x) {
  return x + 1.0;
}

double twin_b(double x) {
  return x + 1.0;
}

}  // namespace fmbd
