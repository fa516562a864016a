// Module 8, tasks T1 and T2 (hidden tests): the node accelerations of a Craig-Bampton rod made
// FFRF-ready (both end nodes as interface), at large deformation and fast spin.
// The oracle: finite differences of the node pose written out in ffrf_checks.hpp.
#include <cmath>
#include <string>

#include "ffrf_checks.hpp"
#include "fmbd/ffrf.hpp"
#include "fmbd/flexible_examples.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m08;

GRADED_TEST("node_acceleration_map Craig-Bampton rod nodes give the nodal velocities and accelerations in frame j",
            "[M08][T1][points=1]") {
  Random rnd(8111);
  const FlexibleExample ex = flexible_slider_crank({}, make_ffrf_body);
  const FlexibleBodyData& data = *ex.data;
  const int n_f = data.num_modes();
  for (int trial = 0; trial < 3; ++trial) {
    const VecX q = random_q(rnd, n_f, modal_scale(data, 0.15));
    VecX v = rnd.vector(3 + n_f, -2.0, 2.0);
    v(2) = 0.0;
    v.tail(n_f) *= modal_scale(data, 1.0);
    const VecX a = rnd.vector(3 + n_f, -3.0, 3.0);
    CAPTURE(q.transpose(), v.transpose(), a.transpose());
    for (std::size_t k = 0; k < data.nodes.size(); ++k) {
      CAPTURE(k);
      const NodeModes& node = data.nodes[k];
      const MatX L = node_acceleration_map(node, q);
      const MatX L_fd = fd_map(node, q);
      const std::string hint = map_hint(L, L_fd, node, q);
      REQUIRE(L.rows() == 3);
      REQUIRE(L.cols() == 3 + n_f);
      // L q_dot is the absolute nodal velocity in frame j ...
      CHECK_CLOSE_NAMED("the node's velocity L_k q_dot of your L_k", VecX(L * v), VecX(fd_velocity(node, q, v)),
                        (Tolerance{1e-8, 1e-8}), hint);
      // ... and without spin L q_ddot its absolute acceleration.
      CHECK_CLOSE_NAMED("the node's acceleration L_k q_ddot of your L_k", VecX(L * a),
                        VecX(fd_acceleration(node, q, v, a)), (Tolerance{1e-7, 1e-7}), hint);
    }
  }
}

GRADED_TEST("node_acceleration_bias fast spin of a deformed Craig-Bampton rod", "[M08][T2][points=1]") {
  Random rnd(8211);
  const FlexibleExample ex = flexible_slider_crank({}, make_ffrf_body);
  const FlexibleBodyData& data = *ex.data;
  const int n_f = data.num_modes();
  for (int trial = 0; trial < 3; ++trial) {
    const VecX q = random_q(rnd, n_f, modal_scale(data, 0.15));
    VecX v = rnd.vector(3 + n_f, -2.0, 2.0);
    v(2) = (trial == 1 ? -1.0 : 1.0) * rnd.uniform(10.0, 30.0);
    v.tail(n_f) *= modal_scale(data, 3.0);
    CAPTURE(q.transpose(), v.transpose());
    for (std::size_t k = 0; k < data.nodes.size(); k += 2) {
      CAPTURE(k);
      const NodeModes& node = data.nodes[k];
      const Vec3 b = node_acceleration_bias(node, q, v);
      const Vec3 expected = fd_acceleration(node, q, v, VecX::Zero(3 + n_f));
      const double scale = expected.cwiseAbs().maxCoeff();
      CHECK_CLOSE_NAMED("your b_k", b, expected, (Tolerance{1e-7 * scale, 1e-7}), bias_hint(b, expected, node, q, v));
    }
  }
}
