// Module 6, task T1: rigid-body modes about the centroid (visible tests).
// The oracles: the mass, centroid and inertia of straight beams and frames as integrals over
// their elements (consistent mass) or sums over the HRZ lumped masses, written out by hand.
#include <cmath>
#include <string>

#include "fmbd/fe_assembly.hpp"
#include "fmbd/reduction.hpp"
#include "grading.hpp"
#include "reduction_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m06;

GRADED_TEST("rigid_body_modes straight beam at any angle and offset has J = m L^2 / 12", "[M06][T1][points=2]") {
  Random rnd(6101);
  for (int trial = 0; trial < 4; ++trial) {
    const double L = rnd.uniform(0.5, 3.0), angle = rnd.uniform(-3.0, 3.0), side = rnd.uniform(0.01, 0.05);
    const int elements = 2 + 3 * trial;
    const Vec2 start(rnd.uniform(0.5, 2.5), rnd.uniform(-2.5, -0.5));
    const Section s = steel(side);
    const FeModel fe = straight_beam(L, elements, s, start, angle);
    const FeMatrices fm = assemble(fe, MassMatrixType::consistent);
    CAPTURE(trial, L, angle, elements, start.transpose());

    // By hand: m = rho A L, c the middle of the beam, J = m L^2 / 12 (the consistent mass
    // integrates the linear rigid field exactly).
    RigidOracle o;
    o.mass = s.rho * s.A * L;
    o.centroid = start + 0.5 * L * Vec2(std::cos(angle), std::sin(angle));
    o.inertia = o.mass * L * L / 12.0;

    const RigidBodyModes rb = rigid_body_modes(fe, fm.M);
    check_rigid_body_modes(fe, rb, o);
  }
}

GRADED_TEST("rigid_body_modes lumped mass beam inertia from the HRZ node masses", "[M06][T1][points=1]") {
  Random rnd(6102);
  for (int trial = 0; trial < 3; ++trial) {
    const double L = rnd.uniform(0.8, 2.5), angle = rnd.uniform(0.2, 1.4), side = rnd.uniform(0.01, 0.05);
    const int elements = 1 + 2 * trial;
    const Vec2 start(rnd.uniform(-2.5, -0.5), rnd.uniform(0.5, 2.5));
    const Section s = steel(side);
    const FeModel fe = straight_beam(L, elements, s, start, angle);
    const FeMatrices fm = assemble(fe, MassMatrixType::lumped);
    CAPTURE(trial, L, angle, elements);

    // By hand: m_e / 2 on both nodes of each element, m_e L_e^2 / 78 rotary at both element ends.
    const double m = s.rho * s.A * L, m_e = m / elements, L_e = L / elements;
    const Vec2 c = start + 0.5 * L * Vec2(std::cos(angle), std::sin(angle));
    double J = 2.0 * elements * m_e * L_e * L_e / 78.0;
    for (int k = 0; k <= elements; ++k) {
      const double node_mass = (k == 0 || k == elements) ? m_e / 2 : m_e;
      J += node_mass * (fe.nodes()[k] - c).squaredNorm();
    }
    RigidOracle o;
    o.mass = m;
    o.centroid = c;
    o.inertia = J;
    CAPTURE(J, m * L * L / 12.0);

    const RigidBodyModes rb = rigid_body_modes(fe, fm.M);
    CHECK_NEAR_NAMED("your mass m",
                     rb.mass, m, (Tolerance{0.0, 1e-11}),
                     with_formula("your mass is not the M-norm of a unit translation",
                                  "m = t_x^T M t_x, t_x = (1, 0, 0) at every node"));
    CHECK_CLOSE_NAMED("your centroid c", rb.centroid, c, (Tolerance{1e-10, 1e-10}), centroid_hint(rb.centroid, o));
    CHECK_NEAR_NAMED("your J about the centroid", rb.inertia, J, (Tolerance{0.0, 1e-10}),
                     inertia_hint(rb.inertia, o) +
                         " (take J from the given M: with a lumped M it differs from m L^2 / 12, never use a closed "
                         "form)");
    CHECK_CLOSE(rb.Phi_r, rigid_columns(fe, c), (Tolerance{1e-10, 1e-10}), phi_r_hint(fe, rb.Phi_r, o));
  }
}

