#include "fmbd/examples.hpp"

#include <cmath>
#include <stdexcept>

namespace fmbd::examples {

namespace {

// Coordinates (x, y, phi) of a link from end point a to end point b, centroid at mid-length.
Vec3 link_between(const Vec2& a, const Vec2& b) {
  const Vec2 mid = 0.5 * (a + b), d = b - a;
  return Vec3(mid.x(), mid.y(), std::atan2(d.y(), d.x()));
}

}  // namespace

SliderCrankClosedForm slider_crank_closed_form(double r, double l, double A) {
  const double s = std::sin(A), c = std::cos(A);
  const double w = l * l - r * r * s * s;  // (l^2 - r^2 sin^2 A)
  const double root = std::sqrt(w);
  const double dw = -2 * r * r * s * c;
  const double d2w = -2 * r * r * (c * c - s * s);
  return {r * c + root, -r * s + dw / (2 * root), -r * c + d2w / (2 * root) - dw * dw / (4 * w * root)};
}

VecX slider_crank_configuration(const SliderCrankParameters& p, double A) {
  const Vec2 B(p.r * std::cos(A), p.r * std::sin(A));
  const Vec2 C(slider_crank_closed_form(p.r, p.l, A).x, 0.0);
  VecX q(9);
  q << link_between(Vec2::Zero(), B), link_between(B, C), C.x(), C.y(), 0.0;
  q(2) = A;  // the crank angle itself, not wrapped to (-pi, pi]: the driver prescribes A
  return q;
}

Model slider_crank(const SliderCrankParameters& p) {
  if (!(p.r > 0) || !(p.l > p.r))
    throw std::invalid_argument("slider_crank: needs 0 < r < l, got r = " + std::to_string(p.r) +
                                ", l = " + std::to_string(p.l));
  const VecX q0 = slider_crank_configuration(p, p.A0);
  Model m;
  const BodyId crank = m.add_body("crank", 1.0, 1.0 / 12 * p.r * p.r, q0.segment<3>(0));
  const BodyId rod = m.add_body("rod", 2.0, 2.0 / 12 * p.l * p.l, q0.segment<3>(3));
  const BodyId slider = m.add_body("slider", 1.5, 0.01, q0.segment<3>(6));

  const PointId O = m.add_point(ground, Vec2::Zero(), "O");
  const PointId O_crank = m.add_point(crank, Vec2(-p.r / 2, 0), "crank O");
  const PointId B_crank = m.add_point(crank, Vec2(p.r / 2, 0), "crank B");
  const PointId B_rod = m.add_point(rod, Vec2(-p.l / 2, 0), "rod B");
  const PointId C_rod = m.add_point(rod, Vec2(p.l / 2, 0), "rod C");
  const PointId C_slider = m.add_point(slider, Vec2::Zero(), "slider C");

  m.add_revolute("O", O, O_crank);
  m.add_revolute("B", B_crank, B_rod);
  m.add_revolute("C", C_rod, C_slider);
  m.add_translational("slider guide", O, C_slider, Vec2::UnitX());
  if (p.driven) m.add_absolute_angle_driver("crank angle", crank, DriveFunction::linear(p.A0, p.omega));
  return m;
}

bool four_bar_joint_C(const FourBarParameters& p, double theta, Vec2& C) {
  const Vec2 B(p.a * std::cos(theta), p.a * std::sin(theta)), O4(p.d, 0.0);
  // C is where the circle of radius b about B meets the circle of radius c about O4.
  const Vec2 BO4 = O4 - B;
  const double e = BO4.norm();
  if (e > p.b + p.c || e < std::abs(p.b - p.c) || e == 0.0) return false;
  const double along = (p.b * p.b - p.c * p.c + e * e) / (2 * e);
  const double h = std::sqrt(std::max(0.0, p.b * p.b - along * along));
  const Vec2 u = BO4 / e;
  C = B + along * u + h * Vec2(-u.y(), u.x());  // open branch: C to the left of B -> O4
  return true;
}

Model four_bar(const FourBarParameters& p) {
  if (!(p.a > 0 && p.b > 0 && p.c > 0 && p.d > 0))
    throw std::invalid_argument("four_bar: all link lengths must be positive");
  const Vec2 O2 = Vec2::Zero(), O4(p.d, 0.0);
  const Vec2 B(p.a * std::cos(p.theta0), p.a * std::sin(p.theta0));
  Vec2 C;
  if (!four_bar_joint_C(p, p.theta0, C)) C = B + Vec2(p.b, 0.0);  // rough guess; cannot close

  Vec3 q_crank = link_between(O2, B);
  q_crank(2) = p.theta0;  // not wrapped: the driver prescribes theta0 + omega t

  Model m;
  const BodyId crank = m.add_body("crank", 1.0, 1.0 / 12 * p.a * p.a, q_crank);
  const BodyId coupler = m.add_body("coupler", 2.0, 2.0 / 12 * p.b * p.b, link_between(B, C));
  const BodyId rocker = m.add_body("rocker", 1.5, 1.5 / 12 * p.c * p.c, link_between(C, O4));

  const PointId O2_ground = m.add_point(ground, O2, "O2");
  const PointId O4_ground = m.add_point(ground, O4, "O4");
  const PointId O2_crank = m.add_point(crank, Vec2(-p.a / 2, 0), "crank O2");
  const PointId B_crank = m.add_point(crank, Vec2(p.a / 2, 0), "crank B");
  const PointId B_coupler = m.add_point(coupler, Vec2(-p.b / 2, 0), "coupler B");
  const PointId C_coupler = m.add_point(coupler, Vec2(p.b / 2, 0), "coupler C");
  const PointId C_rocker = m.add_point(rocker, Vec2(-p.c / 2, 0), "rocker C");
  const PointId O4_rocker = m.add_point(rocker, Vec2(p.c / 2, 0), "rocker O4");

  m.add_revolute("O2", O2_ground, O2_crank);
  m.add_revolute("B", B_crank, B_coupler);
  m.add_revolute("C", C_coupler, C_rocker);
  m.add_revolute("O4", O4_rocker, O4_ground);
  if (p.driven) m.add_absolute_angle_driver("crank angle", crank, DriveFunction::linear(p.theta0, p.omega));
  return m;
}

}  // namespace fmbd::examples
