// Module 1, tasks T2-T4 (hidden): joints assembled in models, ground on either side,
// non-unit axes normalised by the builder, phi0 offsets and large angles.
#include <cmath>

#include "fmbd/constraints.hpp"
#include "fmbd/joints.hpp"
#include "kinematics_checks.hpp"

using namespace fmbd;
using namespace fmbd::m01;

GRADED_TEST("revolute joint: ground on side i or side j in an assembled model", "[M01][T2][points=1]") {
  const Vec2 g(0.4, -0.3), s(0.25, -0.6);
  for (bool ground_first : {true, false}) {
    Model m;
    const BodyId b = m.add_body("arm", 1, 1);
    const PointId pg = m.add_point(ground, g, "pivot");
    const PointId pb = m.add_point(b, s, "arm end");
    if (ground_first) {
      m.add_revolute("hinge", pg, pb);
    } else {
      m.add_revolute("hinge", pb, pg);
    }
    for (double phi : {-kPi, -2.0, 0.7, kPi - 1e-4, 20.0}) {
      INFO("ground on side " << (ground_first ? "i" : "j") << ", phi = " << phi);
      VecX q = place(g, s, phi);
      if (!check_model_closes(m, q, 0.0)) break;
      // Move the arm by a: C = r_Pi - r_Pj reads -a with the ground on side i, +a on side j.
      const Vec2 a(0.03, -0.02);
      q.head<2>() += a;
      CHECK_CLOSE_NAMED("your C of the hinge, the arm moved by a",
                        kernel_evaluation(m, q, 0.0).C, ground_first ? Vec2(-a) : a, kGeometry, hint::revolute_gap);
      if (!check_model_derivatives(m, q, 0.0)) break;
    }
  }
}

GRADED_TEST("translational joint: non-unit axis normalised by the builder with ground on either side",
            "[M01][T3][points=2]") {
  testing::Random random(1301);
  const Vec2 axis_raw(3.0, 4.0);  // the builder stores (0.6, 0.8)
  const Vec2 axis = axis_raw.normalized();
  const double phi0 = 0.6;
  const Vec2 s_i(0.2, -0.35), s_j(-0.15, 0.3), g(1.2, -0.7);

  // (a) two bodies: body a on side i, body b on side j.
  {
    Model m;
    const BodyId a = m.add_body("a", 1, 1), b = m.add_body("b", 1, 1);
    const PointId P_i = m.add_point(a, s_i, "P_i"), P_j = m.add_point(b, s_j, "P_j");
    m.add_translational("slide", P_i, P_j, axis_raw, phi0);
    for (int k = 0; k < 8; ++k) {
      const Vec3 q_a(random.uniform(-2, 2), random.uniform(-2, 2), random.uniform(-40, 40));
      const double slide = random.uniform(-1, 1), delta = random.uniform(-0.2, 0.2);
      const Vec2 r_Pi = q_a.head<2>() + rot(q_a(2)) * s_i;
      const Vec2 u = rot(q_a(2)) * axis, n = rot(q_a(2)) * I_tilde() * axis;
      VecX q(6);
      q << q_a, place(r_Pi + slide * u, s_j, q_a(2) + phi0);
      const VecX q_random = random.vector(6, -2, 2);
      if (!check_model_derivatives(m, q_random, 0.0)) break;
      INFO("two bodies, q = " << show(q) << ", slide " << slide);
      if (!check_model_closes(m, q, 0.0)) break;
      VecX q_off = q;
      q_off.segment<2>(3) += delta * n;
      INFO("body b moved by delta = " << delta << " along n_i");
      CHECK_NEAR_NAMED("the offset row of your translational C, body b moved by delta along n_i",
                       kernel_evaluation(m, q_off, 0.0).C(0), delta, kGeometry, hint::translational_offset);
    }
  }
  // (b) ground on side i: the line is fixed, P_j slides along g + s axis.
  {
    Model m;
    const BodyId b = m.add_body("b", 1, 1);
    const PointId P_i = m.add_point(ground, g, "G"), P_j = m.add_point(b, s_j, "P_j");
    m.add_translational("slide", P_i, P_j, axis_raw, phi0);
    for (double slide : {-0.8, 0.0, 0.45}) {
      const VecX q = place(g + slide * axis, s_j, phi0);
      INFO("ground on side i, q = " << show(q));
      check_model_closes(m, q, 0.0);
      VecX q_off = q;
      q_off.head<2>() += 0.05 * I_tilde() * axis;
      CHECK_NEAR_NAMED("the offset row of your translational C, body b moved off the fixed line",
                       kernel_evaluation(m, q_off, 0.0).C(0), 0.05, kGeometry, hint::translational_offset);
      check_model_derivatives(m, q_off, 0.0);
    }
  }
  // (c) ground on side j: the body carries the line, so the normal turns with it (phi_i = -phi0).
  {
    Model m;
    const BodyId b = m.add_body("b", 1, 1);
    const PointId P_i = m.add_point(b, s_i, "P_i"), P_j = m.add_point(ground, g, "G");
    m.add_translational("slide", P_i, P_j, axis_raw, phi0);
    for (double slide : {-0.6, 0.3}) {
      const double phi = -phi0;
      const Vec2 u = rot(phi) * axis;
      const VecX q = place(g - slide * u, s_i, phi);
      INFO("ground on side j, q = " << show(q));
      check_model_closes(m, q, 0.0);
      VecX q_turned = q;
      q_turned(2) += 0.1;
      CHECK_NEAR_NAMED("the angle row of your translational C, body b turned by 0.1",
                       kernel_evaluation(m, q_turned, 0.0).C(1), -0.1, kGeometry, hint::angle_row);
    }
    for (int k = 0; k < 4; ++k) {
      const VecX q_random = random.vector(3, -2, 2);
      if (!check_model_derivatives(m, q_random, 0.0)) break;
    }
  }
}

