// Module 6, tasks T3 and T4 on other models (hidden tests).

#include <string>
#include <vector>

#include "fmbd/fe_assembly.hpp"
#include "fmbd/reduction.hpp"
#include "grading.hpp"
#include "linear_algebra.hpp"
#include "reduction_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m06;

GRADED_TEST("craig_bampton clamped L-frame with two interface nodes in any order condenses statics exactly",
            "[M06][T3][points=2]") {
  Random rnd(6351);
  const FeModel fe = l_frame();
  const FeMatrices fm = assemble(fe, MassMatrixType::consistent);
  const MatX K = without_leading(fm.K, 3), M = without_leading(fm.M, 3);  // node 0 clamped
  const int n = static_cast<int>(K.rows()), last = fe.num_nodes() - 1, corner = 4;
  // Reduced numbering: node j >= 1 has DOFs 3 (j - 1) .. 3 (j - 1) + 2. The far end first, shuffled.
  const std::vector<int> interface = {3 * (last - 1) + 2, 3 * (last - 1), 3 * (last - 1) + 1, 3 * (corner - 1) + 1,
                                      3 * (corner - 1) + 2, 3 * (corner - 1)};
  for (int trial = 0; trial < 3; ++trial) {
    const int k = 2 * trial;
    CAPTURE(k);
    VecX F = VecX::Zero(n);
    for (int b : interface) F(b) = rnd.uniform(-1000, 1000);
    const VecX u_exact = solve_spd(K, F);

    const ReducedBasis cb = craig_bampton(K, M, interface, k);
    {
      INFO("hint: Phi is n x (n_b + num_modes), num_rigid = 0");
      REQUIRE(cb.Phi.rows() == n);
      REQUIRE(cb.Phi.cols() == 6 + k);
      CHECK(cb.num_rigid == 0);
    }
    const MatX K_r = symmetric_part(cb.Phi.transpose() * K * cb.Phi);
    const VecX u = cb.Phi * solve_symmetric(K_r, cb.Phi.transpose() * F);
    CHECK_CLOSE_NAMED("the static response to the interface loads in your Phi's span",
                      u, u_exact, (Tolerance{1e-8 * u_exact.cwiseAbs().maxCoeff(), 1e-8}),
                      constraint_hint(K, interface, cb.Phi.leftCols(6)));
    CHECK_CLOSE_NAMED("your constraint modes (the first 6 columns of Phi)",
                      MatX(cb.Phi.leftCols(6)), constraint_modes(K, interface), (Tolerance{1e-8, 1e-8}),
                      constraint_hint(K, interface, cb.Phi.leftCols(6)));
    // Contrast: as many clamped modes as columns miss the static solution.
    const MatX modes = mode_shapes(K, M, 6 + k);
    const VecX u_modal = modes * solve_symmetric(symmetric_part(modes.transpose() * K * modes), modes.transpose() * F);
    INFO("hint: test oracle: a modal basis of the same size must miss the static solution");
    CHECK((u_modal - u_exact).norm() > 1e-3 * u_exact.norm());
  }
}

