// Module 7, tasks T4 and T6 with a basis that is NOT M-orthogonal to the rigid modes (hidden tests):
// cantilever shapes of a beam, whose first moment S_f does not vanish. The oracles:
// Phi^T M_FE Phi with its coupling blocks, the kinetic energy 1/2 u_dot^T M_FE u_dot of the
// velocity field u_dot = Phi q_dot, and the static Ritz solution of the clamped beam in that basis.
#include <cmath>
#include <string>

#include "fmbd/fe_assembly.hpp"
#include "fmbd/intuitive_flexible.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/statics.hpp"
#include "flexible_checks.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m07;

GRADED_TEST("intuitive_matrices keeps the coupling blocks of a basis that is not M-orthogonal",
            "[M07][T4][points=2]") {
  Random rnd(7491);
  const double L = 0.9, side = 0.012;
  const FeModel fe = straight_beam(L, 9, steel(side), Vec2(0.2, 0.5), 0.7);
  const FeMatrices fm = assemble(fe, MassMatrixType::consistent);
  const FlexibleBodyData d = flexible_body_data(fe, MassMatrixType::consistent, cantilever_basis(fe, fm, 3));
  const int n = 3 + d.num_modes();
  const MatX expected = d.basis.Phi.transpose() * d.matrices.M * d.basis.Phi;
  {
    INFO("hint: test oracle: the cantilever basis couples the frame and the elastic coordinates");
    REQUIRE(max_abs(MatX(expected.topRightCorner(3, n - 3))) > 1e-3 * max_abs(expected));
  }
  const IntuitiveMatrices r = intuitive_matrices(d.basis.Phi, d.matrices.M, d.matrices.K);
  const MatX M = r.M_bar;
  {
    INFO("hint: M_bar and K_bar are Phi^T M_FE Phi and Phi^T K_FE Phi, (3 + n_f) x (3 + n_f) in (R, theta, q_f)");
    REQUIRE(M.rows() == n);
    REQUIRE(M.cols() == n);
    REQUIRE(r.K_bar.rows() == n);
    REQUIRE(r.K_bar.cols() == n);
  }
  // A rigid motion stores no strain energy, whatever the elastic shapes: K Phi_r = 0.
  const MatX K_frame = r.K_bar.topRows(3);
  CHECK_CLOSE(K_frame, MatX(MatX::Zero(3, n)), (Tolerance{1e-10 * max_abs(r.K_bar), 0.0}),
              "K_bar = Phi^T K_FE Phi: its frame rows vanish in any basis with the rigid modes");
  MatX block_diagonal = MatX::Zero(n, n);
  block_diagonal.topLeftCorner(3, 3) = expected.topLeftCorner(3, 3);
  block_diagonal.bottomRightCorner(n - 3, n - 3) = expected.bottomRightCorner(n - 3, n - 3);
  const Tolerance tol{1e-10 * max_abs(expected), 1e-9};
  CHECK_CLOSE(M, expected, tol,
              diagnose(flat(M), flat(expected),
                       {{"mass matrix is Phi^T M Phi with its coupling blocks: diag(m, m, J, M_ff) holds only for an "
                         "M-orthogonal basis",
                         flat(block_diagonal)}},
                       "M_bar = Phi^T M_FE Phi with its coupling blocks", tol));

  // The kinetic energy of the velocity field u_dot = Phi q_dot of the body at theta = 0.
  const double m = kSteelRho * side * side * L, J = m * L * L / 12;
  for (int trial = 0; trial < 3; ++trial) {
    VecX qd = rnd.vector(n, -1.0, 1.0);
    if (trial == 0) qd.tail(n - 3).setZero();
    const VecX u_dot = d.basis.Phi * qd;
    const double T = 0.5 * qd.dot(M * qd), T_expected = 0.5 * u_dot.dot(fm.M * u_dot);
    CAPTURE(trial, qd.transpose());
    CHECK_NEAR(T, T_expected, (Tolerance{0.0, 1e-9}),
               "mass matrix is Phi^T M Phi: T = 1/2 u_dot^T M_FE u_dot with u_dot = Phi q_dot, coupling included");
    if (trial == 0) {
      CHECK_NEAR(T, 0.5 * (m * qd.head<2>().squaredNorm() + J * qd(2) * qd(2)), (Tolerance{0.0, 1e-9}),
                 "mass matrix is Phi^T M Phi: a rigid motion has T = 1/2 (m |R_dot|^2 + J theta_dot^2)");
    }
  }
}

GRADED_TEST("beam clamped in a basis that is not M-orthogonal sags like its Ritz solution", "[M07][T6][points=2]") {
  const double L = 1.2;
  const int elements = 8;
  const Vec2 g(0.0, -9.81);
  const FeModel fe = straight_beam(L, elements, steel(0.025));
  const FeMatrices fm = assemble(fe, MassMatrixType::consistent);
  const auto data = std::make_shared<const FlexibleBodyData>(
      flexible_body_data(fe, MassMatrixType::consistent, cantilever_basis(fe, fm, 2)));
  const VecX u = ritz_static_clamped(*data, 0, g);
  const double tip_sag = u(3 * elements + 1);
  CAPTURE(tip_sag);

  // The clamp at the wall holds the frame exactly (the cantilever shapes vanish at node 0), so
  // only gravity on the distributed mass, S_f^T A^T g, bends the beam.
  Model model;
  model.set_gravity(g);
  const BodyId beam = model.add_flexible_body("beam", make_intuitive_body(data),
                                              frame_for_placement(fe, MassMatrixType::consistent, Vec2::Zero(), 0.0));
  model.add_fixed("clamp", model.add_point(ground, Vec2::Zero(), "wall"), model.add_node_point(beam, 0, "root"));

  StaticSolution sol;
  bool converged = true;
  try {
    sol = static_equilibrium(model, model.initial_guess());
  } catch (const KinematicsError& e) {
    converged = false;
    INFO("hint: static equilibrium failed (" << e.what()
         << "): elastic force sign (-K_ff q_f) and gravity S_f^T A^T g in intuitive_body_forces" << kNeedsT4);
    CHECK(converged);
  }
  if (!converged) return;
  const Vec3 tip = pose_oracle(data->nodes[elements], model.body_state(sol.q, beam));
  CAPTURE(sol.q.transpose(), tip.transpose());
  CHECK_NEAR(tip(1), tip_sag, (Tolerance{0.0, 1e-6}),
             diagnose(as_matrix(tip(1)), as_matrix(tip_sag),
                      {{"gravity on the elastic coordinates needs S_f: Q_f = S_f^T A^T g - K_ff q_f (the beam does not "
                        "sag)",
                        as_matrix(0.0)},
                       {"elastic force sign: -K_ff q_f, the beam bends up instead of sagging", as_matrix(-tip_sag)}},
                      "tip sag of the clamped beam: Q_f = S_f^T A^T g - K_ff q_f" + kNeedsT4,
                      Tolerance{1e-3 * std::abs(tip_sag), 1e-3}));
  CHECK_NEAR(tip(2), u(3 * elements + 2), (Tolerance{0.0, 1e-6}),
             "tip rotation of the clamped beam: theta + Phi_psi q_f with Q_f = S_f^T A^T g - K_ff q_f" + kNeedsT4);
}
