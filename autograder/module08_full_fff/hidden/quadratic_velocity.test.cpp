// Module 8, task T4 (hidden tests): the quadratic velocity vector with the consistent mass matrix.
// The oracles: the definition Q_v = -L^T M_FE b with L and b taken from finite differences of the
// node poses (ffrf_checks.hpp), and the power balance of the nodal form: with a mass matrix that is
// not isotropic the velocity forces do work, exactly
//   q_dot^T Q_v + 1/2 q_dot^T (dM/dt) q_dot = -theta_dot w^T M_FE I~ w = -theta_dot 1/2 w^T (M I~ - I~ M) w,
// with w the nodal velocities in frame j (for a lumped mass matrix it is zero: Lagrange's equations).
#include <cmath>
#include <string>

#include "ffrf_checks.hpp"
#include "ffrf_hidden_checks.hpp"
#include "fmbd/ffrf.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m08;

GRADED_TEST("quadratic_velocity_vector consistent mass is the projected nodal inertia and its power error",
            "[M08][T4][points=2]") {
  Random rnd(8411);
  const FlexibleBodyData beam = flexible_body_data(
      straight_beam(1.0, 8, square_section(5e8, 1200.0, 0.02), Vec2(0.1, 0.5), -0.6), MassMatrixType::consistent, 4);
  const FlexibleBodyData frame = flexible_body_data(l_frame(), MassMatrixType::consistent, 5);
  for (const FlexibleBodyData* data : {&beam, &frame}) {
    const int n_f = data->num_modes(), N = static_cast<int>(data->nodes.size());
    const MatX& M_FE = data->matrices.M;
    for (int trial = 0; trial < 3; ++trial) {
      const VecX q = random_q(rnd, n_f, modal_scale(*data, 0.1));
      VecX qd = rnd.vector(3 + n_f, -1.0, 1.0);
      qd(2) = (trial == 2 ? -1.0 : 1.0) * rnd.uniform(1.0, 4.0);
      qd.tail(n_f) *= modal_scale(*data, 0.5);
      CAPTURE(q.transpose(), qd.transpose());
      // L and b of every node by finite differences of the poses.
      MatX L(3 * N, 3 + n_f);
      VecX b(3 * N);
      for (int k = 0; k < N; ++k) {
        L.middleRows(3 * k, 3) = fd_map(data->nodes[k], q);
        b.segment<3>(3 * k) = fd_acceleration(data->nodes[k], q, qd, VecX::Zero(3 + n_f));
      }
      const VecX expected = -L.transpose() * (M_FE * b);
      const VecX Qv = quadratic_velocity_vector(*data, q, qd);
      const double scale = expected.cwiseAbs().maxCoeff();
      CHECK_CLOSE_NAMED("your Q_v", Qv, expected, (Tolerance{1e-6 * scale, 1e-6}), qv_hint(Qv, expected, *data, q, qd));

      // The power balance: what Q_v does beyond -1/2 q_dot^T M_dot q_dot is the documented error.
      const double h = 1e-5;
      const MatX M_dot = (mass_oracle(*data, q + h * qd) - mass_oracle(*data, q - h * qd)) / (2 * h);
      const VecX w = L * qd;
      const double power_error = -qd(2) * w.dot(M_FE * stacked_tilde(N) * w);
      const double power = qd.dot(Qv) + 0.5 * qd.dot(M_dot * qd);
      const double power_scale = std::abs(qd.dot(Qv)) + std::abs(0.5 * qd.dot(M_dot * qd));
      CHECK_NEAR_NAMED(
          "the power of your Q_v and M(q)", power, power_error, (Tolerance{1e-6 * power_scale, 1e-6}),
          "power of Q_v: q_dot^T Q_v = -1/2 q_dot^T M_dot q_dot - theta_dot w^T M_FE I~ w for Q_v = -L^T M_FE b "
          "(check the Q_v sign and b)");
    }
  }
}
