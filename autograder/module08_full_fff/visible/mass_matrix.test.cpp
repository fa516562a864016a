// Module 8, task T3: the mass matrix M(q) = L^T M_FE L (visible tests).
// The oracles: M_bar = Phi^T M_FE Phi built here from the rigid columns about the centroid and the
// body's elastic columns (the mass matrix at q_f = 0 up to the rotation of the R block), and the FE
// kinetic energy 1/2 w^T M_FE w of the nodal velocities w in frame j, taken by finite differences
// of the node poses written out in ffrf_checks.hpp.

#include <cmath>
#include <string>

#include "ffrf_checks.hpp"
#include "fmbd/ffrf.hpp"
#include "grading.hpp"
#include "linear_algebra.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m08;

GRADED_TEST("ffrf_mass_matrix symmetric positive definite and the rotated M_bar at q_f = 0", "[M08][T3][points=2]") {
  Random rnd(8301);
  const FlexibleBodyData lumped_beam =
      flexible_body_data(straight_beam(1.0, 8, square_section(2.1e11, 7850.0, 0.02)), MassMatrixType::lumped, 4);
  const FlexibleBodyData consistent_beam = flexible_body_data(
      straight_beam(1.5, 6, square_section(7e10, 2700.0, 0.03), Vec2(-0.4, 0.9), 1.1), MassMatrixType::consistent, 3);
  const FlexibleBodyData frame = flexible_body_data(l_frame(), MassMatrixType::consistent, 5);
  for (const FlexibleBodyData* data : {&lumped_beam, &consistent_beam, &frame}) {
    const int n_f = data->num_modes();
    const double scale = max_abs(reduced_mass(*data));
    for (int trial = 0; trial < 3; ++trial) {
      // q_f = 0: M(q) = T^T M_bar T, T = blockdiag(A^T, 1, I), whatever R and theta.
      VecX q0 = random_q(rnd, n_f, 0.0);
      CAPTURE(q0.transpose());
      const MatX M0 = ffrf_mass_matrix(*data, q0);
      const MatX expected0 = rotated_reduced_mass(*data, q0(2));
      CHECK_CLOSE_NAMED("your M(q) at q_f = 0", M0, expected0, (Tolerance{1e-10 * scale, 1e-10}),
                        mass_hint(M0, expected0, *data, q0));

      // q_f != 0: symmetric and positive definite.
      const VecX q = random_q(rnd, n_f, modal_scale(*data, 0.08));
      CAPTURE(q.transpose());
      const MatX M = ffrf_mass_matrix(*data, q);
      REQUIRE(M.rows() == 3 + n_f);
      REQUIRE(M.cols() == 3 + n_f);
      CHECK_CLOSE_NAMED("your M(q) against its transpose", M, MatX(M.transpose()), (Tolerance{1e-12 * scale, 0.0}),
                        "M(q) = L^T M_FE L is symmetric: the same L on both sides");
      const VecX eigenvalues = symmetric_eigenvalues(0.5 * (M + M.transpose()));
      const double smallest = eigenvalues(0);
      CAPTURE(eigenvalues.transpose());
      INFO("hint: M(q) = L^T M_FE L is positive definite: L has full column rank and M_FE is positive definite");
      CHECK(smallest > 1e-8 * scale);
    }
  }
}

GRADED_TEST("ffrf_mass_matrix kinetic energy is the FE kinetic energy of the deformed spinning body",
            "[M08][T3][points=2]") {
  Random rnd(8302);
  const FlexibleBodyData lumped_frame = flexible_body_data(l_frame(Vec2(-0.3, 0.4)), MassMatrixType::lumped, 4);
  const FlexibleBodyData consistent_beam =
      flexible_body_data(straight_beam(1.0, 8, square_section(2.1e11, 7850.0, 0.02), Vec2(0.1, 0.0), 0.3),
                         MassMatrixType::consistent, 4);
  for (const FlexibleBodyData* data : {&lumped_frame, &consistent_beam}) {
    const int n_f = data->num_modes();
    const MatX& M_FE = data->matrices.M;
    for (int trial = 0; trial < 3; ++trial) {
      const VecX q = random_q(rnd, n_f, modal_scale(*data, 0.1));
      VecX qd = rnd.vector(3 + n_f, -1.0, 1.0);
      qd(2) = rnd.uniform(1.0, 4.0);
      qd.tail(n_f) *= modal_scale(*data, 0.3);
      CAPTURE(q.transpose(), qd.transpose());
      // The nodal velocities in frame j, by finite differences of the node poses.
      const MatX W = fd_stacked_map(*data, q);
      const VecX w = W * qd;
      const double T_fe = 0.5 * w.dot(M_FE * w);
      const MatX M = ffrf_mass_matrix(*data, q);
      REQUIRE(M.rows() == 3 + n_f);
      REQUIRE(M.cols() == 3 + n_f);
      const MatX expected = W.transpose() * M_FE * W;
      const std::string hint = mass_hint(M, expected, *data, q);
      CHECK_NEAR_NAMED("the kinetic energy of your M(q)", 0.5 * qd.dot(M * qd), T_fe, (Tolerance{1e-9 * T_fe, 1e-8}),
                       hint);
      CHECK_CLOSE_NAMED("your M(q)", M, expected, (Tolerance{1e-8 * max_abs(expected), 1e-8}), hint);
    }
  }
}

GRADED_TEST("add_ffrf_mass adds M(q) of the body's own coordinates at rows and columns at .. at + 3 + n_f only",
            "[M08][T3][points=1]") {
  Random rnd(8303);
  const FlexibleBodyData data =
      flexible_body_data(straight_beam(1.2, 6, square_section(7e10, 2700.0, 0.03), Vec2(0.2, -0.1), 0.4),
                         MassMatrixType::consistent, 3);
  const int n = 3 + data.num_modes(), at = 3, size = n + 5;
  const VecX q_j = random_q(rnd, data.num_modes(), modal_scale(data, 0.08));
  VecX q = rnd.vector(size, -1.0, 1.0);
  q.segment(at, n) = q_j;  // the system's q: the body's coordinates at at .. at + n
  const VecX entries = rnd.vector(size * size, -1.0, 1.0);
  const MatX before = Eigen::Map<const MatX>(entries.data(), size, size);
  MatX M = before;
  add_ffrf_mass(data, q, at, M);
  MatX others = M - before;
  others.block(at, at, n, n).setZero();
  CHECK_CLOSE_NAMED("what your add_ffrf_mass adds outside the body's block", others, MatX(MatX::Zero(size, size)),
                    (Tolerance{0.0, 0.0}),
                    "M(q) in M: add the body's block at rows and columns at .. at + 3 + n_f only, with +=");
  const MatX added = (M - before).block(at, at, n, n), expected = mass_oracle(data, q_j);
  CHECK_CLOSE_NAMED("what your add_ffrf_mass adds at the body's block", added, expected,
                    (Tolerance{1e-9 * max_abs(expected), 1e-12}),
                    "M(q) of the body's own coordinates q_j = q.segment(at, 3 + n_f), not of q's first entries: " +
                        mass_hint(added, expected, data, q_j));
}

