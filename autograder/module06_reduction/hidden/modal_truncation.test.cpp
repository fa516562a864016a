// Module 6, task T2: modal truncation of other frames (hidden tests).
#include <string>

#include "fmbd/fe_assembly.hpp"
#include "fmbd/reduction.hpp"
#include "grading.hpp"
#include "reduction_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m06;

GRADED_TEST("modal_truncation lumped triangular frames diagonal pair with the full frequencies", "[M06][T2][points=2]") {
  Random rnd(6251);
  for (int trial = 0; trial < 3; ++trial) {
    const FeModel fe = random_triangle(rnd);
    const MassMatrixType type = trial == 1 ? MassMatrixType::consistent : MassMatrixType::lumped;
    const FeMatrices fm = assemble(fe, type);
    const RigidOracle o = rigid_oracle(fe, type);
    const int k = 3 + 2 * trial;
    const VecX full = frequencies(fm.K, fm.M);
    const VecX full_elastic = full.segment(3, k);
    CAPTURE(trial, fe.num_nodes(), k);

    const ReducedBasis b = modal_truncation(fe, fm, k);
    {
      INFO("hint: Phi = [Phi_r, Phi_f] is n x (3 + num_elastic) with num_rigid = 3");
      CHECK(b.num_rigid == 3);
      REQUIRE(b.Phi.rows() == fe.num_dofs());
      REQUIRE(b.Phi.cols() == 3 + k);
      REQUIRE(b.M_bar.rows() == 3 + k);
      REQUIRE(b.K_bar.rows() == 3 + k);
    }
    VecX diag_M(3 + k);
    diag_M << o.mass, o.mass, o.inertia, VecX::Ones(k);
    CHECK_CLOSE(b.M_bar, MatX(diag_M.asDiagonal()), (Tolerance{1e-8 * o.mass, 1e-9}),
                with_formula("your M_bar is not the rigid masses and ones on its diagonal: Phi_r about the centroid "
                             "first, then mass-normalised elastic free-free modes (rigid (zero) modes kept in Phi_f "
                             "give off-diagonal terms)", "M_bar = diag(m, m, J, 1, ..., 1)"));
    const double w2_max = full_elastic(k - 1) * full_elastic(k - 1);
    VecX diag_K = VecX::Zero(3 + k);
    diag_K.tail(k) = full_elastic.cwiseProduct(full_elastic);
    const VecX got = diagonal_frequencies(b.K_bar, 3);
    VecX kept_zero = VecX::Zero(k);
    for (int i = 3; i < k; ++i) kept_zero(i) = full_elastic(i - 3);
    CAPTURE(got.transpose(), full_elastic.transpose());
    CHECK_CLOSE(b.K_bar, MatX(diag_K.asDiagonal()), (Tolerance{1e-9 * w2_max, 1e-8}),
                diagnose(got, full_elastic,
                         {{"your Phi_f: rigid (zero) modes kept in Phi_f: skip the first three free-free modes",
                           kept_zero}},
                         with_formula("your K_bar is not the elastic frequencies squared: Phi_f are the elastic "
                                      "free-free modes", "K_bar = diag(0, 0, 0, omega_1^2, ..., omega_k^2)"),
                         Tolerance{1e-6, 1e-6}));
  }
}
