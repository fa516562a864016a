// Module 8, tasks T7 and T8: geometric stiffening by the foreshortening of the beam axis (visible
// tests). Oracles: the chord shortening 1/2 int v'^2 ds of a bent Hermite element by quadrature;
// finite differences of the foreshortening as the README defines it and of the stiffened node
// pose (stiffening_checks.hpp); the geometric stiffness sum_e N_e G_e of the centrifugal tension,
// with the tension summed here from the lumped nodal masses and G_e written out (the published
// element matrix).
#include <cmath>
#include <memory>
#include <string>

#include "ffrf_checks.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/geometric_stiffening.hpp"
#include "grading.hpp"
#include "stiffening_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m08;

// ---- T7 -------------------------------------------------------------------------------------

GRADED_TEST("shortening_across_element f_k is the chord shortening 1/2 int v'^2 ds of a bent element",
            "[M08][T7][points=1]") {
  Random rnd(8701);
  for (const double l : {0.05, 0.7, 3.0}) {
    // One element whose elastic coordinates are its own DOFs (v_a, psi_a, v_b, psi_b).
    const MatX H = hermite_slope_matrix(l);
    const Eigen::Vector4d d(rnd.uniform(-0.1, 0.1) * l, rnd.uniform(-0.2, 0.2), rnd.uniform(-0.1, 0.1) * l,
                            rnd.uniform(-0.2, 0.2));
    // 1/2 int v'^2 ds by the midpoint rule on 4000 points, v the cubic Hermite interpolant.
    double shortening = 0.0;
    const int n = 4000;
    for (int i = 0; i < n; ++i) {
      const double x = (i + 0.5) / n;
      const double slope = d(0) * (-6 * x + 6 * x * x) / l + d(1) * (1 - 4 * x + 3 * x * x) +
                           d(2) * (6 * x - 6 * x * x) / l + d(3) * (-2 * x + 3 * x * x);
      shortening += 0.5 * slope * slope * l / n;
    }
    NodeShortening parent;
    parent.f = rnd.vec2(-0.01, 0.01);
    parent.J = MatX::NullaryExpr(2, 4, [&] { return rnd.uniform(-1, 1); });
    parent.c = rnd.vec2(-0.1, 0.1);
    const Vec2 t(std::cos(0.3), std::sin(0.3));
    CAPTURE(l, d.transpose(), sci(shortening));
    const NodeShortening s = shortening_across_element(parent, H, t, d, VecX::Zero(4));
    CHECK_CLOSE_NAMED("your f_k", s.f, Vec2(parent.f - shortening * t), (Tolerance{1e-9 * l, 1e-6}),
                      "f_k: the parent's foreshortening plus this element's, the shortening of its chord along "
                      "-t_e (README section 6)");
  }
}

GRADED_TEST("shortening_across_element J_k and c_k are the derivatives of f_k along a chain of elements",
            "[M08][T7][points=2]") {
  Random rnd(8702);
  for (int n_f : {1, 2, 4}) {
    for (int elements : {1, 2, 3}) {
      const Chain chain = random_chain(rnd, elements, n_f);
      const VecX q_f = rnd.vector(n_f, -0.3, 0.3), q_f_dot = rnd.vector(n_f, -2.0, 2.0);
      CAPTURE(n_f, elements, q_f.transpose(), q_f_dot.transpose());
      const NodeShortening got = chained(chain, q_f, q_f_dot);
      const NodeShortening expected = fd_shortening(chain, q_f, q_f_dot);
      REQUIRE(got.J.rows() == 2);
      REQUIRE(got.J.cols() == n_f);
      const std::string hint = shortening_hint(got, chain, q_f, q_f_dot);
      CHECK_CLOSE_NAMED("your f_k", got.f, expected.f, (Tolerance{1e-12, 1e-12}),
                        "f_k: the parent's plus -1/2 (q_f^T H_e q_f) t_e (README section 6)");
      CHECK_CLOSE_NAMED("your J_k", got.J, expected.J, (Tolerance{1e-8, 1e-8}), hint);
      CHECK_CLOSE_NAMED("your c_k", got.c, expected.c, (Tolerance{1e-6, 1e-6}), hint);
    }
  }
}

// ---- T8 -------------------------------------------------------------------------------------

