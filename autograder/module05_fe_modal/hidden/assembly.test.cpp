// Module 5, task T3: the assembled matrices of beams at any angle have the frequencies of the same
// beam along x (and of the Euler-Bernoulli table), and whole frames with scrambled node numbers
// match an assembly written out here from the integrals of the shape functions (hidden tests).
// Frequencies here come from Eigen's own generalised eigensolver, not from modal_analysis.
#include <cmath>
#include <string>
#include <vector>

#include "fe_checks.hpp"
#include "fe_oracles.hpp"
#include "fmbd/fe_assembly.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m05;

namespace {

// The hints of K and of M of one check, each once: "K's / M's", or one of them when they agree.
std::string both_hints(const std::string& k_hint, const std::string& m_hint) {
  return k_hint == m_hint ? k_hint : k_hint + " / " + m_hint;
}

// The lowest `count` frequencies of the beam model clamped at node 0, by the test's own eigensolver.
VecX clamped_frequencies(const FeModel& fe, const FeMatrices& mats, int count) {
  const std::vector<int> free = free_dofs_by_hand(fe.num_nodes(), {{0, Support::clamped}});
  return omegas_of(eigenvalues_by_hand(rows_cols(mats.K, free), rows_cols(mats.M, free)).head(count));
}

}  // namespace

GRADED_TEST("assemble inclined cantilever has the frequencies of the same beam along x", "[M05][T3][points=1]") {
  Random rnd(5331);
  for (MassMatrixType type : {MassMatrixType::consistent, MassMatrixType::lumped}) {
    for (int n = 0; n < 3; ++n) {
      const double L = rnd.uniform(0.5, 3.0), angle = rnd.uniform(-3.1, 3.1);
      const Section s = random_slender_section(rnd, L);
      const int elements = 16, count = 6;
      CAPTURE(type == MassMatrixType::consistent ? "consistent" : "lumped", n, L, angle);
      const FeModel along_x = straight_beam(L, elements, s);
      const FeModel inclined = straight_beam(L, elements, s, rnd.vec2(-2, 2), angle);
      const FeMatrices a = assemble(along_x, type), b = assemble(inclined, type);
      {
        INFO("hint: K and M are 3N x 3N (N nodes)");
        REQUIRE(a.K.rows() == along_x.num_dofs());
        REQUIRE(a.M.rows() == along_x.num_dofs());
        REQUIRE(b.K.rows() == inclined.num_dofs());
        REQUIRE(b.M.rows() == inclined.num_dofs());
        REQUIRE(a.K.cols() == along_x.num_dofs());
        REQUIRE(a.M.cols() == along_x.num_dofs());
        REQUIRE(b.K.cols() == inclined.num_dofs());
        REQUIRE(b.M.cols() == inclined.num_dofs());
      }
      const VecX w_x = clamped_frequencies(along_x, a, count), w_inclined = clamped_frequencies(inclined, b, count);
      CAPTURE(w_x.transpose(), w_inclined.transpose());
      CHECK_CLOSE_NAMED("your omega of the inclined cantilever, against the same beam along x",
                        w_inclined, w_x, (Tolerance{0, 1e-7}),
                        "your frequencies depend on the angle of the beam. " +
                            both_hints(assembly_hint(b.K, inclined, type, true),
                                       assembly_hint(b.M, inclined, type, false)));
      // Both against Euler-Bernoulli (Blevins, table 8-1) with the discretisation error of 16
      // elements: (beta h)^4 / 1440 for consistent mass, below ~0.3 (beta h)^2 for lumped mass.
      if (type == MassMatrixType::consistent) {
        const auto table = beta_L(Ends::clamped_free);
        for (int i = 0; i < 4; ++i) {
          const double bh = table[i] / elements;
          CAPTURE(i);
          CHECK_NEAR_NAMED("your omega(i) of the cantilever along x",
                           w_x(i), bending_omega(table[i], s, L), (Tolerance{0, bh * bh * bh * bh / 720 + 1e-9}),
                           both_hints(assembly_hint(a.K, along_x, type, true),
                                      assembly_hint(a.M, along_x, type, false)));
        }
      }
    }
  }
}

GRADED_TEST("assemble frames with scrambled node numbers match an assembly by hand", "[M05][T3][points=1]") {
  Random rnd(5332);
  for (int n = 0; n < 4; ++n) {
    const Section s1 = random_section(rnd), s2 = random_section(rnd);
    const FeModel fe = n % 2 == 0 ? l_frame(rnd, 2 + n / 2, s1, s2) : triangle_frame(rnd, 2 + n / 2, s1);
    CAPTURE(n, fe.num_nodes());
    for (MassMatrixType type : {MassMatrixType::consistent, MassMatrixType::lumped}) {
      CAPTURE(type == MassMatrixType::consistent ? "consistent" : "lumped");
      const FeMatrices mats = assemble(fe, type);
      const FeMatrices expected = assemble_by_hand(fe, type);
      CHECK_CLOSE_NAMED("your K_FE of the renumbered frame",
                        mats.K, expected.K, scaled(expected.K, 1e-10), assembly_hint(mats.K, fe, type, true));
      CHECK_CLOSE_NAMED("your M_FE of the renumbered frame",
                        mats.M, expected.M, scaled(expected.M, 1e-10), assembly_hint(mats.M, fe, type, false));
    }
  }
}
