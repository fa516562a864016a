// Module 7, tasks T1 and T3 on single nodes (hidden tests): the poses of the nodes of an L-shaped
// frame reduced by Craig-Bampton, and the convective acceleration in the two limits where it is
// known without calculus: a body that does not turn, and a rigidly spinning deformed body.
#include <cmath>
#include <string>

#include "fmbd/fe_assembly.hpp"
#include "fmbd/intuitive_flexible.hpp"
#include "flexible_checks.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m07;

GRADED_TEST("node_pose of the nodes of a Craig-Bampton L frame follows the FE field", "[M07][T1][points=1]") {
  Random rnd(7191);
  // An L frame: 4 elements along x, then 3 up, in its own coordinates away from the origin.
  FeModel fe;
  const Section s = steel(0.03);
  int previous = fe.add_node(Vec2(0.5, 0.2));
  for (int k = 1; k <= 4; ++k) {
    const int next = fe.add_node(Vec2(0.5 + 0.4 * k, 0.2));
    fe.add_element(previous, next, s);
    previous = next;
  }
  for (int k = 1; k <= 3; ++k) {
    const int next = fe.add_node(Vec2(2.1, 0.2 + 0.35 * k));
    fe.add_element(previous, next, s);
    previous = next;
  }
  const FeMatrices fm = assemble(fe, MassMatrixType::lumped);
  const ReducedBasis cb = craig_bampton(fm.K, fm.M, node_dofs({0, fe.num_nodes() - 1}), 2);
  const FlexibleBodyData d = flexible_body_data(fe, MassMatrixType::lumped, ffrf_basis(fe, fm, cb));
  const int n_f = d.num_modes();
  REQUIRE(n_f > 0);
  for (int trial = 0; trial < 3; ++trial) {
    VecX q(3 + n_f);
    q.head<2>() = rnd.vec2(-3.0, 3.0);
    q(2) = rnd.uniform(-3.0, 3.0);
    q.tail(n_f) = rnd.vector(n_f, -0.05, 0.05) * std::sqrt(d.mass);
    CAPTURE(trial, q.transpose());
    check_poses_follow_fe_field(d, q, 1e-11);
  }
}

GRADED_TEST("node_convective_acceleration vanishes without spin and is centripetal for a rigid spin",
            "[M07][T3][points=1]") {
  Random rnd(7391);
  for (int trial = 0; trial < 4; ++trial) {
    const int n_f = 2 + trial % 3;
    const NodeModes node = random_node(rnd, n_f);
    const VecX q = random_node_state(rnd, n_f);
    CAPTURE(trial, n_f, q.transpose());

    // No spin: every term of c_k has a factor theta_dot, whatever R_dot and q_f_dot are.
    VecX qd = rnd.vector(3 + n_f, -2.0, 2.0);
    qd(2) = 0.0;
    CHECK_CLOSE_NAMED(
        "your c_k", node_convective_acceleration(node, q, qd), Vec3(Vec3::Zero()), (Tolerance{1e-12, 0.0}),
        "your c_k is not 0 when theta_dot = 0: both the centripetal and the Coriolis term carry theta_dot");

    // A rigid spin (q_f_dot = 0) with any R_dot: the node runs on a circle about R with radius
    // |x_bar + u_bar|, so its acceleration is w^2 |r_k - R| towards R.
    const double w = rnd.uniform(1.0, 4.0);
    VecX spin = VecX::Zero(3 + n_f);
    spin.head<2>() = rnd.vec2(-1.0, 1.0);
    spin(2) = w;
    const Vec3 p = pose_oracle(node, q);
    const Vec2 towards_centre = Vec2(q.head<2>()) - Vec2(p.head<2>());
    const Vec3 c = node_convective_acceleration(node, q, spin);
    const Vec2 got = c.head<2>(), want = w * w * towards_centre;
    CHECK_CLOSE_NAMED("the x and y of your c_k", got, want, (Tolerance{1e-10, 1e-10}),
                diagnose(got, want,
                         {{"centripetal term sign: your centripetal term points away from the frame origin; a node on "
                           "a turning frame accelerates towards it",
                           Vec2(-want)},
                          {"centripetal term needs the deformed arm: yours uses the undeformed x_bar",
                           Vec2(-w * w * rot(q(2)) * node.x_bar)},
                          {"your centripetal term has the rate theta_dot, not its square", Vec2(want / w)}},
                         with_formula("your c_k of a rigid spin does not point towards R with w^2 |r_k - R|",
                                      "c_k = -theta_dot^2 A (x_bar + u_bar)"),
                         Tolerance{1e-8, 1e-8}));
    CHECK_NEAR_NAMED("the angle entry of your c_k", c(2), 0.0, (Tolerance{1e-12, 0.0}),
                     "the angle theta + Phi_psi q_f is linear in q: its convective term is 0");
  }
}