GRADED_TEST("add_shortening_rows L_k q_ddot + b_k is the absolute acceleration of the foreshortened node in frame j",
            "[M08][T8][points=2]") {
  Random rnd(8801);
  for (int n_f : {1, 3}) {
    for (int trial = 0; trial < 4; ++trial) {
      const NodeModes node = random_node(rnd, n_f);
      const Chain chain = random_chain(rnd, 2, n_f);
      const VecX q = random_q(rnd, n_f, 0.3);
      VecX v = rnd.vector(3 + n_f, -2.0, 2.0);
      v(2) = (trial % 2 == 0 ? 1.0 : -1.0) * rnd.uniform(0.5, 4.0);
      const VecX a = rnd.vector(3 + n_f, -2.0, 2.0);
      CAPTURE(n_f, q.transpose(), v.transpose(), a.transpose());
      // Your rows of M08T1 and M08T2 are not under test here: start from finite-difference ones.
      const MatX L_before = fd_map(node, q);
      const Vec3 b_before = fd_acceleration(node, q, v, VecX::Zero(3 + n_f));
      const NodeShortening s = fd_shortening(chain, elastic_part(q), elastic_part(v));
      MatX L = L_before;
      Vec3 b = b_before;
      add_shortening_rows(s, v, L, b);
      const MatX L_expected = fd_stiffened_map(node, chain, q);
      const Vec3 b_expected = fd_stiffened_acceleration(node, chain, q, v, VecX::Zero(3 + n_f));
      const std::string hint = stiffened_rows_hint(L, b, L_before, b_before, node, chain, q, v, s);
      REQUIRE(L.rows() == 3);
      REQUIRE(L.cols() == 3 + n_f);
      CHECK_CLOSE_NAMED("your L_k with the foreshortening", L, L_expected, (Tolerance{1e-7, 1e-7}), hint);
      CHECK_CLOSE_NAMED("your b_k with the foreshortening", b, b_expected, (Tolerance{1e-6, 1e-6}), hint);
      CHECK_CLOSE_NAMED("the node's acceleration L_k q_ddot + b_k of yours", VecX(L * a + b),
                        VecX(fd_stiffened_acceleration(node, chain, q, v, a)), (Tolerance{1e-6, 1e-6}), hint);
    }
  }
}

GRADED_TEST("stiffened body the stiffness it adds at steady spin is the geometric stiffness of the centrifugal tension",
            "[M08][T8][points=2]") {
  // A cantilever (EI = 1, rho A = 1, L = 1, lumped mass) spinning at Omega about its clamped root:
  // element e carries N_e = Omega^2 sum_{k beyond e} m_k r_k, and its geometric stiffness
  // N_e G(l_e) acts on its transverse DOFs.
  const int elements = 4;
  const auto data = std::make_shared<FlexibleBodyData>(
      clamped_frame_body_data(straight_beam(1.0, elements, Section{1e4, 1.0, 1.0, 1e-4}), MassMatrixType::lumped, 0, 3));
  const double Omega = 2.0;
  const MatX added = spin_stiffness(StiffenedFfrfBody(data), *data, Omega) - spin_stiffness(FfrfBody(data), *data, Omega);
  const MatX M(data->matrices.M);
  const double l = 1.0 / elements;
  const int n_f = data->num_modes();
  MatX expected = MatX::Zero(n_f, n_f);
  for (int e = 0; e < elements; ++e) {
    double N = 0.0;
    for (int k = e + 1; k <= elements; ++k) N += Omega * Omega * M(3 * k, 3 * k) * (k * l);
    Mat4 G;  // N / (30 l) [36 3l -36 3l; 3l 4l^2 -3l -l^2; ...] per unit N (Przemieniecki 1968)
    G << 36, 3 * l, -36, 3 * l, 3 * l, 4 * l * l, -3 * l, -l * l, -36, -3 * l, 36, -3 * l, 3 * l, -l * l, -3 * l,
        4 * l * l;
    G /= 30 * l;
    MatX T(4, n_f);
    T << data->Phi_f.row(3 * e + 1), data->Phi_f.row(3 * e + 2), data->Phi_f.row(3 * e + 4), data->Phi_f.row(3 * e + 5);
    expected += N * T.transpose() * G * T;
  }
  CHECK_CLOSE_NAMED("the stiffness your rows add at steady spin", added, expected,
                    (Tolerance{1e-6 * expected.norm(), 1e-6}),
                    "the stiffened body's steady-spin stiffness minus the linear one's should be the geometric "
                    "stiffness of the centrifugal tension: it comes from the J_k columns of your L_k (M08T8), "
                    "through which the centrifugal force works on the foreshortening");
}
