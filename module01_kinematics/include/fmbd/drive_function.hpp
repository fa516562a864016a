#pragma once
// Drive functions f(t) of kinematic drivers, with their first and second time derivatives.
// A driver constraint reads C = (measured quantity) - f(t) = 0, so C_t = -f'(t) and the
// acceleration equation needs f''(t) (module 2).

#include <functional>
#include <string>
#include <vector>

namespace fmbd {

/// f(t), f'(t) = df/dt and f''(t) = d2f/dt2 at one instant.
struct DriveValue {
  double f = 0.0;
  double fd = 0.0;
  double fdd = 0.0;
};

/// A smooth function of time. Build one with the named constructors.
class DriveFunction {
 public:
  /// f(t) = value.
  static DriveFunction constant(double value);
  /// f(t) = c0 + c1 t + c2 t^2 + ... (coefficients in increasing powers).
  static DriveFunction polynomial(std::vector<double> coefficients);
  /// f(t) = f0 + rate t: constant speed, e.g. a crank turning at omega rad/s.
  static DriveFunction linear(double f0, double rate);
  /// f(t) = offset + amplitude sin(omega t + phase).
  static DriveFunction harmonic(double offset, double amplitude, double omega, double phase = 0.0);
  /// f rises from f0 at t0 to f1 at t1 along the quintic 10s^3 - 15s^4 + 6s^5 (s = (t-t0)/(t1-t0)),
  /// with zero velocity and acceleration at both ends; constant outside [t0, t1]. Needs t1 > t0.
  static DriveFunction smooth_step(double f0, double f1, double t0, double t1);
  /// Any user function returning (f, f', f'') at t; `description` appears in messages.
  static DriveFunction custom(std::function<DriveValue(double)> function, std::string description);

  DriveValue operator()(double t) const { return function_(t); }
  const std::string& description() const { return description_; }

 private:
  DriveFunction(std::function<DriveValue(double)> function, std::string description);
  std::function<DriveValue(double)> function_;
  std::string description_;
};

}  // namespace fmbd
