// Module 5, task T5: modal analysis of beams built by the tests themselves: the Euler-Bernoulli
// table for more end conditions, axial bar frequencies (continuous and the exact discrete ones of
// linear elements), the convergence order of the frequency error under mesh refinement, and the
// sine shapes of a pinned-pinned beam (hidden tests).
#include <cmath>
#include <string>
#include <vector>

#include "fe_checks.hpp"
#include "fe_oracles.hpp"
#include "fmbd/modal.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m05;

namespace {

Modes checked_modes(const MatX& K, const MatX& M, int count) {
  const Modes modes = modal_analysis(K, M, count);
  INFO("hint: omega has `count` entries and shapes n x count columns");
  REQUIRE(modes.omega.size() == count);
  REQUIRE(modes.shapes.rows() == K.rows());
  REQUIRE(modes.shapes.cols() == count);
  return modes;
}

}  // namespace

GRADED_TEST("modal_analysis pinned clamped and mixed beams match the Euler-Bernoulli table", "[M05][T5][points=1]") {
  // Blevins, Formulas for Natural Frequency and Mode Shape, table 8-1; the consistent-mass
  // discretisation error of `elements` Hermite elements is (beta h)^4 / 1440 to leading order.
  Random rnd(5511);
  for (Ends ends : {Ends::pinned_pinned, Ends::clamped_clamped, Ends::clamped_pinned}) {
    const double L = rnd.uniform(0.5, 3.0), angle = rnd.uniform(-3.0, 3.0);
    const Section s = random_slender_section(rnd, L);
    const int elements = 24, count = 5;
    CAPTURE(name_of(ends), L, angle, s.E, s.rho, s.A, s.I);
    const BeamProblem p = beam_problem(L, angle, s, elements, ends, MassMatrixType::consistent, rnd.vec2(-1, 1));
    const Modes modes = checked_modes(p.K, p.M, count);
    const std::string hint = omega_hint(modes.omega, p.K, p.M, count);
    const auto table = beta_L(ends);
    for (int i = 0; i < 4; ++i) {
      const double expected = bending_omega(table[i], s, L), bh = table[i] / elements;
      CAPTURE(i, table[i], expected);
      CHECK_NEAR_NAMED("your omega(i) of the beam",
                       modes.omega(i), expected, (Tolerance{0, bh * bh * bh * bh / 720 + 1e-9}), hint);
    }
  }
}

GRADED_TEST("modal_analysis axial bar frequencies match the closed forms", "[M05][T5][points=1]") {
  // A beam along x reduced to its axial DOFs u_x (the other DOFs removed here): a bar. Continuous:
  // fixed-free omega_j = (2j - 1) pi/2 c / L, free-free j pi c / L (after one rigid mode at 0),
  // c = sqrt(E / rho). Linear elements of length h reproduce the modes sin(k x), cos(k x) at the
  // nodes exactly, with theta = k h:
  //   consistent mass: omega_h^2 = 6 c^2 / h^2 (1 - cos theta) / (2 + cos theta)
  //   lumped mass:     omega_h^2 = 2 c^2 / h^2 (1 - cos theta)
  // and omega_h / omega - 1 = +theta^2 / 24 resp. -theta^2 / 24 to leading order.
  Random rnd(5512);
  for (MassMatrixType type : {MassMatrixType::consistent, MassMatrixType::lumped}) {
    for (Ends ends : {Ends::clamped_free, Ends::free_free}) {
      const double L = rnd.uniform(0.5, 3.0);
      const Section s = random_section(rnd);
      const int elements = 30, rigid = ends == Ends::free_free ? 1 : 0, count = rigid + 4;
      const double c = std::sqrt(s.E / s.rho), h = L / elements;
      CAPTURE(type == MassMatrixType::consistent ? "consistent" : "lumped", name_of(ends), L, c);
      const FeModel fe = straight_beam(L, elements, s, rnd.vec2(-1, 1));
      const FeMatrices full = assemble_by_hand(fe, type);
      std::vector<int> axial;
      for (int k = ends == Ends::clamped_free ? 1 : 0; k <= elements; ++k) axial.push_back(3 * k);
      const MatX K = rows_cols(full.K, axial), M = rows_cols(full.M, axial);
      const Modes modes = checked_modes(K, M, count);
      const std::string hint = omega_hint(modes.omega, K, M, count);
      if (rigid) {
        INFO("hint: the free bar translates freely: omega_0 = 0 (clamp round-off negatives of lambda to 0). " << hint);
        CHECK(std::abs(modes.omega(0)) < 1e-4 * c / L);
      }
      for (int j = 1; j <= 4; ++j) {
        const double k = (ends == Ends::clamped_free ? (2 * j - 1) * kPi / 2 : j * kPi) / L, theta = k * h;
        const double discrete2 = type == MassMatrixType::consistent
                                     ? 6 * c * c / (h * h) * (1 - std::cos(theta)) / (2 + std::cos(theta))
                                     : 2 * c * c / (h * h) * (1 - std::cos(theta));
        const double omega = modes.omega(rigid + j - 1);
        CAPTURE(j, k * c, std::sqrt(discrete2), omega);
        CHECK_NEAR_NAMED("your omega of the bar, against the discrete closed form",
                         omega, std::sqrt(discrete2), (Tolerance{0, 1e-10}), hint);
        CHECK_NEAR_NAMED("your omega of the bar, against the continuous bar",
                         omega, k * c, (Tolerance{0, theta * theta / 12}), hint);
      }
    }
  }
}

