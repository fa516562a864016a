// Module 6, task T2: modal truncation on free-free modes (visible tests).
// The oracles: the free-free Euler-Bernoulli frequencies (Blevins, table 8-1), the rigid-body
// integrals of reduction_checks.hpp, and the full generalised eigenproblem solved by Eigen.
#include <cmath>
#include <string>

#include "fmbd/fe_assembly.hpp"
#include "fmbd/reduction.hpp"
#include "grading.hpp"
#include "reduction_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m06;

namespace {

// Hint for wrong elastic frequencies sqrt(K_bar_ii): which slip reproduces them.
std::string truncation_frequency_hint(const VecX& got, const VecX& full_elastic) {
  const int k = static_cast<int>(full_elastic.size());
  VecX kept_zero = VecX::Zero(k);
  for (int i = 3; i < k; ++i) kept_zero(i) = full_elastic(i - 3);
  return diagnose(got, full_elastic,
                  {{"your Phi_f: rigid (zero) modes kept in Phi_f: skip the first three free-free modes",
                    kept_zero}},
                  with_formula("your Phi_f must be the lowest elastic free-free modes, mass-normalised",
                               "Phi_f = modes 4 .. 3 + k of K phi = omega^2 M phi, K_bar = diag(0, 0, 0, omega_1^2, "
                               "..., omega_k^2)"),
                  Tolerance{1e-6, 1e-6});
}

// Hint for a wrong M_bar.
std::string truncation_mass_hint(const MatX& M_bar, const MatX& expected) {
  if (M_bar.rows() != expected.rows() || M_bar.cols() != expected.cols())
    return "M_bar is (3 + k) x (3 + k): Phi = [Phi_r, Phi_f] has 3 + num_elastic columns";
  MatX identity_rigid = expected;
  identity_rigid.topLeftCorner(3, 3).setIdentity();
  return diagnose(flat(M_bar), flat(expected),
                  {{"rigid columns must be Phi_r from rigid_body_modes (M_bar starts with diag(m, m, J)), not the zero "
                    "modes of the eigensolver",
                    flat(identity_rigid)}},
                  with_formula("your M_bar: Phi_r must be about the centroid, Phi_f the mass-normalised elastic "
                               "free-free modes (rigid (zero) modes kept in Phi_f give off-diagonal terms)",
                               "M_bar = diag(m, m, J, 1, ..., 1)"),
                  Tolerance{1e-6, 1e-6});
}

}  // namespace

GRADED_TEST("modal_truncation free-free beam M_bar and K_bar diagonal with the betaL frequencies",
            "[M06][T2][points=2]") {
  Random rnd(6201);
  const double L = 2.0;
  const Section s = steel(0.02);
  const FeModel fe = straight_beam(L, 30, s, Vec2(rnd.uniform(-2, -1), rnd.uniform(1, 2)), rnd.uniform(0.3, 1.2));
  const FeMatrices fm = assemble(fe, MassMatrixType::consistent);
  const RigidOracle o = rigid_oracle(fe, MassMatrixType::consistent);
  const int k = 5;
  const VecX full = frequencies(fm.K, fm.M);
  const VecX full_elastic = full.segment(3, k);

  const ReducedBasis b = modal_truncation(fe, fm, k);
  {
    INFO("hint: Phi = [Phi_r, Phi_f] is n x (3 + num_elastic) with num_rigid = 3");
    CHECK(b.num_rigid == 3);
    REQUIRE(b.Phi.rows() == fe.num_dofs());
    REQUIRE(b.Phi.cols() == 3 + k);
    REQUIRE(b.M_bar.rows() == 3 + k);
    REQUIRE(b.M_bar.cols() == 3 + k);
    REQUIRE(b.K_bar.rows() == 3 + k);
    REQUIRE(b.K_bar.cols() == 3 + k);
  }
  CHECK_CLOSE(b.M_bar, MatX(b.Phi.transpose() * fm.M * b.Phi), (Tolerance{1e-10 * o.mass, 1e-10}),
              with_formula("your M_bar is not the reduced mass matrix of your returned Phi", "M_bar = Phi^T M Phi"));
  const double w2_max = full_elastic(k - 1) * full_elastic(k - 1);
  CHECK_CLOSE(b.K_bar, MatX(b.Phi.transpose() * fm.K * b.Phi), (Tolerance{1e-10 * w2_max, 1e-10}),
              with_formula("your K_bar is not the reduced stiffness matrix of your returned Phi", "K_bar = Phi^T K Phi"));

  VecX diag_M(3 + k);
  diag_M << o.mass, o.mass, o.inertia, VecX::Ones(k);
  const MatX M_expected = diag_M.asDiagonal();
  CHECK_CLOSE(b.M_bar, M_expected, (Tolerance{1e-8 * o.mass, 1e-9}), truncation_mass_hint(b.M_bar, M_expected));

  VecX diag_K = VecX::Zero(3 + k);
  diag_K.tail(k) = full_elastic.cwiseProduct(full_elastic);
  const VecX got = diagonal_frequencies(b.K_bar, 3);
  CAPTURE(got.transpose(), full_elastic.transpose());
  CHECK_CLOSE(b.K_bar, MatX(diag_K.asDiagonal()), (Tolerance{1e-9 * w2_max, 1e-8}),
              truncation_frequency_hint(got, full_elastic));
  // Against the continuous beam: the discretisation error of 30 Hermite elements stays below 4e-5.
  const VecX betaL = free_free_omegas(s, L, 4);
  CHECK_CLOSE_NAMED("the first four elastic frequencies of your K_bar",
                    VecX(got.head(4)), betaL, (Tolerance{0.0, 1e-4}), truncation_frequency_hint(got, full_elastic));
}

