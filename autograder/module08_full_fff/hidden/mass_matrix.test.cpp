// Module 8, task T3 (hidden tests): the mass matrix of a basis that is not M-orthogonal to the rigid
// motions, so that M_bar couples R and theta to q_f (S_f != 0).
// The oracles: T^T M_bar T at q_f = 0 with M_bar = Phi^T M_FE Phi built here and T = blockdiag(A^T, 1, I),
// and the FE kinetic energy of the nodal velocities by finite differences of the node poses.

#include <cmath>
#include <string>

#include "ffrf_checks.hpp"
#include "fmbd/ffrf.hpp"
#include "grading.hpp"
#include "linear_algebra.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m08;

GRADED_TEST("ffrf_mass_matrix basis with rigid content couples R theta and q_f like the FE kinetic energy",
            "[M08][T3][points=2]") {
  Random rnd(8311);
  const FeModel fe = l_frame(Vec2(0.7, -0.2));
  const FeMatrices fm = assemble(fe, MassMatrixType::consistent);
  // Elastic columns: smooth fields with a translation and a rotation mixed in.
  const int n = fe.num_dofs(), n_f = 3;
  ReducedBasis basis;
  basis.num_rigid = 3;
  basis.Phi = MatX::Zero(n, 3 + n_f);
  for (int k = 0; k < fe.num_nodes(); ++k) {
    const Vec2 x = fe.nodes()[k];
    basis.Phi.block<3, 3>(3 * k, 0) << 1.0, 0.0, -x.y(), 0.0, 1.0, x.x(), 0.0, 0.0, 1.0;
    basis.Phi.block<3, 3>(3 * k, 3) << 0.3 + x.x() * x.x(), 0.1 * x.y(), -0.2 * x.y(),  //
        x.x() * x.y(), 0.5 + x.y() * x.y() * x.x(), 0.4 * x.x(),                    //
        x.x(), 2.0 * x.y(), 0.2 + x.x() * x.y();
  }
  const FlexibleBodyData data = flexible_body_data(fe, MassMatrixType::consistent, basis);
  REQUIRE(data.num_modes() == n_f);
  {
    INFO("hint: the test basis must couple (this is a check of the test data, not of your code)");
    REQUIRE(data.S_f.cwiseAbs().maxCoeff() > 1e-3 * data.mass);
  }
  const double scale = max_abs(reduced_mass(data));
  for (int trial = 0; trial < 3; ++trial) {
    const VecX q0 = random_q(rnd, n_f, 0.0);
    CAPTURE(q0.transpose());
    const MatX M0 = ffrf_mass_matrix(data, q0);
    const MatX expected0 = rotated_reduced_mass(data, q0(2));
    CHECK_CLOSE_NAMED("your M(q) at q_f = 0", M0, expected0, (Tolerance{1e-10 * scale, 1e-10}),
                      diagnose(flat(M0), flat(expected0),
                               {{"mass matrix is L^T M_FE L, not M_bar: the R rows turn with A (the coupling A S_f)",
                                 flat(reduced_mass(data))}},
                               mass_hint(M0, expected0, data, q0), Tolerance{1e-7, 1e-7}));

    const VecX q = random_q(rnd, n_f, 0.05);
    VecX qd = rnd.vector(3 + n_f, -1.0, 1.0);
    qd(2) = rnd.uniform(1.0, 3.0);
    CAPTURE(q.transpose(), qd.transpose());
    const MatX W = fd_stacked_map(data, q);
    const MatX expected = W.transpose() * data.matrices.M * W;
    const MatX M = ffrf_mass_matrix(data, q);
    const std::string hint = mass_hint(M, expected, data, q);
    const VecX w = W * qd;
    const double T = 0.5 * w.dot(data.matrices.M * w);
    CHECK_NEAR_NAMED("the kinetic energy of your M(q)", 0.5 * qd.dot(M * qd), T, (Tolerance{1e-9 * T, 1e-8}), hint);
    CHECK_CLOSE_NAMED("your M(q)", M, expected, (Tolerance{1e-8 * scale, 1e-8}), hint);
    INFO("hint: M(q) = L^T M_FE L is positive definite");
    CHECK(is_positive_definite(M));
  }
}
