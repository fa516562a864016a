// Module 7, tasks T1-T3 on single nodes: the pose, its Jacobian and its convective acceleration
// (visible tests). The oracles: the pose R + A (x_bar + u_bar), theta + psi written out by hand,
// central differences of that pose in q, and its second derivative in time along a smooth
// motion (five-point stencil).
#include <cmath>
#include <string>

#include "fmbd/intuitive_flexible.hpp"
#include "flexible_checks.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m07;

// ---- T1 -------------------------------------------------------------------------------------

GRADED_TEST("node_pose of random nodes is R + A (x_bar + u_bar) and theta + psi", "[M07][T1][points=2]") {
  Random rnd(7101);
  for (int trial = 0; trial < 6; ++trial) {
    const int n_f = 1 + trial % 4;
    const NodeModes node = random_node(rnd, n_f);
    const VecX q = random_node_state(rnd, n_f);
    CAPTURE(trial, n_f, q.transpose());
    const Vec3 expected = pose_oracle(node, q);
    const Vec3 p = node_pose(node, q);

    const Mat2 A = rot(q(2));
    const Vec2 R = q.head<2>(), u = u_bar(node, q);
    const Vec2 r = p.head<2>(), r_expected = expected.head<2>();
    CHECK_CLOSE_NAMED("the node position r_k of your node_pose", r, r_expected, (Tolerance{1e-12, 1e-12}),
                diagnose(r, r_expected,
                         {{with_formula("your r_k misses u_bar: the node sits at its deformed position", kPose),
                           R + A * node.x_bar},
                          {with_formula("your r_k: u_bar not rotated: u_bar is in the frame", kPose),
                           R + A * node.x_bar + u},
                          {"your r_k turns by A(theta) transposed: use rotation() of module 1",
                           R + A.transpose() * (node.x_bar + u)},
                          {with_formula("your r_k misses R", kPose), A * (node.x_bar + u)}},
                         with_formula("your r_k is not the deformed node in the frame, q = (R_x, R_y, theta, q_f)",
                                      kPose)));
    CHECK_NEAR_NAMED("the node angle phi_k of your node_pose", p(2), expected(2), (Tolerance{1e-12, 1e-12}),
                     diagnose(as_matrix(p(2)), as_matrix(expected(2)),
                              {{with_formula("your pose angle misses psi: the section turns with psi", kPose),
                                as_matrix(q(2))},
                               {with_formula("your pose angle is psi alone: it turns with the frame too", kPose),
                                as_matrix(psi(node, q))}},
                              with_formula("your node angle is not the frame's angle plus the section's turn", kPose)));
  }
}

GRADED_TEST("node_pose of every node of a beam is the frame pose of the FE field Phi_f q_f", "[M07][T1][points=1]") {
  Random rnd(7102);
  const FeModel fe = straight_beam(1.2, 6, steel(0.02), Vec2(0.3, -0.2), 0.4);
  const FlexibleBodyData d = flexible_body_data(fe, MassMatrixType::consistent, 3);
  REQUIRE(d.num_modes() == 3);
  REQUIRE(static_cast<int>(d.nodes.size()) == fe.num_nodes());
  for (int trial = 0; trial < 3; ++trial) {
    VecX q(6);
    q.head<2>() = rnd.vec2(-1.0, 1.0);
    q(2) = rnd.uniform(-3.0, 3.0);
    q.tail(3) = rnd.vector(3, -0.05, 0.05);
    CAPTURE(trial, q.transpose());
    check_poses_follow_fe_field(d, q, 1e-12);
  }
}

// ---- T2 -------------------------------------------------------------------------------------