GRADED_TEST("modal_truncation reduced pair reproduces the lowest full frequencies of a frame", "[M06][T2][points=2]") {
  const FeModel fe = l_frame();
  const FeMatrices fm = assemble(fe, MassMatrixType::consistent);
  const VecX full = frequencies(fm.K, fm.M);
  const MatX full_shapes = mode_shapes(fm.K, fm.M, 15);
  for (int k : {1, 4, 9}) {
    CAPTURE(k);
    const ReducedBasis b = modal_truncation(fe, fm, k);
    {
      INFO("hint: Phi = [Phi_r, Phi_f] is n x (3 + num_elastic)");
      REQUIRE(b.Phi.rows() == fe.num_dofs());
      REQUIRE(b.Phi.cols() == 3 + k);
    }
    // Eigenvalues of the reduced pair, computed here from the returned Phi.
    const MatX Kr = b.Phi.transpose() * fm.K * b.Phi, Mr = b.Phi.transpose() * fm.M * b.Phi;
    const VecX reduced = frequencies(Kr, Mr);
    const VecX expected = full.head(3 + k);
    CAPTURE(reduced.transpose(), expected.transpose());
    const VecX full_elastic = full.segment(3, k);
    // Three zero (rigid) frequencies, round-off aside, then the k lowest elastic ones exactly.
    const std::string hint = truncation_frequency_hint(diagonal_frequencies(b.K_bar, 3), full_elastic);
    CHECK_CLOSE_NAMED("the three rigid frequencies of your reduced model",
                      VecX(reduced.head(3)), VecX(VecX::Zero(3)), (Tolerance{1e-4 * full(3), 0.0}), hint);
    CHECK_CLOSE_NAMED("the k elastic frequencies of your reduced model",
                      VecX(reduced.tail(k)), full_elastic, (Tolerance{0.0, 1e-8}), hint);
    // The elastic columns span the full modes 4 .. 3 + k: the M-projection leaves nothing.
    const MatX Phi_f = b.Phi.rightCols(k);
    const MatX modes = full_shapes.middleCols(3, k);
    const MatX residual = modes - Phi_f * (Phi_f.transpose() * fm.M * modes);
    CHECK_CLOSE_NAMED("the part of the full modes 4 to 3 + k outside your Phi_f",
                      MatX(residual.transpose() * fm.M * residual), MatX(MatX::Zero(k, k)), (Tolerance{1e-10, 0.0}),
                      truncation_frequency_hint(diagonal_frequencies(b.K_bar, 3), full_elastic));
  }
}

GRADED_TEST("modal_truncation sizes from no elastic mode to all and num_elastic out of range", "[M06][T2][points=1]") {
  const FeModel fe = straight_beam(1.2, 4, steel(0.03), Vec2(0.5, -0.7), 0.4);
  const FeMatrices fm = assemble(fe, MassMatrixType::consistent);
  const int n = fe.num_dofs();
  const RigidOracle o = rigid_oracle(fe, MassMatrixType::consistent);

  const ReducedBasis none = modal_truncation(fe, fm, 0);
  {
    INFO("hint: num_elastic = 0 gives Phi = Phi_r alone: 3 columns, num_rigid = 3");
    CHECK(none.size() == 3);
    CHECK(none.num_rigid == 3);
    CHECK(none.num_elastic() == 0);
  }
  if (none.Phi.rows() == n && none.Phi.cols() == 3) {
    CHECK_CLOSE_NAMED("your Phi with num_elastic = 0",
                      none.Phi, rigid_columns(fe, o.centroid), (Tolerance{1e-10, 1e-10}), phi_r_hint(fe, none.Phi, o));
  }

  const ReducedBasis all = modal_truncation(fe, fm, n - 3);
  {
    INFO("hint: num_elastic = n - 3 keeps every elastic mode: Phi is n x n");
    CHECK(all.size() == n);
    CHECK(all.num_rigid == 3);
    CHECK(all.num_elastic() == n - 3);
  }
  if (all.Phi.rows() == n && all.Phi.cols() == n) {
    const VecX full = frequencies(fm.K, fm.M);
    const VecX reduced =
        frequencies(MatX(all.Phi.transpose() * fm.K * all.Phi), MatX(all.Phi.transpose() * fm.M * all.Phi));
    const char* hint = "with every elastic mode the reduced pair has all the frequencies of the full model";
    CHECK_CLOSE_NAMED("the three rigid frequencies of your reduced model with every elastic mode",
                      VecX(reduced.head(3)), VecX(VecX::Zero(3)), (Tolerance{1e-4 * full(3), 0.0}), hint);
    CHECK_CLOSE_NAMED("the elastic frequencies of your reduced model with every elastic mode",
                      VecX(reduced.tail(n - 3)), VecX(full.tail(n - 3)), (Tolerance{0.0, 1e-8}), hint);
  }

  check_throws_mentioning<std::invalid_argument>([&] { modal_truncation(fe, fm, -1); }, "",
                                                 "modal_truncation: num_elastic = -1 is out of range 0 .. n - 3");
  check_throws_mentioning<std::invalid_argument>([&] { modal_truncation(fe, fm, n - 2); }, "",
                                                 "modal_truncation: num_elastic = n - 2 is out of range 0 .. n - 3");
}
