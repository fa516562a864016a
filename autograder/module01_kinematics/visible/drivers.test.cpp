// Module 1, task T5: the four driver types, block by block and assembled in a model.
#include <cmath>

#include "fmbd/drivers.hpp"
#include "kinematics_checks.hpp"

using namespace fmbd;
using namespace fmbd::m01;

namespace {

// C_q of a one-row driver block against central differences (body j only if `two_bodies`).
bool check_driver_jacobian(const BlockOfQ& block, const Vec3& q_i, const Vec3& q_j, bool two_bodies,
                           const Hint& hint_q) {
  const ConstraintBlock b = block(q_i, q_j);
  const BlockDifferences fd = block_differences(block, q_i, q_j);
  CHECK_CLOSE_NAMED("your C_q of body i", b.Cq_i, fd.Cq_i, kFD, hint_q);
  bool ok = testing::compare(b.Cq_i, fd.Cq_i, kFD).ok;
  if (two_bodies) {
    CHECK_CLOSE_NAMED("your C_q of body j", b.Cq_j, fd.Cq_j, kFD, hint_q);
    ok = ok && testing::compare(b.Cq_j, fd.Cq_j, kFD).ok;
  }
  return ok;
}

}  // namespace

GRADED_TEST("angle drivers: C C_q and C_t of the absolute and relative angle drivers", "[M01][T5][points=1]") {
  testing::Random random(501);
  const DriveFunction f = DriveFunction::harmonic(0.4, 0.8, 2.5, 0.3);
  for (int k = 0; k < 15; ++k) {
    const Vec3 q_i = random.vec3(-2, 2), q_j = random.vec3(-2, 2);
    const double t = random.uniform(0, 3);
    const DriveValue v = f(t);
    INFO("q_i = " << show(q_i) << ", q_j = " << show(q_j) << ", t = " << t << ", f = harmonic 0.4 + 0.8 sin(2.5 t + 0.3)");

    const ConstraintBlock a = absolute_angle_constraint(q_i, v);
    REQUIRE(a.C.size() == 1);
    CHECK_NEAR_NAMED("your C of the absolute-angle driver", a.C(0), q_i(2) - v.f, kExact, hint::driver_C);
    const bool ok_a = check_driver_jacobian(
        [&](const Vec3& x, const Vec3&) { return absolute_angle_constraint(x, v); }, q_i, q_j, false,
        hint::absolute_Cq);
    const VecX Ct_a = time_difference([&](const DriveValue& w) { return absolute_angle_constraint(q_i, w); }, f, t);
    CHECK_CLOSE_NAMED("your C_t of the absolute-angle driver", a.Ct, Ct_a, kFD, hint::driver_Ct);

    const ConstraintBlock r = relative_angle_constraint(q_i, q_j, v);
    REQUIRE(r.C.size() == 1);
    CHECK_NEAR_NAMED("your C of the relative-angle driver", r.C(0), q_j(2) - q_i(2) - v.f, kExact, hint::driver_C);
    const bool ok_r = check_driver_jacobian(
        [&](const Vec3& x, const Vec3& y) { return relative_angle_constraint(x, y, v); }, q_i, q_j, true,
        hint::relative_Cq);
    const VecX Ct_r = time_difference([&](const DriveValue& w) { return relative_angle_constraint(q_i, q_j, w); }, f, t);
    CHECK_CLOSE_NAMED("your C_t of the relative-angle driver", r.Ct, Ct_r, kFD, hint::driver_Ct);
    if (!ok_a || !ok_r || !testing::compare(a.Ct, Ct_a, kFD).ok || !testing::compare(r.Ct, Ct_r, kFD).ok) break;
  }
}

