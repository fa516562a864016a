// Module 1, task T5 (hidden): smooth-step drives and their ends, phi near +-pi, coinciding
// points of the distance driver, the ground on side i.
#include <cmath>

#include "fmbd/constraints.hpp"
#include "fmbd/drivers.hpp"
#include "kinematics_checks.hpp"

using namespace fmbd;
using namespace fmbd::m01;

GRADED_TEST("point coordinate driver: phi near plus or minus pi and a smooth step drive", "[M01][T5][points=1]") {
  const DriveFunction f = DriveFunction::smooth_step(-0.3, 0.5, 0.5, 1.5);
  const Vec2 s(0.4, -0.25);
  // One (phi, t, axis) case; false if any check failed.
  auto check = [&](double phi, double t, Axis axis) {
    const Vec3 q(0.3, -0.8, phi);
    const DriveValue v = f(t);
    const int c = axis == Axis::x ? 0 : 1;
    INFO("q_i = " << show(q) << ", s_i = " << show(s) << ", axis " << (c == 0 ? "x" : "y") << ", t = " << t
                  << ", smooth step from -0.3 at t = 0.5 to 0.5 at t = 1.5");
    const ConstraintBlock b = point_coordinate_constraint(q, s, axis, v);
    REQUIRE(b.C.size() == 1);
    const double C = (q.head<2>() + rot(phi) * s)(c) - v.f;
    CHECK_NEAR_NAMED("your C of the point-coordinate driver", b.C(0), C, kExact, hint::driver_C);
    const BlockDifferences fd = block_differences(
        [&](const Vec3& x, const Vec3&) { return point_coordinate_constraint(x, s, axis, v); }, q, Vec3::Zero());
    CHECK_CLOSE_NAMED("your C_q of body i", b.Cq_i, fd.Cq_i, kFD, hint::coordinate_Cq);
    // At t0 and t1 the drive rests (f' = 0 on both sides), so central differences work there too.
    const VecX Ct = time_difference([&](const DriveValue& w) { return point_coordinate_constraint(q, s, axis, w); }, f, t);
    CHECK_CLOSE_NAMED("your C_t of the point-coordinate driver", b.Ct, Ct, kFD, hint::driver_Ct);
    return testing::compare(testing::as_matrix(b.C(0)), testing::as_matrix(C), kExact).ok &&
           testing::compare(b.Cq_i, fd.Cq_i, kFD).ok && testing::compare(b.Ct, Ct, kFD).ok;
  };
  bool ok = true;
  for (double phi : {kPi - 1e-6, -kPi + 1e-6, kPi + 0.2, -25.0})
    for (double t : {0.2, 0.5, 0.8, 1.0, 1.3, 1.5, 2.0})
      for (Axis axis : {Axis::x, Axis::y})
        if (ok) ok = check(phi, t, axis);
}

GRADED_TEST("distance driver: coinciding points and the ground on side i", "[M01][T5][points=1]") {
  const DriveFunction f = DriveFunction::harmonic(0.5, 0.2, 3.0, 1.0);
  // Coinciding points: d = 0, so C = -f^2 / 2 and C_q = 0 (the squared form stays smooth).
  const Vec3 q_i(0.2, 0.1, 0.4);
  const Vec2 s_i(0.3, -0.2), s_j(-0.1, 0.25);
  const Vec3 q_j = place(q_i.head<2>() + rot(q_i(2)) * s_i, s_j, -2.0);
  for (double t : {0.0, 0.4, 1.1}) {
    const DriveValue v = f(t);
    INFO("coinciding points, t = " << t);
    const ConstraintBlock b = distance_constraint(q_i, s_i, q_j, s_j, v);
    REQUIRE(b.C.size() == 1);
    CHECK_NEAR_NAMED("your C of the distance driver, points coinciding",
                     b.C(0), -0.5 * v.f * v.f, kGeometry, hint::distance_C);
    CHECK_CLOSE_NAMED("your C_q of body i, points coinciding",
                      b.Cq_i, Eigen::RowVector3d::Zero(), kGeometry, hint::distance_Cq);
    CHECK_CLOSE_NAMED("your C_q of body j, points coinciding",
                      b.Cq_j, Eigen::RowVector3d::Zero(), kGeometry, hint::distance_Cq);
    const VecX Ct = time_difference([&](const DriveValue& w) { return distance_constraint(q_i, s_i, q_j, s_j, w); }, f, t);
    CHECK_CLOSE_NAMED("your C_t of the distance driver, points coinciding", b.Ct, Ct, kFD, hint::distance_Ct);
  }
  // A distance driver and a relative-angle driver with the ground on side i, in a model.
  Model m;
  const BodyId b = m.add_body("b", 1, 1);
  const PointId pg = m.add_point(ground, Vec2(-0.4, 0.3), "anchor");
  const PointId pb = m.add_point(b, Vec2(0.2, 0.2), "tip");
  m.add_distance_driver("cable", pg, pb, DriveFunction::polynomial({0.5, -0.3, 0.2}));
  m.add_relative_angle_driver("turn", ground, b, DriveFunction::smooth_step(0.0, 1.0, 0.0, 2.0));
  testing::Random random(1501);
  for (int k = 0; k < 6; ++k) {
    const VecX q = random.vector(3, -1.5, 1.5);
    if (!check_model_derivatives(m, q, random.uniform(0.1, 1.9))) break;
  }
  // Where the distance is met exactly, C = 0: put the tip at distance f(t) from the anchor.
  const double t = 0.7, L = 0.5 - 0.3 * t + 0.2 * t * t, phi = f(t).f;  // any angle will do
  const VecX q = place(Vec2(-0.4, 0.3) + L * Vec2(std::cos(1.0), std::sin(1.0)), Vec2(0.2, 0.2), phi);
  CHECK_NEAR_NAMED("your C of the cable's distance driver, its length met",
                   kernel_evaluation(m, q, t).C(0), 0.0, kGeometry, hint::distance_C);
}
