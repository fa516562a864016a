// Module 5, task T5: modal analysis of beams whose K and M are built by the tests themselves
// (element matrices integrated from the shape functions, chained along the beam, supported here),
// so that only modal_analysis is graded: Euler-Bernoulli frequencies against the published
// tables, mass normalisation and orthogonality of the shapes, and the rigid-body modes of a free
// beam (visible tests).

#include <cmath>
#include <string>

#include "fe_checks.hpp"
#include "fmbd/modal.hpp"
#include "grading.hpp"
#include "linear_algebra.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m05;

namespace {

// Relative frequency error allowed for bending mode `betaL` on `elements` Hermite elements with
// consistent mass: the discretisation error is (beta h)^4 / 1440 to leading order (h = L /
// elements); twice that, plus round-off.
double bending_tolerance(double betaL, int elements) {
  const double bh = betaL / elements;
  return bh * bh * bh * bh / 720 + 1e-9;
}

}  // namespace

GRADED_TEST("modal_analysis cantilever frequencies match the Euler-Bernoulli table", "[M05][T5][points=2]") {
  // omega_i = (beta_i L)^2 sqrt(EI / (rho A L^4)), beta_i L = 1.87510407, 4.69409113, 7.85475744,
  // 10.99554073 (R. D. Blevins, Formulas for Natural Frequency and Mode Shape, table 8-1).
  Random rnd(5501);
  for (int n = 0; n < 3; ++n) {
    const double L = rnd.uniform(0.5, 3.0), angle = rnd.uniform(-3.0, 3.0);
    const Section s = random_slender_section(rnd, L);
    const int elements = 24, count = 6;
    CAPTURE(n, L, angle, s.E, s.rho, s.A, s.I, elements);
    const BeamProblem p = beam_problem(L, angle, s, elements, Ends::clamped_free, MassMatrixType::consistent);
    const Modes modes = modal_analysis(p.K, p.M, count);
    {
      INFO("hint: omega has `count` entries and shapes n x count columns");
      REQUIRE(modes.omega.size() == count);
      REQUIRE(modes.shapes.rows() == p.K.rows());
      REQUIRE(modes.shapes.cols() == count);
    }
    const std::string hint = omega_hint(modes.omega, p.K, p.M, count);
    const auto table = beta_L(Ends::clamped_free);
    for (int i = 0; i < 4; ++i) {
      const double expected = bending_omega(table[i], s, L);
      CAPTURE(i, table[i], expected, modes.omega(i));
      CHECK_NEAR_NAMED("your omega(i) of the clamped-free beam",
                       modes.omega(i), expected, (Tolerance{0, bending_tolerance(table[i], elements)}), hint);
    }
    for (int i = 0; i + 1 < count; ++i) {
      INFO("hint: " << hint);
      CHECK(modes.omega(i) <= modes.omega(i + 1));
    }
  }
}

GRADED_TEST("modal_analysis shapes are mass-normalised and K-orthogonal", "[M05][T5][points=1]") {
  // Phi^T M Phi = I, Phi^T K Phi = diag(omega^2) and K phi = omega^2 M phi on a clamped-pinned beam.
  Random rnd(5502);
  for (MassMatrixType type : {MassMatrixType::consistent, MassMatrixType::lumped}) {
    const double L = rnd.uniform(0.5, 3.0), angle = rnd.uniform(-3.0, 3.0);
    const Section s = square_section(rnd.uniform(60e9, 210e9), rnd.uniform(2000, 8000), L * rnd.uniform(0.01, 0.03));
    const BeamProblem p = beam_problem(L, angle, s, 8, Ends::clamped_pinned, type, rnd.vec2(-1, 1));
    const MatX& K = p.K;
    const MatX& M = p.M;
    const int count = 8;
    CAPTURE(type == MassMatrixType::consistent ? "consistent" : "lumped", L, angle, count);
    const Modes modes = modal_analysis(K, M, count);
    {
      INFO("hint: omega has `count` entries and shapes n x count columns");
      REQUIRE(modes.omega.size() == count);
      REQUIRE(modes.shapes.rows() == K.rows());
      REQUIRE(modes.shapes.cols() == count);
    }
    const MatX& Phi = modes.shapes;
    const std::string shape_hint = shapes_hint(Phi, M);
    const std::string freq_hint = omega_hint(modes.omega, K, M, count);
    CHECK_CLOSE_NAMED("the modal mass matrix of your shapes",
                      MatX(Phi.transpose() * M * Phi), MatX::Identity(count, count), (Tolerance{1e-8, 0}), shape_hint);
    const double top = modes.omega.cwiseAbs2().maxCoeff();
    const MatX expected_K = modes.omega.cwiseAbs2().asDiagonal();
    CHECK_CLOSE_NAMED("the modal stiffness matrix of your shapes",
                      MatX(Phi.transpose() * K * Phi), expected_K, (Tolerance{1e-8 * top, 1e-8}),
                      with_formula("your shapes do not diagonalise K with your omega squared",
                                   "Phi^T K Phi = diag(omega^2)") + ". " + freq_hint + " / " + shape_hint);
    for (int i = 0; i < count; ++i) {
      CAPTURE(i, modes.omega(i));
      const VecX residual = K * Phi.col(i) - modes.omega(i) * modes.omega(i) * (M * Phi.col(i));
      CHECK_NEAR_NAMED("the norm of the eigenproblem's residual of your mode i",
                       residual.norm(), 0.0, (Tolerance{1e-8 * max_abs(K) * Phi.col(i).norm(), 0}),
                       with_formula("your shape does not solve the eigenproblem with its own omega",
                                    "K phi = omega^2 M phi") + ". " + freq_hint);
    }
    CHECK_CLOSE_NAMED("your omega of the clamped-pinned beam",
                      modes.omega, omegas_of(eigenvalues_by_hand(K, M).head(count)),
                      (Tolerance{1e-9 * std::sqrt(top), 1e-8}), freq_hint);
  }
}

