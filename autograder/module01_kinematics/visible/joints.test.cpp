// Module 1, tasks T2-T4: revolute, translational and fixed joints, block by block.
#include "fmbd/joints.hpp"
#include "kinematics_checks.hpp"

using namespace fmbd;
using namespace fmbd::m01;

namespace {

// Compares Cq_i and Cq_j of `b` with central differences, column group by column group.
// `xy_i`, `phi_i`, `xy_j`, `phi_j`: hints for the x-y columns and the phi column of each body. A phi
// column with the opposite sign gets its body's x-y hint: the mistake is the body's sign, not A I~.
bool check_block_jacobian(const BlockOfQ& block, const Vec3& q_i, const Vec3& q_j, const Hint& xy_i,
                          const Hint& phi_i, const Hint& xy_j, const Hint& phi_j) {
  const ConstraintBlock b = block(q_i, q_j);
  const BlockDifferences fd = block_differences(block, q_i, q_j);
  const auto negated = [](const VecX& actual, const VecX& expected) {
    return !testing::compare(actual, expected, kFD).ok && testing::compare(actual, (-expected).eval(), kFD).ok;
  };
  CHECK_CLOSE_NAMED("the x-y columns of your C_q of body i", b.Cq_i.leftCols(2), fd.Cq_i.leftCols(2), kFD, xy_i);
  CHECK_CLOSE_NAMED("the phi column of your C_q of body i",
                    b.Cq_i.col(2), fd.Cq_i.col(2), kFD, negated(b.Cq_i.col(2), fd.Cq_i.col(2)) ? xy_i : phi_i);
  CHECK_CLOSE_NAMED("the x-y columns of your C_q of body j", b.Cq_j.leftCols(2), fd.Cq_j.leftCols(2), kFD, xy_j);
  CHECK_CLOSE_NAMED("the phi column of your C_q of body j",
                    b.Cq_j.col(2), fd.Cq_j.col(2), kFD, negated(b.Cq_j.col(2), fd.Cq_j.col(2)) ? xy_j : phi_j);
  CHECK_CLOSE_NAMED("your C_t of the joint", b.Ct, VecX::Zero(b.C.size()), kExact, hint::joint_Ct);
  return testing::compare(b.Cq_i, fd.Cq_i, kFD).ok && testing::compare(b.Cq_j, fd.Cq_j, kFD).ok;
}

}  // namespace

// ---- revolute (T2) -------------------------------------------------------------------------

GRADED_TEST("revolute joint: C vanishes where the points coincide and equals the gap otherwise",
            "[M01][T2][points=1]") {
  testing::Random random(201);
  for (int k = 0; k < 20; ++k) {
    const Vec3 q_i = random.vec3(-2, 2);
    const Vec2 s_i = random.vec2(-1, 1), s_j = random.vec2(-1, 1);
    const Vec2 r = q_i.head<2>() + rot(q_i(2)) * s_i;
    const Vec3 q_j = place(r, s_j, random.uniform(-kPi, kPi));
    INFO("q_i = " << show(q_i) << ", s_i = " << show(s_i) << ", q_j = " << show(q_j) << ", s_j = " << show(s_j));
    const ConstraintBlock b = revolute_constraint(q_i, s_i, q_j, s_j);
    REQUIRE(b.C.size() == 2);
    CHECK_CLOSE_NAMED("your C of the revolute joint", b.C, Vec2::Zero(), kGeometry, hint::revolute_closed);
    // Moving body j by delta moves P_j by delta: C = r_Pi - r_Pj = -delta.
    const Vec2 delta = random.vec2(-0.5, 0.5);
    Vec3 q_moved = q_j;
    q_moved.head<2>() += delta;
    INFO("body j moved by delta = " << show(delta));
    CHECK_CLOSE_NAMED("your C of the revolute joint, body j moved by delta",
                      revolute_constraint(q_i, s_i, q_moved, s_j).C, -delta, kGeometry, hint::revolute_gap);
    if (!testing::compare(b.C, Vec2::Zero(), kGeometry).ok) break;
  }
}