GRADED_TEST("node_jacobian matches central differences of the node pose in every column", "[M07][T2][points=3]") {
  Random rnd(7201);
  for (int trial = 0; trial < 6; ++trial) {
    const int n_f = 1 + trial % 4;
    const NodeModes node = random_node(rnd, n_f);
    const VecX q = random_node_state(rnd, n_f);
    CAPTURE(trial, n_f, q.transpose());
    // The oracle: differences of the hand-written pose (not of the student's node_pose).
    const MatX fd = finite_difference_jacobian([&](const VecX& x) { return VecX(pose_oracle(node, x)); }, q, 1e-6);

    const MatX G = node_jacobian(node, q);
    {
      INFO("hint: G_k is 3 x (3 + n_f): rows (r_x, r_y, phi), columns (R_x, R_y, theta, q_f)");
      REQUIRE(G.rows() == 3);
      REQUIRE(G.cols() == 3 + n_f);
    }
    const Tolerance tol{1e-8, 1e-8};
    const Mat2 A = rot(q(2));
    const Vec2 u = u_bar(node, q);
    CHECK_CLOSE_NAMED("columns 0-1 (R) of your G_k", MatX(G.block(0, 0, 3, 2)), MatX(fd.block(0, 0, 3, 2)), tol,
                      "columns 0-1 of G_k are [I_2; 0 0]: the node moves with R, its angle does not");

    const Vec2 column2 = G.block<2, 1>(0, 2), column2_expected = fd.block<2, 1>(0, 2);
    CHECK_CLOSE_NAMED(
        "column 2 (theta) of your G_k, position rows", column2, column2_expected, tol,
        diagnose(column2, column2_expected,
                 {{with_formula("your column 2 of G_k uses the undeformed arm: the arm is the deformed "
                                "position, not x_bar alone",
                                kColumn2),
                   A * tilde() * node.x_bar},
                  {with_formula("your column 2 of G_k is not turned by A(theta): A is missing", kColumn2),
                   tilde() * (node.x_bar + u)},
                  {with_formula("your column 2 of G_k is the arm itself, not its derivative by theta: I~ is "
                                "missing",
                                kColumn2),
                   A * (node.x_bar + u)},
                  {with_formula("your column 2 of G_k has the wrong sign (column 2 sign)", kColumn2),
                   -A * tilde() * (node.x_bar + u)}},
                 with_formula("your column 2 of G_k is not module 1's point Jacobian column with the deformed "
                              "arm as s_bar",
                              kColumn2),
                 Tolerance{1e-7, 1e-7}));
    CHECK_NEAR_NAMED("G_k(2, 2) of your G_k", G(2, 2), 1.0, tol,
                     "your G_k's angle row: the node angle turns one to one with theta");

    const MatX elastic = G.block(0, 3, 2, n_f), elastic_expected = fd.block(0, 3, 2, n_f);
    CHECK_CLOSE_NAMED(
        "the q_f columns of your G_k, position rows", elastic, elastic_expected, tol,
        diagnose(flat(elastic), flat(elastic_expected),
                 {{with_formula("your G_k: the elastic columns are missing or not turned into global axes: "
                                "u_bar is in the frame",
                                kElasticColumns),
                   flat(node.Phi_t)},
                  {with_formula("your G_k: the elastic columns are missing: they are not zero (the node moves "
                                "with the deformation)",
                                kElasticColumns),
                   flat(MatX(MatX::Zero(2, n_f)))},
                  {with_formula("your elastic columns of G_k are turned the wrong way (by minus the frame's angle)",
                                kElasticColumns),
                   flat(MatX(A.transpose() * node.Phi_t))}},
                 with_formula("your elastic columns of G_k are not the derivative of r_k by q_f", kElasticColumns),
                 Tolerance{1e-7, 1e-7}));

    const MatX angle = G.block(2, 3, 1, n_f), angle_expected = fd.block(2, 3, 1, n_f);
    CHECK_CLOSE_NAMED(
        "the q_f columns of your G_k, angle row", angle, angle_expected, tol,
        diagnose(flat(angle), flat(angle_expected),
                 {{with_formula("your G_k: Phi_psi row of the angle missing: a clamped node turns with psi",
                                "dphi_k/dq_f = Phi_psi"),
                   flat(MatX(MatX::Zero(1, n_f)))}},
                 with_formula("your angle row of G_k is not the derivative of the node angle by q_f",
                              "dphi_k/dq_f = Phi_psi"),
                 Tolerance{1e-7, 1e-7}));
  }
}

