// Module 1, task T6 (hidden): assemblies of random chains of many bodies, every joint type between
// random pairs and with the ground on either side, in storage reused across models' calls.
#include <string>
#include <vector>

#include "fmbd/constraints.hpp"
#include "kinematics_checks.hpp"

using namespace fmbd;
using namespace fmbd::m01;

namespace {

// n bodies; joint k between bodies (or the ground) drawn at random, of type k mod 7.
Model random_model(int n, testing::Random& random) {
  Model m;
  std::vector<BodyId> bodies;
  for (int k = 0; k < n; ++k) bodies.push_back(m.add_body("b" + std::to_string(k), 1, 1));
  const auto any = [&](bool allow_ground) {
    const int k = static_cast<int>(random.uniform(allow_ground ? -1.0 : 0.0, n - 1e-9));
    return k < 0 ? ground : bodies[static_cast<std::size_t>(k)];
  };
  int points = 0;
  const auto point = [&](BodyId b) { return m.add_point(b, random.vec2(-0.5, 0.5), "p" + std::to_string(points++)); };
  // Drivers drive distinct quantities (the builder refuses two drivers of one quantity).
  const auto body = [&](int k, int shift) { return bodies[static_cast<std::size_t>((k / 7 + shift) % n)]; };
  for (int k = 0; k < 2 * n; ++k) {
    BodyId i = any(true), j = any(true);
    while (j.index == i.index) j = any(true);
    const std::string name = "c" + std::to_string(k);
    switch (k % 7) {
      case 0: m.add_revolute(name, point(i), point(j)); break;
      case 1: m.add_translational(name, point(i), point(j), random.vec2(0.2, 1.0)); break;
      case 2: m.add_fixed(name, point(i), point(j), random.uniform(-1, 1)); break;
      case 3: m.add_absolute_angle_driver(name, body(k, 0), DriveFunction::polynomial({0.1, 0.3, -0.2})); break;
      case 4: m.add_relative_angle_driver(name, body(k, 0), body(k, 1), DriveFunction::polynomial({0.2, -0.4})); break;
      case 5: m.add_point_coordinate_driver(name, point(any(false)), Axis::y, DriveFunction::polynomial({0.3, 0.5})); break;
      default: m.add_distance_driver(name, point(i), point(j), DriveFunction::polynomial({1.0, 0.2, 0.1})); break;
    }
  }
  return m;
}

}  // namespace

GRADED_TEST("assembly: random models of 2 to 12 bodies with every constraint type", "[M01][T6][points=2]") {
  testing::Random random(613);
  for (int n : {2, 3, 5, 8, 12}) {
    const Model m = random_model(n, random);
    ConstraintEvaluation out = constraint_storage(m);
    bool ok = true;
    for (int k = 0; k < 3 && ok; ++k) {
      ok = check_assembly(m, random.vector(m.num_coordinates(), -2.0, 2.0), random.uniform(0.0, 3.0), out,
                          std::to_string(n) + " bodies, " + std::to_string(m.num_constraints()) + " equations");
    }
    if (!ok) break;
  }
}
