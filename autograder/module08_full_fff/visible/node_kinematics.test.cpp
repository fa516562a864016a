// Module 8, tasks T1 and T2: the absolute accelerations of the nodes in frame j (visible tests).
// The oracle: the node pose r_k = R + A (x_bar_k + Phi_t,k q_f), phi_k = theta + Phi_psi,k q_f written
// out in ffrf_checks.hpp, differentiated twice in time by central differences along smooth motions
// q(t) = q0 + v t + a t^2 / 2, the translation turned into frame j with A^T.
#include <cmath>
#include <string>

#include "ffrf_checks.hpp"
#include "fmbd/ffrf.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m08;

// ---- T1 -------------------------------------------------------------------------------------

GRADED_TEST("node_acceleration_map L q_ddot is the absolute node acceleration in frame j without spin",
            "[M08][T1][points=2]") {
  Random rnd(8101);
  for (int n_f : {1, 2, 4}) {
    for (int trial = 0; trial < 3; ++trial) {
      const NodeModes node = random_node(rnd, n_f);
      const VecX q = random_q(rnd, n_f, 0.4);
      // theta_dot = 0: the velocity terms b_k vanish, the acceleration is L_k q_ddot alone.
      VecX v = rnd.vector(3 + n_f, -1.5, 1.5);
      v(2) = 0.0;
      const VecX a = rnd.vector(3 + n_f, -2.0, 2.0);
      CAPTURE(n_f, q.transpose(), v.transpose(), a.transpose());
      const MatX L = node_acceleration_map(node, q);
      const MatX L_fd = fd_map(node, q);
      const std::string hint = map_hint(L, L_fd, node, q);
      REQUIRE(L.rows() == 3);
      REQUIRE(L.cols() == 3 + n_f);
      const Vec3 expected = fd_acceleration(node, q, v, a);
      CHECK_CLOSE_NAMED("the node's acceleration L_k q_ddot of your L_k", VecX(L * a), VecX(expected),
                        (Tolerance{1e-7, 1e-7}), hint);
      CHECK_CLOSE_NAMED("your L_k", L, L_fd, (Tolerance{1e-8, 1e-8}), hint);
    }
  }
}

GRADED_TEST("node_acceleration_map columns of every node of a deformed beam and an L frame", "[M08][T1][points=1]") {
  Random rnd(8102);
  const FlexibleBodyData beam =
      flexible_body_data(straight_beam(1.2, 6, square_section(7e10, 2700.0, 0.02), Vec2(0.3, 0.2), 0.4),
                         MassMatrixType::consistent, 3);
  const FlexibleBodyData frame = flexible_body_data(l_frame(), MassMatrixType::lumped, 4);
  for (const FlexibleBodyData* data : {&beam, &frame}) {
    const int n_f = data->num_modes();
    const VecX q = random_q(rnd, n_f, modal_scale(*data, 0.05));
    CAPTURE(q.transpose());
    for (std::size_t k = 0; k < data->nodes.size(); ++k) {
      CAPTURE(k);
      const NodeModes& node = data->nodes[k];
      const MatX L = node_acceleration_map(node, q);
      const MatX L_fd = fd_map(node, q);
      CHECK_CLOSE_NAMED("your L_k", L, L_fd, (Tolerance{1e-8, 1e-8}), map_hint(L, L_fd, node, q));
    }
  }
}

// ---- T2 -------------------------------------------------------------------------------------

GRADED_TEST("node_acceleration_bias is the node acceleration in frame j along q0 + v t", "[M08][T2][points=2]") {
  Random rnd(8201);
  for (int n_f : {1, 3, 4}) {
    for (int trial = 0; trial < 3; ++trial) {
      const NodeModes node = random_node(rnd, n_f);
      const VecX q = random_q(rnd, n_f, 0.4);
      VecX v = rnd.vector(3 + n_f, -2.0, 2.0);
      v(2) = (trial % 2 == 0 ? 1.0 : -1.0) * rnd.uniform(0.8, 3.0);
      const VecX zero = VecX::Zero(3 + n_f);
      CAPTURE(n_f, q.transpose(), v.transpose());
      const Vec3 b = node_acceleration_bias(node, q, v);
      const Vec3 expected = fd_acceleration(node, q, v, zero);
      CHECK_CLOSE_NAMED("your b_k", b, expected, (Tolerance{1e-7, 1e-7}), bias_hint(b, expected, node, q, v));
    }
  }
}

GRADED_TEST("node_acceleration_map and bias L q_ddot + b along a smooth motion", "[M08][T2][points=1]") {
  Random rnd(8202);
  const FlexibleBodyData beam =
      flexible_body_data(straight_beam(0.8, 5, square_section(2e11, 7850.0, 0.015)), MassMatrixType::lumped, 4);
  for (int trial = 0; trial < 4; ++trial) {
    const NodeModes node = trial < 2 ? beam.nodes[static_cast<std::size_t>(trial == 0 ? 0 : 5)] : random_node(rnd, 4);
    const VecX q = random_q(rnd, 4, trial < 2 ? modal_scale(beam, 0.05) : 0.3);
    const VecX v = rnd.vector(7, -2.5, 2.5), a = rnd.vector(7, -3.0, 3.0);
    CAPTURE(trial, q.transpose(), v.transpose(), a.transpose());
    const MatX L = node_acceleration_map(node, q);
    const Vec3 b = node_acceleration_bias(node, q, v);
    REQUIRE(L.rows() == 3);
    REQUIRE(L.cols() == 7);
    const Vec3 expected = fd_acceleration(node, q, v, a);
    const Vec3 expected_b = fd_acceleration(node, q, v, VecX::Zero(7));
    const MatX L_fd = fd_map(node, q);
    CHECK_CLOSE_NAMED("the node's acceleration L_k q_ddot + b_k of yours", VecX(L * a + b), VecX(expected),
                      (Tolerance{1e-7, 1e-7}),
                      !compare(L, L_fd, Tolerance{1e-7, 1e-7}).ok ? map_hint(L, L_fd, node, q)
                                                                  : bias_hint(b, expected_b, node, q, v));
  }
}