GRADED_TEST("modal_analysis frequency error converges at order 4 with consistent and 2 with lumped mass",
            "[M05][T5][points=1]") {
  // Pinned-pinned beam, first two modes, 8, 16 and 32 elements: the relative error of omega falls
  // like h^4 with consistent mass and like h^2 with lumped mass; the order is log2(e(h) / e(h/2)).
  Random rnd(5513);
  const double L = rnd.uniform(0.5, 3.0), angle = rnd.uniform(-3.0, 3.0);
  const Section s = random_slender_section(rnd, L);
  CAPTURE(L, angle, s.E, s.rho, s.A, s.I);
  for (MassMatrixType type : {MassMatrixType::consistent, MassMatrixType::lumped}) {
    const double order = type == MassMatrixType::consistent ? 4.0 : 2.0;
    double previous[2] = {0, 0};
    for (int elements : {8, 16, 32}) {
      CAPTURE(type == MassMatrixType::consistent ? "consistent" : "lumped", elements);
      const BeamProblem p = beam_problem(L, angle, s, elements, Ends::pinned_pinned, type);
      const Modes modes = checked_modes(p.K, p.M, 2);
      const std::string hint = omega_hint(modes.omega, p.K, p.M, 2);
      for (int i = 0; i < 2; ++i) {
        const double error = rel_error(modes.omega(i), bending_omega((i + 1) * kPi, s, L));
        CAPTURE(i, error);
        CHECK_NEAR_NAMED("the relative error of your omega(i) against the Euler-Bernoulli value",
                         error, 0.0, (Tolerance{type == MassMatrixType::consistent ? 1e-3 : 0.05, 0}), hint);
        if (previous[i] > 0) {
          const double measured = std::log2(previous[i] / error);
          CAPTURE(previous[i], measured);
          CHECK_NEAR_NAMED("the convergence order of your omega(i)'s error",
                           measured, order, (Tolerance{0.3, 0}), hint);
        }
        previous[i] = error;
      }
    }
  }
}

GRADED_TEST("modal_analysis pinned-pinned mode shapes are sines", "[M05][T5][points=1]") {
  // The transverse displacement of mode j at the nodes is proportional to sin(j pi x / L) (exact at
  // the nodes of a uniform mesh); the sign of a shape is free, so compare up to sign.
  Random rnd(5514);
  for (MassMatrixType type : {MassMatrixType::consistent, MassMatrixType::lumped}) {
    const double L = rnd.uniform(0.5, 3.0), angle = rnd.uniform(-3.0, 3.0);
    const Section s = random_slender_section(rnd, L);
    const int elements = 20, count = 4;
    CAPTURE(type == MassMatrixType::consistent ? "consistent" : "lumped", L, angle);
    const BeamProblem p = beam_problem(L, angle, s, elements, Ends::pinned_pinned, type, rnd.vec2(-1, 1));
    const Modes modes = checked_modes(p.K, p.M, count);
    const std::string hint = omega_hint(modes.omega, p.K, p.M, count);
    const Vec2 nrm = perp(Vec2(std::cos(angle), std::sin(angle)));
    for (int j = 1; j <= count; ++j) {
      // Full shape (zeros at the hinged DOFs), then its transverse component at every node.
      VecX full = VecX::Zero(p.fe.num_dofs());
      for (std::size_t r = 0; r < p.free.size(); ++r) full(p.free[r]) = modes.shapes(static_cast<Eigen::Index>(r), j - 1);
      VecX v(elements + 1), sine(elements + 1);
      for (int k = 0; k <= elements; ++k) {
        v(k) = nrm.dot(full.segment<2>(3 * k));
        sine(k) = std::sin(j * kPi * k / elements);
      }
      CAPTURE(j);
      const double scale = v.norm();
      INFO("hint: mode " << j << " of a pinned-pinned beam bends like sin(j pi x / L). " << hint);
      REQUIRE(scale > 0);
      const VecX shape = v / scale * (v.dot(sine) < 0 ? -1.0 : 1.0);
      CHECK_CLOSE_NAMED("the transverse displacements of your mode j, normalised",
                        shape, VecX(sine / sine.norm()), (Tolerance{1e-7, 0}), hint);
    }
  }
}