GRADED_TEST("rigid_body_modes L-shaped frame of two sections against hand-computed integrals", "[M06][T1][points=2]") {
  const FeModel fe = l_frame();
  // Leg 1: steel 40 mm, (0.4, 0.3) to (2.4, 0.3); leg 2: aluminium 30 mm, (2.4, 0.3) to (2.4, 1.8).
  const double m1 = 7850.0 * 0.04 * 0.04 * 2.0, m2 = 2700.0 * 0.03 * 0.03 * 1.5;
  const Vec2 mid1(1.4, 0.3), mid2(2.4, 1.05);
  const double m = m1 + m2;
  const Vec2 c = (m1 * mid1 + m2 * mid2) / m;
  // Consistent mass: the integral of rho A |x - c|^2 over both legs.
  const double J = m1 * ((mid1 - c).squaredNorm() + 2.0 * 2.0 / 12.0) + m2 * ((mid2 - c).squaredNorm() + 1.5 * 1.5 / 12.0);
  RigidOracle o;
  o.mass = m;
  o.centroid = c;
  o.inertia = J;
  CAPTURE(m, c.transpose(), J);

  const FeMatrices fm = assemble(fe, MassMatrixType::consistent);
  const RigidBodyModes rb = rigid_body_modes(fe, fm.M);
  CHECK_NEAR_NAMED("your mass m",
                   rb.mass, m, (Tolerance{0.0, 1e-11}),
                   with_formula("your mass is not the M-norm of a unit translation",
                                "m = t_x^T M t_x, t_x = (1, 0, 0) at every node"));
  CHECK_CLOSE_NAMED("your centroid c", rb.centroid, c, (Tolerance{1e-10, 1e-10}), centroid_hint(rb.centroid, o));
  CHECK_NEAR_NAMED("your J about the centroid", rb.inertia, J, (Tolerance{0.0, 1e-10}), inertia_hint(rb.inertia, o));
  CHECK_CLOSE(rb.Phi_r, rigid_columns(fe, c), (Tolerance{1e-10, 1e-10}), phi_r_hint(fe, rb.Phi_r, o));

  // Lumped mass: the same mass and centroid, J from the node masses and the rotary terms.
  const FeMatrices lumped = assemble(fe, MassMatrixType::lumped);
  const RigidOracle ol = rigid_oracle(fe, MassMatrixType::lumped);
  const RigidBodyModes rl = rigid_body_modes(fe, lumped.M);
  CHECK_NEAR_NAMED("your mass m",
                   rl.mass, m, (Tolerance{0.0, 1e-11}),
                   with_formula("your mass is not the M-norm of a unit translation",
                                "m = t_x^T M t_x, t_x = (1, 0, 0) at every node"));
  CHECK_CLOSE_NAMED("your centroid c", rl.centroid, c, (Tolerance{1e-10, 1e-10}), centroid_hint(rl.centroid, ol));
  CHECK_NEAR_NAMED("your J about the centroid",
                   rl.inertia, ol.inertia, (Tolerance{0.0, 1e-10}), inertia_hint(rl.inertia, ol));
}

