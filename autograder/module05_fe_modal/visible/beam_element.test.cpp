// Module 5, tasks T1 to T3: the frame element's stiffness, mass and transformation matrices
// against rigid motions, the energies of fields the element reproduces exactly (integrated here
// by Gauss quadrature), the cantilever formulas and the projection on the element axes (visible
// tests).

#include <cmath>
#include <string>

#include "fe_checks.hpp"
#include "fmbd/beam_element.hpp"
#include "grading.hpp"
#include "linear_algebra.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m05;

namespace {

// Local rigid motions of an element of length L: axial and transverse translation, and the
// rotation about node a (v = x theta, psi = theta).
Vec6 axial_translation() { return (Vec6() << 1, 0, 0, 1, 0, 0).finished(); }
Vec6 transverse_translation() { return (Vec6() << 0, 1, 0, 0, 1, 0).finished(); }
Vec6 rigid_rotation(double L) { return (Vec6() << 0, 0, 1, 0, L, 1).finished(); }

}  // namespace

// ---- T1 ---------------------------------------------------------------------------------------

GRADED_TEST("beam_stiffness is symmetric with the three rigid motions as its null space", "[M05][T1][points=2]") {
  Random rnd(5101);
  for (int n = 0; n < 8; ++n) {
    const Section s = random_section(rnd);
    const double L = rnd.uniform(0.1, 3.0);
    CAPTURE(n, s.E, s.A, s.I, L);
    const Mat6 k = beam_stiffness(s, L);
    const std::string hint = stiffness_hint(k, s, L);
    const double size = max_abs(k);
    // Reported as k - k^T, whose worst entry (i, j) names the pair k(i, j), k(j, i) that differ.
    const Mat6 k_minus_k_transposed = k - k.transpose();
    CHECK_CLOSE_NAMED("your k_e minus its transpose",
                      k_minus_k_transposed, Mat6::Zero(), (Tolerance{1e-12 * size, 0}), hint);
    // k r = 0 for every rigid motion r: a rigid motion stores no strain energy.
    for (const Vec6& r : {axial_translation(), transverse_translation(), rigid_rotation(L)}) {
      CAPTURE(r.transpose());
      CHECK_CLOSE_NAMED("your k_e times a rigid motion",
                        Vec6(k * r), Vec6::Zero(), (Tolerance{1e-11 * size * r.norm(), 0}), hint);
    }
    // Rank 3 and positive semi-definite: exactly three positive eigenvalues, three zeros.
    const Vec6 lambda = symmetric_eigenvalues(0.5 * (k + k.transpose()));
    CAPTURE(lambda.transpose());
    int positive = 0;
    for (int i = 0; i < 6; ++i) positive += lambda(i) > 1e-10 * size;
    INFO("hint: " << hint);
    CHECK(lambda.minCoeff() >= -1e-10 * size);
    CHECK(positive == 3);
  }
}

GRADED_TEST("beam_stiffness strain energy of exact linear and cubic fields matches the integral",
            "[M05][T1][points=2]") {
  // 1/2 u_e^T k_e u_e = 1/2 integral (EA u'^2 + EI v''^2) dx for u linear and v cubic, which the
  // element reproduces exactly; the integral is taken here by Gauss quadrature of the field itself.
  Random rnd(5102);
  for (int n = 0; n < 8; ++n) {
    const Section s = random_section(rnd);
    const double L = rnd.uniform(0.1, 3.0);
    CAPTURE(n, s.E, s.A, s.I, L);
    const Mat6 k = beam_stiffness(s, L);
    const std::string hint = stiffness_hint(k, s, L);
    const Field fields[4] = {random_field(rnd, L, 1e-3, true, false), random_field(rnd, L, 1e-3, false, true),
                             random_field(rnd, L), random_field(rnd, L)};
    for (int i = 0; i < 4; ++i)
      for (int j = i; j < 4; ++j) {
        CAPTURE(i, j);
        const Vec6 qi = fields[i].nodal(L), qj = fields[j].nodal(L);
        const double product = qi.dot(k * qj), expected = strain_product(s, L, fields[i], fields[j]);
        CHECK_NEAR_NAMED("the strain-energy product of two exact fields with your k_e",
                         product, expected, (Tolerance{1e-10 * max_abs(k) * qi.norm() * qj.norm(), 1e-9}), hint);
      }
  }
}

