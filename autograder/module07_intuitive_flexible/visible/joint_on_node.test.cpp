// Module 7, task T5: a revolute joint on a node of a flexible body (visible tests). The oracles:
// the joint equation C = r_Pi - r_k written out with the hand-written node pose, its central
// differences in every column of both bodies, and its second time derivative along a straight
// motion (q_ddot = 0, so gamma = -d2C/dt2).
#include <string>

#include "fmbd/intuitive_flexible.hpp"
#include "flexible_checks.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m07;

namespace {

// The hints of the whole joint close with what it is built on.
const std::string kNeedsT1T3 = " (revolute_on_node builds on your node_pose, node_jacobian and "
                               "node_convective_acceleration: M07T1-T3)";

// C = R_i + A_i s_i - r_k of the joint at x = (q_i, q_j), written out.
VecX joint_gap(const NodeModes& node, const Vec2& s_i, const VecX& x) {
  const Vec3 q_i = x.head<3>();
  return VecX(q_i.head<2>() + rot(q_i(2)) * s_i - pose_oracle(node, x.tail(x.size() - 3)).head<2>());
}

VecX stacked(const Vec3& q_i, const VecX& q_j) {
  VecX x(3 + q_j.size());
  x << q_i, q_j;
  return x;
}

void require_sizes(const NodeJointRows& rows, int n_f) {
  INFO("hint: a revolute joint has 2 rows: C (2), C_q_i (2 x 3), C_q_j (2 x (3 + n_f)), gamma (2)");
  REQUIRE(rows.C.size() == 2);
  REQUIRE(rows.Cq_i.rows() == 2);
  REQUIRE(rows.Cq_j.rows() == 2);
  REQUIRE(rows.Cq_j.cols() == 3 + n_f);
  REQUIRE(rows.gamma.size() == 2);
}

}  // namespace

GRADED_TEST("revolute_on_node: C is the gap to the deformed node and C_q matches central differences",
            "[M07][T5][points=2]") {
  Random rnd(7501);
  for (int trial = 0; trial < 6; ++trial) {
    const int n_f = 1 + trial % 3;
    const bool on_ground = trial % 3 == 2;
    const NodeModes node = random_node(rnd, n_f);
    const VecX q_j = random_node_state(rnd, n_f);
    const Vec3 q_i = on_ground ? Vec3::Zero() : Vec3(rnd.vec3(-2.0, 2.0));
    const Vec2 s_i = rnd.vec2(-1.0, 1.0);
    CAPTURE(trial, n_f, on_ground, q_i.transpose(), s_i.transpose(), q_j.transpose());

    const VecX x = stacked(q_i, q_j);
    const auto gap = [&](const VecX& y) { return joint_gap(node, s_i, y); };
    const VecX C_expected = gap(x);
    const MatX J = finite_difference_jacobian(gap, x, 1e-6);
    const NodeJointRows rows = revolute_on_node(q_i, Vec3::Zero(), s_i, node, q_j, VecX::Zero(3 + n_f));
    require_sizes(rows, n_f);

    const Vec3 p = pose_oracle(node, q_j);
    const VecX C = rows.C;
    CHECK_CLOSE(C, C_expected, (Tolerance{1e-10, 1e-10}),
                diagnose(C, C_expected,
                         {{"the node marker has s_bar = 0: its pose p_k holds x_bar_k already",
                           VecX(C_expected - rot(p(2)) * node.x_bar)}},
                         "C = r_Pi - r_k: the revolute kernel of module 1 on the node marker (pose p_k, s_bar = 0)" +
                             kNeedsT1T3,
                         Tolerance{1e-8, 1e-8}));
    if (!on_ground) {
      const MatX Cq_i = rows.Cq_i, expected_i = J.leftCols(3);
      CHECK_CLOSE(Cq_i, expected_i, (Tolerance{1e-6, 1e-6}), "C_q_i: the kernel's block of the rigid body i, as in module 1");
    }
    const MatX Cq_j = rows.Cq_j, expected_j = J.rightCols(3 + n_f);
    MatX frame_only = MatX::Zero(2, 3 + n_f);
    frame_only.leftCols(2) = -Mat2::Identity();
    CHECK_CLOSE(Cq_j, expected_j, (Tolerance{1e-6, 1e-6}),
                diagnose(flat(Cq_j), flat(expected_j),
                         {{"C_q of the node is B G_k: the kernel's block on the node pose times your node_jacobian, "
                           "in every column of body j",
                           flat(frame_only)},
                          {"C_q of the node is B G_k: the sign of B (C = r_Pi - r_k, the node on side j)",
                           flat(MatX(-expected_j))}},
                         "C_q_j = B_j G_k (2 x (3 + n_f))" + kNeedsT1T3, Tolerance{1e-5, 1e-5}));
  }
}

GRADED_TEST("revolute_on_node: gamma is the second time derivative of C without q_ddot", "[M07][T5][points=2]") {
  Random rnd(7502);
  for (int trial = 0; trial < 6; ++trial) {
    const int n_f = 1 + trial % 3;
    const NodeModes node = random_node(rnd, n_f);
    const VecX q_j = random_node_state(rnd, n_f);
    const Vec3 q_i = rnd.vec3(-2.0, 2.0);
    const Vec2 s_i = rnd.vec2(-1.0, 1.0);
    Vec3 qd_i = rnd.vec3(-1.0, 1.0);
    qd_i(2) = rnd.uniform(1.0, 3.0);
    VecX qd_j(3 + n_f);
    qd_j.head<2>() = rnd.vec2(-1.0, 1.0);
    qd_j(2) = rnd.uniform(1.0, 3.0) * (trial % 2 == 0 ? 1.0 : -1.0);
    qd_j.tail(n_f) = rnd.vector(n_f, -1.0, 1.0);
    CAPTURE(trial, n_f, q_i.transpose(), qd_i.transpose(), q_j.transpose(), qd_j.transpose());

    // Along x(t) = x + t x_dot, q_ddot = 0 and C_q q_ddot = gamma leaves gamma = -d2C/dt2.
    const VecX x = stacked(q_i, q_j), xd = stacked(qd_i, qd_j);
    const VecX expected = -second_derivative([&](double t) { return joint_gap(node, s_i, VecX(x + t * xd)); }, 1e-3);
    const NodeJointRows rows = revolute_on_node(q_i, qd_i, s_i, node, q_j, qd_j);
    require_sizes(rows, n_f);

    // The node's convective acceleration c_k enters through -B_j c_k = +c_k (B_j = -[I 0]).
    const ConvectiveParts parts = convective_parts(node, q_j, qd_j);
    const Vec2 c_k = parts.centripetal + parts.coriolis;
    const VecX gamma = rows.gamma;
    CHECK_CLOSE(gamma, expected, (Tolerance{1e-6, 1e-6}),
                diagnose(gamma, expected,
                         {{"gamma needs - B_j c_k: the node accelerates without q_ddot (centripetal and Coriolis)",
                           VecX(expected - c_k)},
                          {"gamma is the kernel's gamma minus B_j c_k, not plus", VecX(expected - 2 * c_k)}},
                         "gamma = revolute_gamma on the node marker - B_j c_k" + kNeedsT1T3, Tolerance{1e-5, 1e-5}));
  }
}