GRADED_TEST("ffrf_basis of a modal basis plain or mixed gives back its frequencies and span", "[M06][T4][points=2]") {
  Random rnd(6451);
  for (int trial = 0; trial < 3; ++trial) {
    const FeModel fe = random_triangle(rnd);
    const MassMatrixType type = trial == 1 ? MassMatrixType::lumped : MassMatrixType::consistent;
    const FeMatrices fm = assemble(fe, type);
    const RigidOracle o = rigid_oracle(fe, type);
    const int k = 5, n = fe.num_dofs();
    const VecX full = frequencies(fm.K, fm.M);
    const VecX elastic = full.segment(3, k);
    // [Phi_r, five free-free modes]: first as it is (the modal truncation basis, independent
    // columns), then every column mixed with every other by a random matrix: the same span, rigid
    // content in every column, and columns that are neither orthogonal nor normalised.
    MatX modal(n, 3 + k);
    modal << rigid_columns(fe, o.centroid), mode_shapes(fm.K, fm.M, 3 + k).rightCols(k);
    MatX mix = MatX::Identity(3 + k, 3 + k);
    if (trial > 0) mix += 0.5 * MatX(rnd.vector((3 + k) * (3 + k), -1, 1).reshaped(3 + k, 3 + k));
    ReducedBasis input;
    input.Phi = modal * mix;
    input.M_bar = input.Phi.transpose() * fm.M * input.Phi;
    input.K_bar = input.Phi.transpose() * fm.K * input.Phi;
    CAPTURE(trial, elastic.transpose());
    REQUIRE(std::abs(determinant(mix)) > 1e-3);

    const ReducedBasis b = ffrf_basis(fe, fm, input);
    {
      INFO("hint: 3 rigid + 5 elastic columns: the rigid content of the input spans only Phi_r");
      CHECK(b.num_rigid == 3);
      REQUIRE(b.Phi.rows() == n);
      REQUIRE(b.Phi.cols() == 3 + k);
      REQUIRE(b.K_bar.rows() == 3 + k);
    }
    VecX diag_M(3 + k);
    diag_M << o.mass, o.mass, o.inertia, VecX::Ones(k);
    CHECK_CLOSE_NAMED("the reduced mass matrix of your returned Phi",
                      MatX(b.Phi.transpose() * fm.M * b.Phi), MatX(diag_M.asDiagonal()),
                      (Tolerance{1e-8 * o.mass, 1e-9}),
                      with_formula("your basis: rigid content not removed or columns not M-normalised",
                                   "Phi^T M Phi = diag(m, m, J, 1, ..., 1)"));
    const double w2_max = elastic(k - 1) * elastic(k - 1);
    VecX diag_K(3 + k);
    diag_K << 0.0, 0.0, 0.0, elastic.cwiseProduct(elastic);
    CHECK_CLOSE_NAMED("the reduced stiffness matrix of your returned Phi",
                      MatX(b.Phi.transpose() * fm.K * b.Phi), MatX(diag_K.asDiagonal()),
                      (Tolerance{1e-9 * w2_max, 1e-8}),
                      with_formula("your basis of an exact invariant subspace does not give back the free-free "
                                   "frequencies: is the stiffness diagonalised?", "Phi^T K Phi = diag(0, 0, 0, omega^2 "
                                   "ascending)"));
    CHECK_NEAR_NAMED("the part of the input basis outside the span of your Phi",
                     outside_span(modal, b.Phi, fm.M), 0.0, (Tolerance{1e-12, 0.0}),
                     "the span of [Phi_r, Phi_f] must equal the span of the input basis");
  }
}

GRADED_TEST("ffrf_basis one-node interface drops the rigid constraint modes", "[M06][T4][points=1]") {
  const FeModel fe = l_frame();
  const FeMatrices fm = assemble(fe, MassMatrixType::consistent);
  const RigidOracle o = rigid_oracle(fe, MassMatrixType::consistent);
  const int k = 4;
  // With one clamped node as the interface, the three constraint modes are rigid motions.
  const ReducedBasis cb = craig_bampton_oracle(fm.K, fm.M, node_dofs({0}), k);
  const VecX w = frequencies(cb.K_bar, cb.M_bar);
  const VecX elastic = w.tail(k);
  CAPTURE(w.transpose());

  const ReducedBasis b = ffrf_basis(fe, fm, cb);
  {
    INFO("hint: the three constraint modes are rigid motions: nothing is left of them after the rigid content is "
         "removed, so 3 + k columns remain");
    CHECK(b.num_rigid == 3);
    REQUIRE(b.Phi.rows() == fe.num_dofs());
    REQUIRE(b.Phi.cols() == 3 + k);
  }
  VecX diag_M(3 + k);
  diag_M << o.mass, o.mass, o.inertia, VecX::Ones(k);
  CHECK_CLOSE_NAMED("the reduced mass matrix of your returned Phi",
                    MatX(b.Phi.transpose() * fm.M * b.Phi), MatX(diag_M.asDiagonal()), (Tolerance{1e-8 * o.mass, 1e-9}),
                    with_formula("your basis is not M-orthonormal after the rigid columns",
                                 "Phi^T M Phi = diag(m, m, J, 1, ..., 1)"));
  CHECK_CLOSE_NAMED("the elastic frequencies sqrt(K_bar_ii) of your basis",
                    diagonal_frequencies(b.K_bar, 3), elastic, (Tolerance{1e-6 * elastic(k - 1), 1e-8}),
                    "sqrt(K_bar_ii) are the nonzero frequencies of the input pair, ascending");

  // A basis whose rows do not match the model is an argument error.
  ReducedBasis wrong = cb;
  wrong.Phi = cb.Phi.topRows(fe.num_dofs() - 3);
  check_throws_mentioning<std::invalid_argument>([&] { ffrf_basis(fe, fm, wrong); }, "",
                                                 "ffrf_basis: a basis without n rows is an error");
}
