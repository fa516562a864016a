// Module 3, task T1: the mass matrix (visible tests).
#include <string>

#include "dynamics_checks.hpp"
#include "fmbd/mass_matrix.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m03;

namespace {

// A model of n_b free bodies with random masses and inertias.
Model random_bodies(Random& rnd, int n_b) {
  Model m;
  for (int k = 0; k < n_b; ++k)
    m.add_body("body " + std::to_string(k), rnd.uniform(0.5, 5.0), rnd.uniform(0.01, 2.0), rnd.vec3(-1, 1));
  return m;
}

// Hint for a wrong mass matrix: which slip of diag(m_k, m_k, J_k) reproduces it.
std::string mass_hint(const Model& model, const MatX& M) {
  const VecX d = mass_diagonal(model);
  VecX with_m = d, without_J = d, swapped = d;
  for (int k = 0; k < model.num_bodies(); ++k) {
    with_m(3 * k + 2) = d(3 * k);
    without_J(3 * k + 2) = 0.0;
    swapped.segment<3>(3 * k) << d(3 * k + 2), d(3 * k + 2), d(3 * k);
  }
  if (M.rows() != d.size() || M.cols() != d.size())
    return "your M is not n x n (n = " + std::to_string(d.size()) + "): one row and column per coordinate";
  const char* block = "block k = diag(m_k, m_k, J_k) at rows and columns 3k .. 3k+2";
  return diagnose(flat(M), flat(MatX(d.asDiagonal())),
                  {{with_formula("your M has m_k where J_k belongs? The phi entry of body k is its inertia", block),
                    flat(MatX(with_m.asDiagonal()))},
                   {with_formula("your M: J_k missing? The phi entry of body k is its inertia", block),
                    flat(MatX(without_J.asDiagonal()))},
                   {with_formula("your M has m_k and J_k swapped on the coordinates (x_k, y_k, phi_k)", block),
                    flat(MatX(swapped.asDiagonal()))}},
                  with_formula("your M is not the bodies' masses and inertias on the diagonal, zero elsewhere", block));
}

}  // namespace

GRADED_TEST("mass_matrix kinetic energy 1/2 qd^T M qd equals the sum over the bodies", "[M03][T1][points=2]") {
  Random rnd(3101);
  for (int n_b = 1; n_b <= 4; ++n_b) {
    const Model model = random_bodies(rnd, n_b);
    const MatX M = mass_matrix(model);
    const std::string hint = mass_hint(model, M);
    INFO("hint: " << hint);
    REQUIRE(M.rows() == 3 * n_b);
    REQUIRE(M.cols() == 3 * n_b);
    for (int trial = 0; trial < 3; ++trial) {
      const VecX qd = rnd.vector(3 * n_b, -2, 2);
      // By hand: T = sum_k 1/2 m_k (x_dot^2 + y_dot^2) + 1/2 J_k phi_dot^2, momentum (m v, m v, J w).
      double T = 0;
      VecX momentum(3 * n_b);
      for (int k = 0; k < n_b; ++k) {
        const Body& b = model.bodies()[k];
        const double vx = qd(3 * k), vy = qd(3 * k + 1), w = qd(3 * k + 2);
        T += 0.5 * b.mass * (vx * vx + vy * vy) + 0.5 * b.inertia * w * w;
        momentum.segment<3>(3 * k) << b.mass * vx, b.mass * vy, b.inertia * w;
      }
      CAPTURE(n_b, trial);
      CHECK_NEAR_NAMED("the kinetic energy of your M", 0.5 * qd.dot(M * qd), T, kExact, hint);
      CHECK_CLOSE_NAMED("the momentum M q_dot of your M", M * qd, momentum, kExact, hint);
    }
  }
}

GRADED_TEST("mass_matrix is symmetric diagonal and positive definite", "[M03][T1][points=1]") {
  Random rnd(3102);
  const Model model = random_bodies(rnd, 3);
  const MatX M = mass_matrix(model);
  const std::string hint = mass_hint(model, M);
  REQUIRE(M.rows() == 9);
  REQUIRE(M.cols() == 9);
  CHECK_CLOSE_NAMED("your M against its transpose", M, M.transpose(), kExact, hint);
  CHECK_CLOSE_NAMED("the diagonal part of your M against all of it", MatX(M.diagonal().asDiagonal()), M, kExact,
                    "centroidal coordinates decouple translation and rotation: every off-diagonal entry of M is zero");
  for (int k = 0; k < 9; ++k) {
    INFO("hint: " << hint);
    CAPTURE(k);
    CHECK(M(k, k) > 0);
  }
  CHECK_CLOSE_NAMED("the diagonal of your M", M.diagonal(), mass_diagonal(model), kExact, hint);
  // The slider-crank of the examples: crank, rod, slider.
  const Model sc = examples::slider_crank();
  const MatX Msc = mass_matrix(sc);
  CHECK_CLOSE_NAMED("your M of the slider-crank", Msc, MatX(mass_diagonal(sc).asDiagonal()), kExact,
                    mass_hint(sc, Msc));
}
