// Module 7, task T5 on real beams (hidden tests): the hinge of a pendulum beam on the ground at its
// end node, and a crank pin at the tip of a Craig-Bampton rod, spinning fast. The oracles: central
// differences of C = r_Pi - r_k (the node pose written out) and its second time derivative.
#include <string>

#include "fmbd/craig_bampton.hpp"
#include "fmbd/fe_assembly.hpp"
#include "fmbd/intuitive_flexible.hpp"
#include "flexible_checks.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m07;

GRADED_TEST("revolute_on_node: a hinge on the ground and a crank pin on real beams spinning fast", "[M07][T5][points=1]") {
  Random rnd(7591);
  const FeModel fe = straight_beam(0.8, 6, steel(0.01));
  const FeMatrices fm = assemble(fe, MassMatrixType::consistent);
  const FlexibleBodyData free_free = flexible_body_data(fe, MassMatrixType::lumped, 3);
  const ReducedBasis cb = craig_bampton(fm.K, fm.M, node_dofs({0, 6}), 2);
  const FlexibleBodyData rod = flexible_body_data(fe, MassMatrixType::consistent, ffrf_basis(fe, fm, cb));
  struct Case {
    const FlexibleBodyData* data;
    int node;
    bool on_ground;
    const char* what;
  };
  for (const Case& c : {Case{&free_free, 0, true, "pendulum hinge on the ground at node 0"},
                        Case{&rod, 6, false, "crank pin at the tip of a Craig-Bampton rod"}}) {
    const int n_f = c.data->num_modes();
    const NodeModes& node = c.data->nodes[c.node];
    VecX q_j(3 + n_f), qd_j(3 + n_f);
    q_j.head<3>() = rnd.vec3(-1.0, 1.0);
    q_j.tail(n_f) = rnd.vector(n_f, -1.0, 1.0) * 0.02 * std::sqrt(c.data->mass);
    qd_j.head<3>() = rnd.vec3(-2.0, 2.0);
    qd_j(2) = 25.0;
    qd_j.tail(n_f) = rnd.vector(n_f, -1.0, 1.0) * 0.5 * std::sqrt(c.data->mass);
    const Vec3 q_i = c.on_ground ? Vec3::Zero() : Vec3(rnd.vec3(-1.0, 1.0));
    const Vec3 qd_i = c.on_ground ? Vec3::Zero() : Vec3(0.3, -0.2, 150.0);
    const Vec2 s_i = c.on_ground ? Vec2(rnd.vec2(-1.0, 1.0)) : Vec2(0.15, 0.0);
    CAPTURE(c.what, q_j.transpose(), qd_j.transpose());

    const auto gap = [&](const VecX& x) {
      const Vec3 qi = x.head<3>();
      return VecX(qi.head<2>() + rot(qi(2)) * s_i - pose_oracle(node, x.tail(3 + n_f)).head<2>());
    };
    VecX x(6 + n_f), xd(6 + n_f);
    x << q_i, q_j;
    xd << qd_i, qd_j;
    const MatX J = finite_difference_jacobian(gap, x, 1e-7);
    const VecX gamma_expected = -second_derivative([&](double t) { return gap(VecX(x + t * xd)); }, 2e-4);
    const NodeJointRows rows = revolute_on_node(q_i, qd_i, s_i, node, q_j, qd_j);
    {
      INFO("hint: a revolute joint has 2 rows: C_q_j is 2 x (3 + n_f)");
      REQUIRE(rows.Cq_j.rows() == 2);
      REQUIRE(rows.Cq_j.cols() == 3 + n_f);
      REQUIRE(rows.gamma.size() == 2);
    }
    const MatX Cq_j = rows.Cq_j, expected_j = J.rightCols(3 + n_f);
    CHECK_CLOSE(Cq_j, expected_j, (Tolerance{1e-6, 1e-6}), "C_q of the node is B G_k, every column of body j");
    const VecX gamma = rows.gamma;
    CHECK_CLOSE(gamma, gamma_expected, (Tolerance{1e-5 * std::max(1.0, gamma_expected.norm()), 1e-6}),
                "gamma needs - B_j c_k at a fast spin: centripetal -theta_dot^2 A (x_bar + u_bar) and Coriolis");
  }
}
