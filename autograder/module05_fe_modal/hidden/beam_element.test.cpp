// Module 5, tasks T1 to T3: every entry of the element matrices against the integrals of the shape
// functions, and rotated element matrices against the rigid motions of the plane (hidden tests).
#include <cmath>
#include <string>

#include "fe_checks.hpp"
#include "fmbd/beam_element.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m05;

GRADED_TEST("beam_stiffness random sections and lengths match the integral of the shape functions",
            "[M05][T1][points=1]") {
  // k_e = integral (EA B_u^T B_u + EI B_v^T B_v) dx with B_v the curvatures of the Hermite functions.
  Random rnd(5111);
  for (int n = 0; n < 20; ++n) {
    const Section s = random_section(rnd);
    const double L = std::exp(rnd.uniform(std::log(0.05), std::log(10.0)));
    CAPTURE(n, s.E, s.A, s.I, L);
    const Mat6 k = beam_stiffness(s, L);
    const Mat6 expected = stiffness_by_quadrature(s, L);
    CHECK_CLOSE_NAMED("your k_e", k, expected, scaled(expected, 1e-10), stiffness_hint(k, s, L));
  }
}

GRADED_TEST("beam_mass consistent and lumped match the integrals of the shape functions", "[M05][T2][points=1]") {
  // consistent: integral rho A (N_u^T N_u + N_v^T N_v) dx; lumped: its diagonal scaled per field so
  // that each field carries the element mass (HRZ).
  Random rnd(5211);
  for (MassMatrixType type : {MassMatrixType::consistent, MassMatrixType::lumped}) {
    for (int n = 0; n < 10; ++n) {
      const Section s = random_section(rnd);
      const double L = std::exp(rnd.uniform(std::log(0.05), std::log(10.0)));
      CAPTURE(type == MassMatrixType::consistent ? "consistent" : "lumped", n, s.rho, s.A, L);
      const Mat6 m = beam_mass(s, L, type);
      const Mat6 expected = mass_by_quadrature(s, L, type);
      CHECK_CLOSE_NAMED("your m_e", m, expected, scaled(expected, 1e-10), mass_hint(m, s, L, type));
    }
  }
}

GRADED_TEST("beam_transformation rotated element matrices keep the rigid motions and the mass", "[M05][T3][points=1]") {
  // Element from node a at the origin to node b at L (cos alpha, sin alpha). In global DOFs the
  // translations x, y and the rotation about node a (node b moves by L (-sin alpha, cos alpha))
  // lie in the null space of T^T k_e T, and T^T m_e T gives every translation the mass rho A L.
  // The local matrices here are the test's own integrals, so only T is graded.
  Random rnd(5321);
  for (int n = 0; n < 12; ++n) {
    const Section s = random_section(rnd);
    const double L = rnd.uniform(0.2, 3.0), alpha = rnd.uniform(-4.0, 4.0);
    CAPTURE(n, L, alpha);
    const Mat6 T = beam_transformation(alpha);
    const Vec2 e(std::cos(alpha), std::sin(alpha));
    const Mat6 right = element_rotation(e);
    const std::string hint = diagnose(
        flat(T), flat(right),
        {{with_formula("your T is transposed: T turns global displacements into local ones", kTransformationFormula),
          flat(Mat6(right.transpose()))}},
        with_formula("your T: the rows of each rotation block are the element axes e and n", kTransformationFormula),
        Tolerance{1e-12, 1e-12});
    const Mat6 k = T.transpose() * stiffness_by_quadrature(s, L) * T;
    const double size = max_abs(k);
    Vec6 tx, ty, rot;
    tx << 1, 0, 0, 1, 0, 0;
    ty << 0, 1, 0, 0, 1, 0;
    rot << 0, 0, 1, -L * e.y(), L * e.x(), 1;
    for (const Vec6& r : {tx, ty, rot}) {
      CAPTURE(r.transpose());
      CHECK_CLOSE_NAMED("the element's global stiffness with your T, times a rigid motion",
                        Vec6(k * r), Vec6::Zero(), (Tolerance{1e-11 * size * r.norm(), 0}), hint);
    }
    for (MassMatrixType type : {MassMatrixType::consistent, MassMatrixType::lumped}) {
      const Mat6 m = T.transpose() * mass_by_quadrature(s, L, type) * T;
      const double total = s.rho * s.A * L;
      const Vec2 d = rnd.vec2(-1, 1).normalized();
      Vec6 r;
      r << d, 0, d, 0;
      CHECK_NEAR_NAMED("the mass that the element's global mass matrix with your T gives a translation",
                       r.dot(m * r), total, (Tolerance{0, 1e-12}), hint);
      // The rigid rotation about node a has the kinetic energy of the element turning about its end.
      const double J = type == MassMatrixType::consistent ? total * L * L / 3 : total * L * L / 2 + 2 * total * L * L / 78;
      CHECK_NEAR_NAMED("the inertia that the element's global mass matrix with your T gives the rotation about node a",
                       rot.dot(m * rot), J, (Tolerance{0, 1e-12}), hint);
    }
  }
}
