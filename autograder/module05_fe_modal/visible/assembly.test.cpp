// Module 5, task T3: assembly of M_FE and K_FE for frames with members at any angle and nodes in a
// scrambled order: the rigid motions of the plane as the null space of K, the total mass and the
// rigid-body kinetic energy against closed forms, and the tip deflection of an inclined cantilever
// (solved by the given static_solve) against beam theory (visible tests).

#include <cmath>
#include <string>
#include <vector>

#include "fe_checks.hpp"
#include "fmbd/fe_assembly.hpp"
#include "fmbd/modal.hpp"
#include "grading.hpp"
#include "linear_algebra.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m05;

namespace {

Section stocky_section(Random& rnd) {
  return square_section(rnd.uniform(60e9, 210e9), rnd.uniform(2000, 8000), rnd.uniform(0.04, 0.1));
}

// Frames of the tests: L-shaped and triangular, a few sizes.
std::vector<FeModel> test_frames(Random& rnd) {
  std::vector<FeModel> out;
  out.push_back(l_frame(rnd, 2, stocky_section(rnd), stocky_section(rnd)));
  out.push_back(triangle_frame(rnd, 2, stocky_section(rnd)));
  out.push_back(l_frame(rnd, 3, stocky_section(rnd), stocky_section(rnd)));
  out.push_back(triangle_frame(rnd, 3, stocky_section(rnd)));
  return out;
}

// "reduce or expand is wrong (fix T4 first)" when the student's T4 functions disagree with the
// test's own on this map, else empty (static_solve uses them).
std::string supports_upstream_hint(const MatX& K, const DofMap& map) {
  try {
    const VecX F = VecX::LinSpaced(map.num_dofs, 1.0, 2.0);
    const VecX u_f = VecX::LinSpaced(map.num_free(), -1.0, 1.0);
    VecX expanded = VecX::Zero(map.num_dofs);
    for (int r = 0; r < map.num_free(); ++r) expanded(map.free[r]) = u_f(r);
    if (!compare(reduce(K, map), rows_cols(K, map.free), Tolerance{1e-14, 0}).ok ||
        !compare(reduce(F, map), VecX(F(map.free)), Tolerance{1e-14, 0}).ok ||
        !compare(expand(u_f, map), expanded, Tolerance{1e-14, 0}).ok)
      return "reduce or expand is wrong (fix the T4 tests first; static_solve uses them). ";
  } catch (const std::exception&) {
    return "reduce or expand throws (static_solve uses them: do T4 first). ";
  }
  return "";
}

}  // namespace

GRADED_TEST("assemble free L-shaped and triangular frames have exactly three rigid motions in the null space of K",
            "[M05][T3][points=2]") {
  Random rnd(5311);
  for (const FeModel& fe : test_frames(rnd)) {
    const int n = fe.num_dofs();
    CAPTURE(fe.num_nodes(), fe.num_elements());
    const FeMatrices mats = assemble(fe, MassMatrixType::consistent);
    {
      INFO("hint: K and M are 3N x 3N (N nodes)");
      REQUIRE(mats.K.rows() == n);
      REQUIRE(mats.K.cols() == n);
      REQUIRE(mats.M.rows() == n);
      REQUIRE(mats.M.cols() == n);
    }
    const std::string hint = assembly_rule_hint(fe, MassMatrixType::consistent);
    const double size = max_abs(mats.K);
    CHECK_CLOSE_NAMED("your K_FE, against its own transpose",
                      mats.K, MatX(mats.K.transpose()), (Tolerance{1e-12 * size, 0}), hint);
    CHECK_CLOSE_NAMED("your M_FE, against its own transpose",
                      mats.M, MatX(mats.M.transpose()), (Tolerance{1e-12 * max_abs(mats.M), 0}),
                      assembly_rule_hint(fe, MassMatrixType::consistent));
    // Translations x and y and a rotation about a random centre cost no strain energy.
    const MatX R = rigid_motions(fe, rnd.vec2(-2, 2));
    for (int j = 0; j < 3; ++j) {
      CAPTURE(j);
      CHECK_CLOSE_NAMED("your K_FE times a rigid motion",
                        VecX(mats.K * R.col(j)), VecX::Zero(n), (Tolerance{1e-11 * size * R.col(j).norm(), 0}), hint);
    }
    // ... and nothing else does: exactly three zero eigenvalues, the rest positive.
    const VecX lambda = symmetric_eigenvalues(0.5 * (mats.K + mats.K.transpose()));
    int zeros = 0;
    for (Eigen::Index i = 0; i < lambda.size(); ++i) zeros += std::abs(lambda(i)) <= 1e-10 * size;
    CAPTURE(lambda.head(5).transpose(), zeros);
    INFO("hint: " << hint);
    INFO("a connected free frame has exactly three rigid motions and K is positive semi-definite");
    CHECK(zeros == 3);
    CHECK(lambda.minCoeff() >= -1e-10 * size);
  }
}