GRADED_TEST("revolute joint: C_q matches central finite differences on random configurations",
            "[M01][T2][points=2]") {
  testing::Random random(202);
  for (int k = 0; k < 25; ++k) {
    const Vec3 q_i = random.vec3(-2, 2), q_j = random.vec3(-2, 2);
    const Vec2 s_i = random.vec2(-1, 1), s_j = random.vec2(-1, 1);
    INFO("q_i = " << show(q_i) << ", s_i = " << show(s_i) << ", q_j = " << show(q_j) << ", s_j = " << show(s_j));
    const BlockOfQ block = [&](const Vec3& a, const Vec3& b) { return revolute_constraint(a, s_i, b, s_j); };
    REQUIRE(block(q_i, q_j).C.size() == 2);
    if (!check_block_jacobian(block, q_i, q_j, hint::revolute_Cq_i_translation, hint::revolute_Cq_phi,
                              hint::revolute_Cq_j_translation, hint::revolute_Cq_phi))
      break;
  }
}

// ---- translational (T3) --------------------------------------------------------------------

GRADED_TEST("translational joint: C vanishes on the sliding line and C_1 equals the normal offset",
            "[M01][T3][points=1]") {
  testing::Random random(301);
  for (int k = 0; k < 20; ++k) {
    const Vec3 q_i = random.vec3(-2, 2);
    const Vec2 s_i = random.vec2(-1, 1), s_j = random.vec2(-1, 1);
    const double axis_angle = random.uniform(-kPi, kPi), phi0 = random.uniform(-1.5, 1.5);
    const double slide = random.uniform(-1, 1), delta = random.uniform(-0.3, 0.3);
    const Vec2 axis(std::cos(axis_angle), std::sin(axis_angle));
    const Vec2 u = rot(q_i(2)) * axis;              // sliding direction, global
    const Vec2 n = rot(q_i(2)) * I_tilde() * axis;  // normal, global
    const Vec2 r_Pi = q_i.head<2>() + rot(q_i(2)) * s_i;
    const Vec3 q_j = place(r_Pi + slide * u, s_j, q_i(2) + phi0);
    INFO("q_i = " << show(q_i) << ", s_i = " << show(s_i) << ", q_j = " << show(q_j) << ", s_j = " << show(s_j)
                  << ", axis_i = " << show(axis) << ", phi0 = " << phi0);

    const ConstraintBlock b = translational_constraint(q_i, s_i, q_j, s_j, axis, phi0);
    REQUIRE(b.C.size() == 2);
    CHECK_NEAR_NAMED("the offset row of your translational C", b.C(0), 0.0, kGeometry, hint::translational_on_line);
    CHECK_NEAR_NAMED("the angle row of your translational C", b.C(1), 0.0, kGeometry, hint::angle_row);
    CHECK_CLOSE_NAMED("your C_t of the translational joint", b.Ct, Vec2::Zero(), kExact, hint::joint_Ct);

    // Sliding further along the axis changes nothing; a shift along n_i gives C_1 = delta.
    Vec3 q_slid = q_j, q_off = q_j;
    q_slid.head<2>() += 0.7 * u;
    q_off.head<2>() += delta * n;
    const Vec3 q_turned = place(r_Pi + slide * u, s_j, q_i(2) + phi0 + delta);  // P_j stays on the line
    INFO("slide 0.7 along the axis, offset delta = " << delta << " along n_i, or turn body j by delta");
    CHECK_NEAR_NAMED("the offset row of your translational C, body j slid along the axis",
                     translational_constraint(q_i, s_i, q_slid, s_j, axis, phi0).C(0), 0.0, kGeometry,
                     hint::translational_on_line);
    CHECK_NEAR_NAMED("the offset row of your translational C, body j moved by delta along n_i",
                     translational_constraint(q_i, s_i, q_off, s_j, axis, phi0).C(0), delta, kGeometry,
                     hint::translational_offset);
    const ConstraintBlock turned = translational_constraint(q_i, s_i, q_turned, s_j, axis, phi0);
    CHECK_NEAR_NAMED("the offset row of your translational C, body j turned by delta",
                     turned.C(0), 0.0, kGeometry, hint::translational_on_line);
    CHECK_NEAR_NAMED("the angle row of your translational C, body j turned by delta",
                     turned.C(1), delta, kGeometry, hint::angle_row);
    if (!testing::compare(b.C, Vec2::Zero(), kGeometry).ok) break;
  }
}

