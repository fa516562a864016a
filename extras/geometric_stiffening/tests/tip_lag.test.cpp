// The quasi-static tip lag that the README ("Two beams") quotes for the benchmark's beams. A
// cantilever of length L on a hub of radius zero, under the angular acceleration theta_ddot of
// the spin-up, carries the transverse load rho A theta_ddot x; a unit load at x moves the tip by
// x^2 (3 L - x) / (6 EI). Integrated here by Gauss quadrature, the lag is compared with the
// closed form 11 rho A L^5 theta_ddot / (120 EI) and with the numbers the README prints; the
// largest theta_ddot is taken from spin_up_profile itself.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "fmbd/flexible_examples.hpp"
#include "grading.hpp"

using namespace fmbd;

namespace {

// Tip lag per unit angular acceleration [m per rad/s^2], by 4-point Gauss quadrature (exact for
// the quartic integrand).
double lag_per_acceleration(double rhoA, double EI, double L) {
  const double x[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  const double w[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  double sum = 0;
  for (int i = 0; i < 4; ++i) {
    const double s = 0.5 * L * (1 + x[i]);
    sum += 0.5 * L * w[i] * rhoA * s * s * s * (3 * L - s) / (6 * EI);
  }
  return sum;
}

// The largest angular acceleration of the spin-up to `rate` in `time` seconds, sampled.
double peak_acceleration(double rate, double time) {
  const DriveFunction profile = spin_up_profile(rate, time);
  double peak = 0;
  for (int i = 0; i <= 3000; ++i) peak = std::max(peak, std::abs(profile(time * i / 3000).fdd));
  return peak;
}

std::string readme() {
  std::ifstream in(FMBD_GEOMETRIC_STIFFENING_README);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string fixed(const char* format, double value) {
  char s[32];
  std::snprintf(s, sizeof s, format, value);
  return s;
}

}  // namespace

TEST_CASE("README: the quasi-static tip lag 11 rho A L^5 theta_ddot / (120 EI) of the benchmark's two beams",
          "[geometric_stiffening][readme]") {
  const SpinUpBeamParameters aluminium;  // the section the README names; its length there is 10 m
  const double L = 10.0, T = 15.0;
  const double rhoA = aluminium.rho * aluminium.A, EI = aluminium.E * aluminium.I;
  const double lag = lag_per_acceleration(rhoA, EI, L), kane = lag_per_acceleration(1.2, 14000.0, L);
  CHECK(std::abs(lag - 11 * rhoA * std::pow(L, 5) / (120 * EI)) < 1e-12 * lag);
  CHECK(std::abs(kane - 11 * 1.2 * std::pow(L, 5) / (120 * 14000.0)) < 1e-12 * kane);
  CHECK(std::abs(peak_acceleration(4.0, T) - 2 * 4.0 / T) < 1e-6);

  const std::string text = readme();
  REQUIRE_FALSE(text.empty());
  const std::string expected[] = {
      "11 ρA L⁵ θ̈ /(120 EI) =",
      fixed("%.1f m per rad/s²", lag),
      fixed("%.1f m at Ω_s = 4 rad/s", lag * peak_acceleration(4.0, T)),
      fixed("%.1f m at 10 rad/s", lag * peak_acceleration(10.0, T)),
      fixed("%.2f m per rad/s²", kane),
      fixed("%.2f m and ", kane * peak_acceleration(4.0, T)) + fixed("%.2f m.", kane * peak_acceleration(10.0, T))};
  for (const std::string& s : expected) {
    INFO("the README should say: " << s);
    CHECK(text.find(s) != std::string::npos);
  }
}