GRADED_TEST("beam_stiffness one-element cantilever deflects P L^3 over 3EI under a tip load", "[M05][T1][points=1]") {
  // Node a clamped: k_bb (u_b, v_b, psi_b) = (N, P, M_t) gives the exact end displacement of a
  // cantilever: u = N L / EA, v = P L^3 / 3EI + M_t L^2 / 2EI, psi = P L^2 / 2EI + M_t L / EI.
  Random rnd(5103);
  for (int n = 0; n < 8; ++n) {
    const Section s = random_section(rnd);
    const double L = rnd.uniform(0.2, 3.0);
    const double N = rnd.uniform(-1e4, 1e4), P = rnd.uniform(-1e3, 1e3), Mt = rnd.uniform(-1e3, 1e3);
    CAPTURE(n, s.E, s.A, s.I, L, N, P, Mt);
    const Mat6 k = beam_stiffness(s, L);
    const Eigen::Matrix3d k_bb = k.bottomRightCorner<3, 3>();
    const Eigen::Vector3d u = solve_general(k_bb, Eigen::Vector3d(N, P, Mt));
    const double EA = s.E * s.A, EI = s.E * s.I;
    const Eigen::Vector3d expected(N * L / EA, P * L * L * L / (3 * EI) + Mt * L * L / (2 * EI),
                                   P * L * L / (2 * EI) + Mt * L / EI);
    CHECK_CLOSE_NAMED("the end displacement of a one-element cantilever with your k_e",
                      u, expected, (Tolerance{1e-9 * expected.cwiseAbs().maxCoeff(), 1e-8}), stiffness_hint(k, s, L));
  }
}

// ---- T2 ---------------------------------------------------------------------------------------

GRADED_TEST("beam_mass consistent kinetic energy of exact velocity fields matches the integral",
            "[M05][T2][points=2]") {
  // 1/2 u_dot_e^T m_e u_dot_e = 1/2 integral rho A (u_dot^2 + v_dot^2) dx for velocity fields the
  // shape functions reproduce exactly (linear u_dot, cubic v_dot), integrated here by quadrature.
  Random rnd(5201);
  for (int n = 0; n < 8; ++n) {
    const Section s = random_section(rnd);
    const double L = rnd.uniform(0.1, 3.0);
    CAPTURE(n, s.rho, s.A, L);
    const Mat6 m = beam_mass(s, L, MassMatrixType::consistent);
    const std::string hint = mass_hint(m, s, L, MassMatrixType::consistent);
    const Field fields[4] = {random_field(rnd, L, 1.0, true, false), random_field(rnd, L, 1.0, false, true),
                             random_field(rnd, L, 1.0), random_field(rnd, L, 1.0)};
    for (int i = 0; i < 4; ++i)
      for (int j = i; j < 4; ++j) {
        CAPTURE(i, j);
        const Vec6 qi = fields[i].nodal(L), qj = fields[j].nodal(L);
        const double product = qi.dot(m * qj), expected = inertia_product(s, L, fields[i], fields[j]);
        CHECK_NEAR_NAMED("the kinetic-energy product of two exact velocity fields with your consistent m_e",
                         product, expected, (Tolerance{1e-11 * max_abs(m) * qi.norm() * qj.norm(), 1e-9}), hint);
      }
  }
}

GRADED_TEST("beam_mass lumped is diagonal with half the mass on each node", "[M05][T2][points=1]") {
  Random rnd(5202);
  for (int n = 0; n < 8; ++n) {
    const Section s = random_section(rnd);
    const double L = rnd.uniform(0.1, 3.0);
    const double total = s.rho * s.A * L;
    CAPTURE(n, s.rho, s.A, L, total);
    const Mat6 m = beam_mass(s, L, MassMatrixType::lumped);
    const std::string hint = mass_hint(m, s, L, MassMatrixType::lumped);
    Mat6 off = m;
    off.diagonal().setZero();
    CHECK_CLOSE_NAMED("the off-diagonal entries of your lumped m_e",
                      off, Mat6::Zero(), (Tolerance{1e-14 * total, 0}), hint);
    // u and v alike (isotropic translations), m/2 per node, and the HRZ rotary term.
    const Vec6 d = m.diagonal();
    const Vec6 expected = hrz_lumped_mass(s, L).diagonal();
    CHECK_CLOSE_NAMED("the diagonal of your lumped m_e",
                      d, expected, (Tolerance{1e-12 * total * (1 + L * L), 1e-10}), hint);
    CHECK_NEAR_NAMED("your lumped m_e's axial mass at node a, against its transverse mass",
                     d(0), d(1), (Tolerance{1e-12 * total, 0}), hint);
  }
}