GRADED_TEST("assemble total mass and rigid kinetic energy of a frame match closed forms", "[M05][T3][points=1]") {
  Random rnd(5312);
  for (const FeModel& fe : test_frames(rnd)) {
    const Vec2 c = rnd.vec2(-2, 2);
    const MatX R = rigid_motions(fe, c);
    // Closed forms per member from a to b (axis e, length L, mass m = rho A L), d = x_a - c:
    //   mass of the rigid translation: sum m;
    //   consistent rotation about c: sum rho A integral |d + s e|^2 ds = sum m (|d|^2 + L d.e + L^2/3);
    //   lumped rotation about c: sum m/2 (|x_a - c|^2 + |x_b - c|^2) + 2 m L^2 / 78.
    double mass = 0, J_consistent = 0, J_lumped = 0;
    for (int e = 0; e < fe.num_elements(); ++e) {
      const BeamElement& el = fe.elements()[e];
      const double L = fe.length(e), m = el.section.rho * el.section.A * L;
      const Vec2 d = fe.nodes()[el.node_a] - c, db = fe.nodes()[el.node_b] - c, axis = axis_of(fe, e);
      mass += m;
      J_consistent += m * (d.squaredNorm() + L * d.dot(axis) + L * L / 3);
      J_lumped += m / 2 * (d.squaredNorm() + db.squaredNorm()) + 2 * m * L * L / 78;
    }
    CAPTURE(fe.num_nodes(), mass, J_consistent, J_lumped);
    for (MassMatrixType type : {MassMatrixType::consistent, MassMatrixType::lumped}) {
      CAPTURE(type == MassMatrixType::consistent ? "consistent" : "lumped");
      const MatX M = assemble(fe, type).M;
      {
        INFO("hint: M is 3N x 3N (N nodes)");
        REQUIRE(M.rows() == fe.num_dofs());
        REQUIRE(M.cols() == fe.num_dofs());
      }
      const std::string hint = assembly_rule_hint(fe, type);
      const MatX energy = R.transpose() * M * R;  // twice the kinetic energy of unit rigid rates
      CHECK_NEAR_NAMED("the mass that your M_FE gives the x translation",
                       energy(0, 0), mass, (Tolerance{0, 1e-12}), hint);
      CHECK_NEAR_NAMED("the mass that your M_FE gives the y translation",
                       energy(1, 1), mass, (Tolerance{0, 1e-12}), hint);
      CHECK_NEAR_NAMED("the coupling of the x and y translations in your M_FE",
                       energy(0, 1), 0.0, (Tolerance{1e-12 * mass, 0}), hint);
      CHECK_NEAR_NAMED("the moment of inertia that your M_FE gives the rotation about c",
                       energy(2, 2), type == MassMatrixType::consistent ? J_consistent : J_lumped, (Tolerance{0, 1e-11}),
                       hint);
    }
  }
}

GRADED_TEST("assemble inclined cantilever deflects P L^3 over 3EI under a tip load", "[M05][T3][points=1]") {
  // Clamped at node 0, loads at the tip: N along the axis, P across it, a moment M_t. Beam theory
  // (exact at the nodes of cubic elements): at distance x from the clamp
  //   u = N x / EA,  v = P x^2 (3L - x) / 6EI + M_t x^2 / 2EI,  psi = P x (2L - x) / 2EI + M_t x / EI.
  Random rnd(5313);
  for (int n = 0; n < 4; ++n) {
    const double L = rnd.uniform(0.5, 3.0), angle = rnd.uniform(-3.1, 3.1);
    const Section s = square_section(rnd.uniform(60e9, 210e9), rnd.uniform(2000, 8000), L * rnd.uniform(0.01, 0.05));
    const int elements = 3 + n;
    const FeModel fe = straight_beam(L, elements, s, rnd.vec2(-1, 1), angle);
    const Vec2 e(std::cos(angle), std::sin(angle)), nrm = perp(e);
    const double EA = s.E * s.A, EI = s.E * s.I;
    const double P = rnd.uniform(-1e3, 1e3), N = rnd.uniform(-1e5, 1e5), Mt = rnd.uniform(-1e3, 1e3);
    CAPTURE(n, L, angle, elements, P, N, Mt);
    VecX F = VecX::Zero(fe.num_dofs());
    F.segment<2>(3 * elements) = N * e + P * nrm;
    F(3 * elements + 2) = Mt;
    const FeMatrices mats = assemble(fe, MassMatrixType::consistent);
    DofMap map;  // clamped at node 0: every DOF but the first three is free
    map.num_dofs = fe.num_dofs();
    for (int i = 3; i < map.num_dofs; ++i) map.free.push_back(i);
    VecX expected(fe.num_dofs());
    for (int k = 0; k <= elements; ++k) {
      const double x = L * k / elements;
      const double u = N * x / EA, v = P * x * x * (3 * L - x) / (6 * EI) + Mt * x * x / (2 * EI);
      expected.segment<2>(3 * k) = u * e + v * nrm;
      expected(3 * k + 2) = P * x * (2 * L - x) / (2 * EI) + Mt * x / EI;
    }
    std::string hint;
    if (mats.K.rows() == fe.num_dofs() && mats.K.cols() == fe.num_dofs())
      hint = supports_upstream_hint(mats.K, map) + assembly_rule_hint(fe, MassMatrixType::consistent);
    if (hint.empty()) hint = "K u = F with K from assemble, clamped at node 0: check the element matrices and T";
    VecX u;
    try {
      u = static_solve(fe, mats, map, F);
    } catch (const SingularStiffness& error) {
      INFO("hint: " << hint);
      FAIL_CHECK(error.what());
      continue;
    }
    CHECK_CLOSE_NAMED("the cantilever's deflection u with your K_FE",
                      u, expected, (Tolerance{1e-8 * expected.cwiseAbs().maxCoeff(), 1e-7}), hint);
  }
}