GRADED_TEST("fixed joint: welded to the ground on side j with phi0 and large angles", "[M01][T4][points=1]") {
  const Vec2 s(0.3, 0.1), g(-0.5, 0.8);
  for (double phi0 : {-2.5, 0.0, 0.9, kPi}) {
    Model m;
    const BodyId b = m.add_body("b", 1, 1);
    const PointId pb = m.add_point(b, s, "weld body"), pg = m.add_point(ground, g, "weld ground");
    m.add_fixed("weld", pb, pg, phi0);  // C_3 = 0 - phi_b - phi0
    const VecX q = place(g, s, -phi0);
    INFO("phi0 = " << phi0 << ", q = " << show(q));
    check_model_closes(m, q, 0.0);
    VecX q_turned = place(g, s, -phi0 + 0.2);
    const VecX C = kernel_evaluation(m, q_turned, 0.0).C;
    CHECK_CLOSE_NAMED("the point rows of your fixed joint's C, body b turned by 0.2",
                      C.head<2>(), Vec2::Zero(), kGeometry, hint::fixed_closed);
    CHECK_NEAR_NAMED("the angle row of your fixed joint's C, body b turned by 0.2",
                     C(2), -0.2, kGeometry, hint::angle_row);
    // Derivatives at large angles.
    VecX q_far = q;
    q_far(2) += 12 * kPi + 0.3;
    check_model_derivatives(m, q_far, 0.0);
    // The block itself with large angles on both sides.
    const Vec3 q_i(0.1, 0.2, -35.0), q_j(-0.3, 0.5, 41.0);
    const BlockOfQ block = [&](const Vec3& x, const Vec3& y) { return fixed_constraint(x, s, y, -s, phi0); };
    const BlockDifferences fd = block_differences(block, q_i, q_j);
    const ConstraintBlock bl = block(q_i, q_j);
    CHECK_CLOSE_NAMED("your C_q of body i of the fixed joint at large angles",
                      bl.Cq_i, fd.Cq_i, kFD, hint::revolute_Cq_phi);
    CHECK_CLOSE_NAMED("your C_q of body j of the fixed joint at large angles",
                      bl.Cq_j, fd.Cq_j, kFD, hint::revolute_Cq_phi);
  }
}