GRADED_TEST("rigid_body_modes Phi_r^T M Phi_r = diag of m m J and K Phi_r = 0 on random frames", "[M06][T1][points=2]") {
  Random rnd(6104);
  for (int trial = 0; trial < 4; ++trial) {
    const FeModel fe = random_triangle(rnd);
    const MassMatrixType type = trial % 2 == 0 ? MassMatrixType::consistent : MassMatrixType::lumped;
    const FeMatrices fm = assemble(fe, type);
    const RigidOracle o = rigid_oracle(fe, type);
    CAPTURE(trial, fe.num_nodes(), o.mass, o.centroid.transpose(), o.inertia);

    const RigidBodyModes rb = rigid_body_modes(fe, fm.M);
    {
      INFO("hint: Phi_r is n x 3 (n = 3 N): translation x, translation y, rotation about the centroid");
      REQUIRE(rb.Phi_r.rows() == fe.num_dofs());
      REQUIRE(rb.Phi_r.cols() == 3);
    }
    // Mass matrix of the rigid motions: diagonal only about the centroid.
    const MatX G = rb.Phi_r.transpose() * fm.M * rb.Phi_r;
    const MatX G_expected = Eigen::Vector3d(o.mass, o.mass, o.inertia).asDiagonal();
    const MatX R_o = rigid_columns(fe, Vec2::Zero());
    const std::string G_hint =
        diagnose(flat(G), flat(G_expected),
                 {{"your rotation column is about the origin instead of the centroid: it couples with the "
                   "translations through M",
                   flat(MatX(R_o.transpose() * fm.M * R_o))}},
                 with_formula("your Phi_r is not M-orthogonal: that holds only for the unit rotation about the "
                              "centroid", "Phi_r^T M Phi_r = diag(m, m, J)"));
    CHECK_CLOSE_NAMED("the mass matrix of the rigid motions in your Phi_r",
                      G, G_expected, (Tolerance{1e-10 * o.mass, 1e-10}), G_hint);
    CHECK_NEAR_NAMED("your mass m", rb.mass, G(0, 0), (Tolerance{0.0, 1e-11}),
                     with_formula("your mass is not the M-norm of a unit translation", "m = t_x^T M t_x"));
    CHECK_NEAR_NAMED("your J about the centroid", rb.inertia, G(2, 2), (Tolerance{0.0, 1e-10}),
                     with_formula("your J about the origin? It is the M-norm of your rotation column about the centroid",
                                  "J = r_c^T M r_c"));

    // Rigid motions strain nothing.
    const double K_scale = max_abs(fm.K) * position_scale(fe);
    CHECK_CLOSE_NAMED("K_FE times your Phi_r",
                      MatX(fm.K * rb.Phi_r), MatX(MatX::Zero(fe.num_dofs(), 3)), (Tolerance{1e-11 * K_scale, 0.0}),
                      with_formula("your Phi_r strains the body: every column must be a rigid motion, the psi entry of "
                                   "the rotation column included", "node k of the rotation column is (-(y_k - c_y), "
                                   "x_k - c_x, 1)"));

    // The rotation column as a rigid field (a - w y, b + w x, w): no velocity at the centroid.
    const Vec2 x0 = fe.nodes()[0];
    const double w = rb.Phi_r(2, 2), a = rb.Phi_r(0, 2) + w * x0.y(), b = rb.Phi_r(1, 2) - w * x0.x();
    const Vec2 v_centroid(a - w * rb.centroid.y(), b + w * rb.centroid.x());
    const Vec2 v_origin(a, b);
    CAPTURE(v_centroid.transpose(), v_origin.transpose());
    CHECK_CLOSE_NAMED("the velocity of your centroid under your rotation column",
                      v_centroid, Vec2(Vec2::Zero()), (Tolerance{1e-10, 0.0}),
                      v_origin.norm() < 1e-10
                          ? with_formula("your rotation column about the origin instead of the centroid",
                                         "node k gets (-(y_k - c_y), x_k - c_x, 1)")
                          : with_formula("your rotation column must leave your returned centroid at rest",
                                         "node k gets (-(y_k - c_y), x_k - c_x, 1)"));
    CHECK_CLOSE(rb.Phi_r, rigid_columns(fe, o.centroid), (Tolerance{1e-10, 1e-10}), phi_r_hint(fe, rb.Phi_r, o));
  }
}