GRADED_TEST("translational joint: C_q matches central finite differences on random configurations",
            "[M01][T3][points=2]") {
  testing::Random random(302);
  for (int k = 0; k < 25; ++k) {
    const Vec3 q_i = random.vec3(-2, 2), q_j = random.vec3(-2, 2);
    const Vec2 s_i = random.vec2(-1, 1), s_j = random.vec2(-1, 1);
    const double axis_angle = random.uniform(-kPi, kPi), phi0 = random.uniform(-1, 1);
    const Vec2 axis(std::cos(axis_angle), std::sin(axis_angle));
    INFO("q_i = " << show(q_i) << ", s_i = " << show(s_i) << ", q_j = " << show(q_j) << ", s_j = " << show(s_j)
                  << ", axis_i = " << show(axis) << ", phi0 = " << phi0);
    const BlockOfQ block = [&](const Vec3& a, const Vec3& b) {
      return translational_constraint(a, s_i, b, s_j, axis, phi0);
    };
    const ConstraintBlock b = block(q_i, q_j);
    REQUIRE(b.C.size() == 2);
    const BlockDifferences fd = block_differences(block, q_i, q_j);
    CHECK_CLOSE_NAMED("the offset row's x-y columns of your C_q of body i",
                      b.Cq_i.row(0).head(2), fd.Cq_i.row(0).head(2), kFD, hint::translational_Cq_translation);
    CHECK_CLOSE_NAMED("the offset row's x-y columns of your C_q of body j",
                      b.Cq_j.row(0).head(2), fd.Cq_j.row(0).head(2), kFD, hint::translational_Cq_translation);
    CHECK_NEAR_NAMED("the offset row's phi column of your C_q of body i",
                     b.Cq_i(0, 2), fd.Cq_i(0, 2), kFD, hint::translational_Cq_phi_i);
    CHECK_NEAR_NAMED("the offset row's phi column of your C_q of body j",
                     b.Cq_j(0, 2), fd.Cq_j(0, 2), kFD, hint::translational_Cq_phi_j);
    CHECK_CLOSE_NAMED("the angle row of your C_q of body i", b.Cq_i.row(1), fd.Cq_i.row(1), kFD, hint::angle_row_Cq);
    CHECK_CLOSE_NAMED("the angle row of your C_q of body j", b.Cq_j.row(1), fd.Cq_j.row(1), kFD, hint::angle_row_Cq);
    CHECK_CLOSE_NAMED("your C_t of the translational joint", b.Ct, Vec2::Zero(), kExact, hint::joint_Ct);
    if (!testing::compare(b.Cq_i, fd.Cq_i, kFD).ok || !testing::compare(b.Cq_j, fd.Cq_j, kFD).ok) break;
  }
}

// ---- fixed (T4) ----------------------------------------------------------------------------

