// Definitions of the hidden module 3 checks (see dynamics_hidden_checks.hpp).
#include "dynamics_hidden_checks.hpp"

#include <cmath>

namespace fmbd::testing::m03 {

namespace {

Vec2 weld_on_coupler() { return Vec2(0.05, 0.04); }
Vec2 weld_on_bob() { return Vec2(-0.03, 0.01); }

}  // namespace

examples::FourBarParameters four_bar_parameters(double a, double b, double c, double d, double theta0,
                                                double omega) {
  examples::FourBarParameters p;
  p.a = a;
  p.b = b;
  p.c = c;
  p.d = d;
  p.theta0 = theta0;
  p.omega = omega;
  return p;
}

VecX four_bar_bob_configuration(const examples::FourBarParameters& p, double theta) {
  Vec2 C;
  if (!examples::four_bar_joint_C(p, theta, C)) return VecX::Constant(12, std::nan(""));
  const Vec2 B(p.a * std::cos(theta), p.a * std::sin(theta)), O4(p.d, 0.0);
  auto link = [](const Vec2& a, const Vec2& b) {
    const Vec2 d = b - a;
    return Vec3(0.5 * (a.x() + b.x()), 0.5 * (a.y() + b.y()), std::atan2(d.y(), d.x()));
  };
  const Vec3 coupler = link(B, C);
  const double phi_bob = coupler(2) + kWeldAngle;
  const Vec2 weld = point_at(coupler, weld_on_coupler());
  const Vec2 R_bob = weld - rotate(phi_bob, weld_on_bob());
  VecX q(12);
  q << Vec3(B.x() / 2, B.y() / 2, theta), coupler, link(C, O4), R_bob.x(), R_bob.y(), phi_bob;
  return q;
}

Model four_bar_with_bob(const examples::FourBarParameters& p) {
  Model m = examples::four_bar(p);
  const VecX q0 = four_bar_bob_configuration(p, p.theta0);
  const BodyId bob = m.add_body("bob", 0.6, 0.004, q0.segment<3>(9));
  m.add_fixed("weld", m.add_point(m.find_body("coupler"), weld_on_coupler(), "coupler weld"),
              m.add_point(bob, weld_on_bob(), "bob weld"), kWeldAngle);
  m.set_gravity(Vec2(0.0, -9.81));
  m.add_rsda("rocker spring", ground, m.find_body("rocker"), 6.0, 1.2, 0.0);
  m.add_rsda("knee", m.find_body("coupler"), m.find_body("crank"), 1.5, 0.0, 0.05,
             DriveFunction::harmonic(0.0, 0.3, 2.0));
  return m;
}

}  // namespace fmbd::testing::m03
