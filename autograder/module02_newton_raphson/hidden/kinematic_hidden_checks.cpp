// Definitions of the hidden module 2 checks (see kinematic_hidden_checks.hpp).
#include "kinematic_hidden_checks.hpp"

#include <cmath>

namespace fmbd::testing::m02 {

VecX ArmCollar::exact(double t) const {
  const double phi = std::asin(tip_y(t).f / (2 * h)), rho = radius(t).f;
  VecX q(6);
  q << h * std::cos(phi), h * std::sin(phi), phi, rho * std::cos(phi), rho * std::sin(phi), phi;
  return q;
}

ArmCollar arm_collar(double h, DriveFunction tip_y, DriveFunction radius, double t_guess) {
  ArmCollar a{Model{}, h, tip_y, radius};
  const VecX q0 = a.exact(t_guess);
  Model& m = a.model;
  const BodyId arm = m.add_body("arm", 1.0, 0.02, q0.segment<3>(0));
  const BodyId collar = m.add_body("collar", 0.5, 0.001, q0.segment<3>(3));
  const PointId O = m.add_point(ground, Vec2::Zero(), "O");
  const PointId arm_O = m.add_point(arm, Vec2(-h, 0.0), "arm pivot");
  const PointId arm_tip = m.add_point(arm, Vec2(h, 0.0), "arm tip");
  const PointId collar_c = m.add_point(collar, Vec2::Zero(), "collar centre");
  m.add_revolute("pivot", O, arm_O);
  m.add_translational("collar guide", arm_O, collar_c, Vec2::UnitX());
  m.add_point_coordinate_driver("tip height", arm_tip, Axis::y, tip_y);
  m.add_distance_driver("collar radius", O, collar_c, radius);
  return a;
}

}  // namespace fmbd::testing::m02