// ---- T3 -------------------------------------------------------------------------------------

GRADED_TEST("node_convective_acceleration is the second time derivative of the pose without q_ddot",
            "[M07][T3][points=3]") {
  Random rnd(7301);
  for (int trial = 0; trial < 6; ++trial) {
    const int n_f = 1 + trial % 4;
    const NodeModes node = random_node(rnd, n_f);
    const VecX q0 = random_node_state(rnd, n_f);
    VecX v(3 + n_f), a(3 + n_f);
    v.head<2>() = rnd.vec2(-2.0, 2.0);
    v(2) = rnd.uniform(1.0, 3.0) * (trial % 2 == 0 ? 1.0 : -1.0);
    v.tail(n_f) = rnd.vector(n_f, -1.0, 1.0);
    a = rnd.vector(3 + n_f, -2.0, 2.0);
    CAPTURE(trial, n_f, q0.transpose(), v.transpose(), a.transpose());

    // Along q(t) = q0 + v t + a t^2 / 2, d2p/dt2 at t = 0 is G a + c: c is what remains after
    // the q_ddot part G a (G by differences of the hand-written pose).
    const VecX p_ddot = second_derivative(
        [&](double t) { return VecX(pose_oracle(node, VecX(q0 + t * v + 0.5 * t * t * a))); }, 1e-3);
    const MatX G = finite_difference_jacobian([&](const VecX& x) { return VecX(pose_oracle(node, x)); }, q0, 1e-6);
    const VecX expected = p_ddot - G * a;
    const ConvectiveParts parts = convective_parts(node, q0, v);
    CHECK_CLOSE(expected.head<2>(), Vec2(parts.centripetal + parts.coriolis), (Tolerance{1e-6, 1e-6}),
                "test oracle: c_k written out");

    const Vec3 c = node_convective_acceleration(node, q0, v);
    const Vec2 got = c.head<2>(), want = expected.head<2>();
    const Mat2 A = rot(q0(2));
    const Vec2 cent = parts.centripetal, cor = parts.coriolis;
    const Vec2 rate_part = node.Phi_t * elastic_part(v);
    const double w = v(2);
    CHECK_CLOSE_NAMED(
        "the x and y of your c_k", got, want, (Tolerance{1e-6, 1e-6}),
        diagnose(
            got, want,
            {{"centripetal term sign: yours points away from the frame origin; a node on a turning frame accelerates "
              "towards it",
              Vec2(-cent + cor)},
             {"centripetal term needs the deformed arm: yours uses the undeformed x_bar, but the node turns at its "
              "deformed position",
              Vec2(-w * w * A * node.x_bar + cor)},
             {"Coriolis factor 2 missing: your Coriolis term is half the right one (the product rule gives the cross "
              "term twice)",
              Vec2(cent + 0.5 * cor)},
             {"Coriolis term not turned a quarter turn: your elastic velocity is turned into global axes, but the "
              "Coriolis term is also at right angles to it",
              Vec2(cent + 2 * w * A * rate_part)},
             {"Coriolis term sign: yours has the opposite sign", Vec2(cent - cor)},
             {"Coriolis term missing: yours has none, but the elastic velocity turns with the frame", cent},
             {"Coriolis term uses the elastic velocity q_f_dot: yours uses the displacement q_f",
              Vec2(cent + 2 * w * A * tilde() * u_bar(node, q0))},
             {"centripetal term missing: yours has none, but a node on a turning frame accelerates towards its origin",
              cor}},
            with_formula("your c_k differs from the node's acceleration at q_ddot = 0: check its "
                         "centripetal and Coriolis terms",
                         "c_k = (-theta_dot^2 A (x_bar + u_bar) + 2 theta_dot A I~ Phi_t q_f_dot, 0)"),
            Tolerance{1e-5, 1e-5}));
    CHECK_NEAR_NAMED("the angle entry of your c_k", c(2), 0.0, (Tolerance{1e-6, 0.0}),
                     "the angle theta + Phi_psi q_f is linear in q: its convective term is 0");
  }
}
