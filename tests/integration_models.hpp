#pragma once
// The models that the project tests of simulate() share (integration.test.cpp,
// integration_units.test.cpp).
#include <cmath>

#include "fmbd/model.hpp"

namespace fmbd::integration_testing {

inline constexpr double kG = 9.81;

// A uniform rod (m = 1, L = 1) hinged at one end to the ground at the origin, optionally with a
// constant motor torque.
struct Rod {
  Model model;
  explicit Rod(double torque = 0.0) {
    model.set_gravity(Vec2(0, -kG));
    const BodyId rod = model.add_body("rod", 1.0, 1.0 / 12, Vec3(0.5, 0, 0));
    model.add_revolute("pivot", model.add_point(ground, Vec2::Zero(), "O"), model.add_point(rod, Vec2(-0.5, 0), "end"));
    if (torque != 0.0) model.add_torque("motor", rod, DriveFunction::constant(torque));
  }
  static VecX q(double phi) { return (VecX(3) << 0.5 * std::cos(phi), 0.5 * std::sin(phi), phi).finished(); }
  static VecX qd(double phi, double w) {
    return (VecX(3) << -0.5 * w * std::sin(phi), 0.5 * w * std::cos(phi), w).finished();
  }
};

}  // namespace fmbd::integration_testing