GRADED_TEST("modal_analysis free-free beam has three rigid modes in the null space of K", "[M05][T5][points=1]") {
  Random rnd(5503);
  for (int n = 0; n < 2; ++n) {
    const double L = rnd.uniform(0.5, 3.0), angle = rnd.uniform(-3.0, 3.0);
    const Section s = random_slender_section(rnd, L);
    const int elements = 24, count = 7;
    CAPTURE(n, L, angle, s.E, s.rho, s.A, s.I);
    const BeamProblem p =
        beam_problem(L, angle, s, elements, Ends::free_free, MassMatrixType::consistent, rnd.vec2(-1, 1));
    const Modes modes = modal_analysis(p.K, p.M, count);
    {
      INFO("hint: omega has `count` entries and shapes n x count columns");
      REQUIRE(modes.omega.size() == count);
      REQUIRE(modes.shapes.cols() == count);
      REQUIRE(modes.shapes.rows() == p.K.rows());
    }
    const std::string hint = omega_hint(modes.omega, p.K, p.M, count);
    const auto table = beta_L(Ends::free_free);
    const double first_elastic = bending_omega(table[0], s, L);
    CAPTURE(modes.omega.transpose());
    // Three (near) zero frequencies: two translations and a rotation, with round-off negatives of
    // lambda clamped to zero (never NaN).
    for (int i = 0; i < 3; ++i) {
      INFO("hint: " << with_formula("your rigid-body modes' omega must be zero up to round-off, and finite (clamp "
                                    "round-off negatives of lambda)", "omega = sqrt(max(lambda, 0))")
                    << ". " << hint);
      CHECK(std::isfinite(modes.omega(i)));
      CHECK(modes.omega(i) >= 0.0);
      CHECK(modes.omega(i) < 1e-3 * first_elastic);
    }
    // Their shapes store no strain energy (K phi = 0) and span the rigid motions.
    const MatX rigid = rigid_motions(p.fe, rnd.vec2(-1, 1));
    const MatX Phi0 = modes.shapes.leftCols(3);
    for (int i = 0; i < 3; ++i) {
      CAPTURE(i);
      CHECK_NEAR_NAMED("the norm of K_FE times your rigid mode i",
                       (p.K * Phi0.col(i)).norm(), 0.0, (Tolerance{1e-6 * max_abs(p.K) * Phi0.col(i).norm(), 0}),
                       "your three lowest modes of a free body are not its rigid motions (they store no strain "
                       "energy). " + hint);
    }
    // Each rigid motion is a combination of the three shapes: least-squares residual ~ 0.
    const MatX coeffs = least_squares(Phi0, rigid);
    const double residual = (Phi0 * coeffs - rigid).norm() / rigid.norm();
    CHECK_NEAR_NAMED("the part of the rigid motions outside your first three shapes",
                     residual, 0.0, (Tolerance{1e-6, 0}),
                     "the first three shapes must span the rigid motions (translations x, y and the rotation). " + hint);
    for (int i = 0; i < 4; ++i) {
      const double expected = bending_omega(table[i], s, L);
      CAPTURE(i, table[i], expected);
      CHECK_NEAR_NAMED("your omega(3 + i) of the free-free beam",
                       modes.omega(3 + i), expected, (Tolerance{0, bending_tolerance(table[i], elements)}), hint);
    }
  }
}