GRADED_TEST("fixed joint: C vanishes on a welded pair and its angle row measures the relative rotation",
            "[M01][T4][points=1]") {
  testing::Random random(401);
  for (int k = 0; k < 20; ++k) {
    const Vec3 q_i = random.vec3(-2, 2);
    const Vec2 s_i = random.vec2(-1, 1), s_j = random.vec2(-1, 1);
    const double phi0 = random.uniform(-1.5, 1.5), delta = random.uniform(-0.3, 0.3);
    const Vec2 r = q_i.head<2>() + rot(q_i(2)) * s_i;
    const Vec3 q_j = place(r, s_j, q_i(2) + phi0);
    INFO("q_i = " << show(q_i) << ", s_i = " << show(s_i) << ", q_j = " << show(q_j) << ", s_j = " << show(s_j)
                  << ", phi0 = " << phi0);
    const ConstraintBlock b = fixed_constraint(q_i, s_i, q_j, s_j, phi0);
    REQUIRE(b.C.size() == 3);
    CHECK_CLOSE_NAMED("the point rows of your fixed joint's C",
                      b.C.head(2), Vec2::Zero(), kGeometry, hint::fixed_closed);
    CHECK_NEAR_NAMED("the angle row of your fixed joint's C", b.C(2), 0.0, kGeometry, hint::angle_row);
    CHECK_CLOSE_NAMED("your C_t of the fixed joint", b.Ct, Vec3::Zero(), kExact, hint::joint_Ct);
    // Turn body j about P_j by delta: the point rows stay zero, the angle row reads delta.
    const Vec3 q_turned = place(r, s_j, q_i(2) + phi0 + delta);
    INFO("body j turned about P_j by delta = " << delta);
    const ConstraintBlock turned = fixed_constraint(q_i, s_i, q_turned, s_j, phi0);
    CHECK_CLOSE_NAMED("the point rows of your fixed joint's C, body j turned by delta",
                      turned.C.head(2), Vec2::Zero(), kGeometry, hint::fixed_closed);
    CHECK_NEAR_NAMED("the angle row of your fixed joint's C, body j turned by delta",
                     turned.C(2), delta, kGeometry, hint::angle_row);
    // Move body j by a: the point rows read -a.
    const Vec2 a = random.vec2(-0.5, 0.5);
    Vec3 q_moved = q_j;
    q_moved.head<2>() += a;
    CHECK_CLOSE_NAMED("the point rows of your fixed joint's C, body j moved by a",
                      fixed_constraint(q_i, s_i, q_moved, s_j, phi0).C.head(2), -a, kGeometry, hint::revolute_gap);
    if (!testing::compare(b.C, Vec3::Zero(), kGeometry).ok) break;
  }
}

GRADED_TEST("fixed joint: C_q matches central finite differences on random configurations", "[M01][T4][points=1]") {
  testing::Random random(402);
  for (int k = 0; k < 25; ++k) {
    const Vec3 q_i = random.vec3(-2, 2), q_j = random.vec3(-2, 2);
    const Vec2 s_i = random.vec2(-1, 1), s_j = random.vec2(-1, 1);
    const double phi0 = random.uniform(-1, 1);
    INFO("q_i = " << show(q_i) << ", s_i = " << show(s_i) << ", q_j = " << show(q_j) << ", s_j = " << show(s_j)
                  << ", phi0 = " << phi0);
    const BlockOfQ block = [&](const Vec3& a, const Vec3& b) { return fixed_constraint(a, s_i, b, s_j, phi0); };
    const ConstraintBlock b = block(q_i, q_j);
    REQUIRE(b.C.size() == 3);
    const BlockDifferences fd = block_differences(block, q_i, q_j);
    CHECK_CLOSE_NAMED("the point rows' x-y columns of your C_q of body i",
                      b.Cq_i.topLeftCorner(2, 2), fd.Cq_i.topLeftCorner(2, 2), kFD, hint::revolute_Cq_i_translation);
    CHECK_CLOSE_NAMED("the point rows' phi column of your C_q of body i",
                      b.Cq_i.col(2).head(2), fd.Cq_i.col(2).head(2), kFD, hint::revolute_Cq_phi);
    CHECK_CLOSE_NAMED("the point rows' x-y columns of your C_q of body j",
                      b.Cq_j.topLeftCorner(2, 2), fd.Cq_j.topLeftCorner(2, 2), kFD, hint::revolute_Cq_j_translation);
    CHECK_CLOSE_NAMED("the point rows' phi column of your C_q of body j",
                      b.Cq_j.col(2).head(2), fd.Cq_j.col(2).head(2), kFD, hint::revolute_Cq_phi);
    CHECK_CLOSE_NAMED("the angle row of your C_q of body i", b.Cq_i.row(2), fd.Cq_i.row(2), kFD, hint::angle_row_Cq);
    CHECK_CLOSE_NAMED("the angle row of your C_q of body j", b.Cq_j.row(2), fd.Cq_j.row(2), kFD, hint::angle_row_Cq);
    CHECK_CLOSE_NAMED("your C_t of the fixed joint", b.Ct, Vec3::Zero(), kExact, hint::joint_Ct);
    if (!testing::compare(b.Cq_i, fd.Cq_i, kFD).ok || !testing::compare(b.Cq_j, fd.Cq_j, kFD).ok) break;
  }
}