GRADED_TEST("beam_mass rigid translation carries the total mass in both directions", "[M05][T2][points=1]") {
  Random rnd(5203);
  for (MassMatrixType type : {MassMatrixType::consistent, MassMatrixType::lumped}) {
    for (int n = 0; n < 6; ++n) {
      const Section s = random_section(rnd);
      const double L = rnd.uniform(0.1, 3.0);
      const double total = s.rho * s.A * L;
      CAPTURE(type == MassMatrixType::consistent ? "consistent" : "lumped", n, s.rho, s.A, L, total);
      const Mat6 m = beam_mass(s, L, type);
      const std::string hint = mass_hint(m, s, L, type);
      const Vec6 rx = axial_translation(), ry = transverse_translation();
      CHECK_NEAR_NAMED("the mass that your m_e gives the axial translation",
                       rx.dot(m * rx), total, (Tolerance{0, 1e-12}), hint);
      CHECK_NEAR_NAMED("the mass that your m_e gives the transverse translation",
                       ry.dot(m * ry), total, (Tolerance{0, 1e-12}), hint);
      CHECK_NEAR_NAMED("the coupling of the axial and transverse translations in your m_e",
                       rx.dot(m * ry), 0.0, (Tolerance{1e-13 * total, 0}), hint);
      const Mat6 m_minus_m_transposed = m - m.transpose();
      CHECK_CLOSE_NAMED("your m_e minus its transpose",
                        m_minus_m_transposed, Mat6::Zero(), (Tolerance{1e-14 * max_abs(m), 0}), hint);
      {
        // Every motion has kinetic energy: m_e is positive definite (else M_FE is singular).
        INFO("hint: " << hint);
        INFO("m_e must be positive definite");
        CHECK(is_positive_definite(m));
      }
      if (type == MassMatrixType::consistent) {
        // Rotation about node a: integral rho A x^2 dx = m L^2 / 3.
        const Vec6 r = rigid_rotation(L);
        CHECK_NEAR_NAMED("the moment of inertia that your consistent m_e gives the rotation about node a",
                         r.dot(m * r), total * L * L / 3, (Tolerance{0, 1e-12}), hint);
      }
    }
  }
}

// ---- T3 ---------------------------------------------------------------------------------------

GRADED_TEST("beam_transformation projects global displacements onto the element axes", "[M05][T3][points=1]") {
  // The local axial displacement is the global one projected on the axis e = (cos alpha, sin alpha),
  // the transverse one on n = (-sin alpha, cos alpha); the rotation psi is the same in both frames.
  Random rnd(5301);
  for (int n = 0; n < 12; ++n) {
    const double alpha = rnd.uniform(-7.0, 7.0);
    CAPTURE(n, alpha);
    const Mat6 T = beam_transformation(alpha);
    const Vec2 e(std::cos(alpha), std::sin(alpha));
    const Mat6 expected = element_rotation(e);
    const std::string hint = diagnose(
        flat(T), flat(expected),
        {{with_formula("your T is transposed: T turns global displacements into local ones (its first row is the "
                       "axis)", kTransformationFormula),
          flat(Mat6(expected.transpose()))},
         {"alpha in degrees? beam_transformation takes radians", flat(element_rotation(
                                                                   Vec2(std::cos(alpha * kPi / 180),
                                                                        std::sin(alpha * kPi / 180))))},
         {"your T changes psi: psi is the same in both frames", [&] {
            Mat6 t = expected;
            t(2, 2) = t(5, 5) = 0;
            return flat(t);
          }()}},
        with_formula("your T is not the element's rotation, one block per node", kTransformationFormula),
        Tolerance{1e-12, 1e-12});
    CHECK_CLOSE_NAMED("your T transposed times T", Mat6(T.transpose() * T), Mat6::Identity(), (Tolerance{1e-13, 0}),
                      "your T is not orthogonal: two rotations on the diagonal. " + hint);
    const Vec6 u = rnd.vector(6, -1, 1);
    const Vec6 local = T * u;
    const Vec6 projected =
        (Vec6() << e.dot(u.head<2>()), perp(e).dot(u.head<2>()), u(2), e.dot(u.segment<2>(3)),
         perp(e).dot(u.segment<2>(3)), u(5))
            .finished();
    CHECK_CLOSE_NAMED("your T times a global u_e (the local displacements)",
                      local, projected, (Tolerance{1e-13, 1e-13}), hint);
  }
}
