#include "fmbd/drive_function.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace fmbd {

DriveFunction::DriveFunction(std::function<DriveValue(double)> function, std::string description)
    : function_(std::move(function)), description_(std::move(description)) {}

DriveFunction DriveFunction::constant(double value) {
  return polynomial({value});
}

DriveFunction DriveFunction::linear(double f0, double rate) {
  return polynomial({f0, rate});
}

DriveFunction DriveFunction::polynomial(std::vector<double> c) {
  std::ostringstream text;
  text << "polynomial of degree " << (c.empty() ? 0 : c.size() - 1);
  return DriveFunction(
      [c = std::move(c)](double t) {
        DriveValue v;  // Horner's scheme for f, f', f''
        for (auto k = c.size(); k-- > 0;) {
          v.fdd = v.fdd * t + 2 * v.fd;
          v.fd = v.fd * t + v.f;
          v.f = v.f * t + c[k];
        }
        return v;
      },
      text.str());
}

DriveFunction DriveFunction::harmonic(double offset, double amplitude, double omega, double phase) {
  return DriveFunction(
      [=](double t) {
        const double s = std::sin(omega * t + phase), c = std::cos(omega * t + phase);
        return DriveValue{offset + amplitude * s, amplitude * omega * c, -amplitude * omega * omega * s};
      },
      "harmonic");
}

DriveFunction DriveFunction::smooth_step(double f0, double f1, double t0, double t1) {
  if (!(t1 > t0)) throw std::invalid_argument("DriveFunction::smooth_step: needs t1 > t0");
  return DriveFunction(
      [=](double t) {
        const double T = t1 - t0, h = f1 - f0;
        if (t <= t0) return DriveValue{f0, 0.0, 0.0};
        if (t >= t1) return DriveValue{f1, 0.0, 0.0};
        const double s = (t - t0) / T;  // 10 s^3 - 15 s^4 + 6 s^5
        return DriveValue{f0 + h * s * s * s * (10 - 15 * s + 6 * s * s),
                          h / T * 30 * s * s * (1 - s) * (1 - s),
                          h / (T * T) * 60 * s * (1 - s) * (1 - 2 * s)};
      },
      "smooth step");
}

DriveFunction DriveFunction::custom(std::function<DriveValue(double)> function, std::string description) {
  if (!function) throw std::invalid_argument("DriveFunction::custom: empty function");
  return DriveFunction(std::move(function), std::move(description));
}

}  // namespace fmbd
