// Module 5, task T4: repeated supports, and supported beams solved by the given static_solve
// (which uses the student's DofMap, reduce and expand) against beam theory; K and M are the tests'
// own (hidden tests).
#include <cmath>
#include <string>
#include <vector>

#include "fe_checks.hpp"
#include "fe_oracles.hpp"
#include "fmbd/modal.hpp"
#include "fmbd/supports.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m05;

namespace {

// The likely T4 mistake behind a wrong static solution: the free list, else reduce or expand.
std::string solve_hint(const FeModel& fe, const FeMatrices& mats, const std::vector<NodeSupport>& supports,
                       const DofMap& map, const VecX& F) {
  if (map.free != free_dofs_by_hand(fe.num_nodes(), supports)) return free_list_hint(fe.num_nodes(), supports, map.free);
  const MatX K_ff = reduce(mats.K, map);
  if (!compare(K_ff, rows_cols(mats.K, map.free), Tolerance{1e-14, 0}).ok) return reduce_matrix_hint(mats.K, map, K_ff);
  const VecX F_f = reduce(F, map);
  if (!compare(F_f, VecX(F(map.free)), Tolerance{1e-14, 0}).ok) return reduce_vector_hint(F, map, F_f);
  const VecX u_f = VecX::LinSpaced(map.num_free(), 1.0, 2.0);
  return expand_hint(u_f, map, expand(u_f, map));
}

// static_solve, with the hint on a SingularStiffness (supports that leave the beam free to move);
// returns NaNs then, so that the comparison fails as well.
VecX solve_checked(const FeModel& fe, const FeMatrices& mats, const DofMap& map, const VecX& F,
                   const std::string& hint) {
  try {
    return static_solve(fe, mats, map, F);
  } catch (const SingularStiffness& error) {
    INFO("hint: " << hint);
    FAIL_CHECK(error.what());
  }
  return VecX::Constant(fe.num_dofs(), std::nan(""));
}

}  // namespace

GRADED_TEST("apply_supports repeated supports fix the union of their DOFs", "[M05][T4][points=1]") {
  const std::vector<std::vector<NodeSupport>> cases = {
      {{1, Support::hinged}, {1, Support::clamped}},
      {{1, Support::clamped}, {1, Support::hinged}},
      {{0, Support::clamped}, {0, Support::free}},
      {{2, Support::free}, {2, Support::hinged}},
      {{2, Support::hinged}, {0, Support::hinged}, {2, Support::hinged}},
      {{3, Support::hinged}, {1, Support::free}, {3, Support::clamped}, {3, Support::free}, {1, Support::hinged}},
  };
  for (const std::vector<NodeSupport>& supports : cases) {
    const FeModel fe = straight_beam(2.0, 3, square_section(2e11, 7800, 0.02));
    CAPTURE(describe(supports));
    const DofMap map = apply_supports(fe, supports);
    const std::vector<int> expected = free_dofs_by_hand(fe.num_nodes(), supports);
    CAPTURE(as_vec(map.free).transpose(), as_vec(expected).transpose());
    CHECK(map.num_dofs == fe.num_dofs());
    CHECK_CLOSE_NAMED("your DofMap::free", as_vec(map.free), as_vec(expected), (Tolerance{1e-14, 0}),
                      free_list_hint(fe.num_nodes(), supports, map.free));
  }
}

GRADED_TEST("apply_supports and static_solve give the simply supported and cantilever deflections",
            "[M05][T4][points=1]") {
  Random rnd(5411);
  for (int n = 0; n < 3; ++n) {
    const double L = rnd.uniform(0.5, 3.0), angle = rnd.uniform(-3.1, 3.1);
    const Section s = square_section(rnd.uniform(60e9, 210e9), rnd.uniform(2000, 8000), L * rnd.uniform(0.01, 0.05));
    const int elements = 2 * (2 + n);
    const FeModel fe = straight_beam(L, elements, s, rnd.vec2(-1, 1), angle);
    const FeMatrices mats = assemble_by_hand(fe, MassMatrixType::consistent);
    const Vec2 e(std::cos(angle), std::sin(angle)), nrm = perp(e);
    const double EI = s.E * s.I, P = rnd.uniform(-1e3, 1e3);
    CAPTURE(n, L, angle, elements, P);
    {
      // Hinged at both ends, P across the beam at mid-span: for x <= L/2,
      //   v = P x (3 L^2 - 4 x^2) / 48 EI,  psi = P (L^2 - 4 x^2) / 16 EI  (symmetric about L/2).
      const std::vector<NodeSupport> supports = {{0, Support::hinged}, {elements, Support::hinged}};
      const DofMap map = apply_supports(fe, supports);
      VecX F = VecX::Zero(fe.num_dofs());
      F.segment<2>(3 * (elements / 2)) = P * nrm;
      VecX expected(fe.num_dofs());
      for (int k = 0; k <= elements; ++k) {
        const double x = L * k / elements, xs = std::min(x, L - x), sign = x <= L / 2 ? 1.0 : -1.0;
        expected.segment<2>(3 * k) = P * xs * (3 * L * L - 4 * xs * xs) / (48 * EI) * nrm;
        expected(3 * k + 2) = sign * P * (L * L - 4 * xs * xs) / (16 * EI);
      }
      const std::string hint = solve_hint(fe, mats, supports, map, F);
      const VecX u = solve_checked(fe, mats, map, F, hint);
      CHECK_CLOSE_NAMED("the simply supported beam's deflection u with your supports",
                        u, expected, (Tolerance{1e-8 * expected.cwiseAbs().maxCoeff(), 1e-7}), hint);
      // expand puts exact zeros at the supported DOFs.
      for (int i : {0, 1, 3 * elements, 3 * elements + 1}) {
        CAPTURE(i);
        CHECK_NEAR_NAMED("your u(i) at a supported DOF",
                         u(i), 0.0, (Tolerance{1e-300, 0}), "expand puts zeros at fixed DOFs (the supports)");
      }
    }
    {
      // Clamped at the last node, P across the beam at node 0: v = P r^2 (3L - r) / 6EI at
      // distance r = L - x from the clamp, psi = -P r (2L - r) / 2EI (x runs away from the clamp).
      const std::vector<NodeSupport> supports = {{elements, Support::clamped}};
      const DofMap map = apply_supports(fe, supports);
      VecX F = VecX::Zero(fe.num_dofs());
      F.segment<2>(0) = P * nrm;
      VecX expected(fe.num_dofs());
      for (int k = 0; k <= elements; ++k) {
        const double r = L - L * k / elements;
        expected.segment<2>(3 * k) = P * r * r * (3 * L - r) / (6 * EI) * nrm;
        expected(3 * k + 2) = -P * r * (2 * L - r) / (2 * EI);
      }
      const std::string hint = solve_hint(fe, mats, supports, map, F);
      const VecX u = solve_checked(fe, mats, map, F, hint);
      CHECK_CLOSE_NAMED("the cantilever's deflection u with your supports",
                        u, expected, (Tolerance{1e-8 * expected.cwiseAbs().maxCoeff(), 1e-7}), hint);
    }
  }
}