GRADED_TEST("point coordinate driver: C C_q and C_t match the definition and finite differences",
            "[M01][T5][points=1]") {
  testing::Random random(502);
  const DriveFunction f = DriveFunction::polynomial({0.2, -0.7, 0.45, 0.1});
  for (int k = 0; k < 15; ++k) {
    const Vec3 q_i = random.vec3(-2, 2);
    const Vec2 s_i = random.vec2(-1, 1);
    const double t = random.uniform(-1, 2);
    const DriveValue v = f(t);
    const Vec2 r_P = q_i.head<2>() + rot(q_i(2)) * s_i;
    bool ok = true;
    for (Axis axis : {Axis::x, Axis::y}) {
      const int c = axis == Axis::x ? 0 : 1;
      INFO("q_i = " << show(q_i) << ", s_i = " << show(s_i) << ", axis " << (c == 0 ? "x" : "y") << ", t = " << t
                    << ", f = 0.2 - 0.7 t + 0.45 t^2 + 0.1 t^3");
      const ConstraintBlock b = point_coordinate_constraint(q_i, s_i, axis, v);
      REQUIRE(b.C.size() == 1);
      CHECK_NEAR_NAMED("your C of the point-coordinate driver", b.C(0), r_P(c) - v.f, kExact, hint::driver_C);
      ok = check_driver_jacobian([&](const Vec3& x, const Vec3&) { return point_coordinate_constraint(x, s_i, axis, v); },
                                 q_i, Vec3::Zero(), false, hint::coordinate_Cq) && ok;
      const VecX Ct = time_difference([&](const DriveValue& w) { return point_coordinate_constraint(q_i, s_i, axis, w); },
                                      f, t);
      CHECK_CLOSE_NAMED("your C_t of the point-coordinate driver", b.Ct, Ct, kFD, hint::driver_Ct);
      ok = ok && testing::compare(b.Ct, Ct, kFD).ok;
    }
    if (!ok) break;
  }
}

GRADED_TEST("distance driver: C C_q and C_t match the definition and finite differences", "[M01][T5][points=1]") {
  testing::Random random(503);
  const DriveFunction f = DriveFunction::harmonic(0.9, 0.3, 1.7, -0.4);
  for (int k = 0; k < 20; ++k) {
    const Vec3 q_i = random.vec3(-2, 2), q_j = random.vec3(-2, 2);
    const Vec2 s_i = random.vec2(-1, 1), s_j = random.vec2(-1, 1);
    const double t = random.uniform(0, 4);
    const DriveValue v = f(t);
    INFO("q_i = " << show(q_i) << ", s_i = " << show(s_i) << ", q_j = " << show(q_j) << ", s_j = " << show(s_j)
                  << ", t = " << t << ", f = 0.9 + 0.3 sin(1.7 t - 0.4)");
    const Vec2 d = q_j.head<2>() + rot(q_j(2)) * s_j - q_i.head<2>() - rot(q_i(2)) * s_i;
    const ConstraintBlock b = distance_constraint(q_i, s_i, q_j, s_j, v);
    REQUIRE(b.C.size() == 1);
    CHECK_NEAR_NAMED("your C of the distance driver",
                     b.C(0), 0.5 * (d.squaredNorm() - v.f * v.f), kExact, hint::distance_C);
    const bool ok_q = check_driver_jacobian(
        [&](const Vec3& x, const Vec3& y) { return distance_constraint(x, s_i, y, s_j, v); }, q_i, q_j, true,
        hint::distance_Cq);
    const VecX Ct = time_difference([&](const DriveValue& w) { return distance_constraint(q_i, s_i, q_j, s_j, w); }, f, t);
    CHECK_CLOSE_NAMED("your C_t of the distance driver", b.Ct, Ct, kFD, hint::distance_Ct);
    if (!ok_q || !testing::compare(b.Ct, Ct, kFD).ok) break;
  }
}

GRADED_TEST("drivers: assembled C_q and C_t of a model with every driver type match finite differences",
            "[M01][T5][points=1]") {
  Model m;
  const BodyId a = m.add_body("a", 1, 1), b = m.add_body("b", 1, 1);
  const PointId pa = m.add_point(a, Vec2(0.3, -0.1), "pa");
  const PointId pb = m.add_point(b, Vec2(-0.2, 0.25), "pb");
  const PointId pg = m.add_point(ground, Vec2(0.5, 0.4), "pg");
  m.add_absolute_angle_driver("angle a", a, DriveFunction::harmonic(0.1, 0.5, 3.0));
  m.add_relative_angle_driver("angle b-a", a, b, DriveFunction::polynomial({0.3, 0.2, -0.15}));
  m.add_point_coordinate_driver("y of pb", pb, Axis::y, DriveFunction::harmonic(-0.2, 0.4, 1.3, 0.7));
  m.add_distance_driver("distance pg-pa", pg, pa, DriveFunction::polynomial({0.6, 0.25, 0.05}));
  m.add_distance_driver("distance pa-pb", pa, pb, DriveFunction::harmonic(0.8, 0.2, 2.0));
  testing::Random random(504);
  for (int k = 0; k < 10; ++k) {
    const VecX q = random.vector(6, -1.5, 1.5);
    const double t = random.uniform(0, 2);
    if (!check_model_derivatives(m, q, t)) break;
  }
}
