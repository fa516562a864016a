// Module 6, tasks T3 and T4: Craig-Bampton, and a Craig-Bampton basis made ready for the FFRF
// (visible tests). The oracles: the full static solution and the full generalised eigenproblem
// (Cholesky and Eigen's solver in the test), the constraint modes as static solutions by their
// definition, Rayleigh-Ritz bounds, and the rigid-body integrals of reduction_checks.hpp. The
// ffrf_basis tests start from a Craig-Bampton basis built in the test, not by craig_bampton.

#include <cmath>
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

namespace {

// A straight cantilever: node 0 clamped by removing its three DOFs (rows and columns 0 .. 2).
struct Cantilever {
  FeModel fe;
  MatX K, M;              // without the clamped DOFs
  std::vector<int> tip;   // the tip node's DOFs in the reduced numbering
};

Cantilever cantilever(double L, int elements, const Section& s, const Vec2& start, double angle) {
  Cantilever c;
  c.fe = straight_beam(L, elements, s, start, angle);
  const FeMatrices fm = assemble(c.fe, MassMatrixType::consistent);
  c.K = without_leading(fm.K, 3);
  c.M = without_leading(fm.M, 3);
  const int first = 3 * elements - 3;
  c.tip = {first, first + 1, first + 2};
  return c;
}

// q = (Phi^T K Phi)^{-1} Phi^T F, u = Phi q: the static solution in the span of Phi.
VecX reduced_static(const MatX& Phi, const MatX& K, const VecX& F) {
  const MatX K_r = symmetric_part(Phi.transpose() * K * Phi);
  return Phi * solve_symmetric(K_r, Phi.transpose() * F);
}

const char* kSizeHint = "Phi is n x (n_b + num_modes): the constraint modes, then the normal modes; num_rigid = 0";

}  // namespace

// ---- T3 -------------------------------------------------------------------------------------

GRADED_TEST("craig_bampton cantilever static tip load is exact in the reduced space", "[M06][T3][points=2]") {
  Random rnd(6301);
  const Cantilever c = cantilever(1.5, 10, steel(0.03), Vec2(rnd.uniform(-1, 1), rnd.uniform(-1, 1)),
                                  rnd.uniform(-1.5, 1.5));
  const int n = static_cast<int>(c.K.rows());
  VecX F = VecX::Zero(n);
  F(c.tip[0]) = rnd.uniform(500, 2000);
  F(c.tip[1]) = rnd.uniform(-2000, -500);
  F(c.tip[2]) = rnd.uniform(100, 400);
  const VecX u_exact = solve_spd(c.K, F);  // the full static solution
  const double u_scale = u_exact.cwiseAbs().maxCoeff();

  for (int k : {0, 2, 5}) {
    CAPTURE(k);
    const ReducedBasis cb = craig_bampton(c.K, c.M, c.tip, k);
    {
      INFO("hint: " << kSizeHint);
      REQUIRE(cb.Phi.rows() == n);
      REQUIRE(cb.Phi.cols() == 3 + k);
      CHECK(cb.num_rigid == 0);
    }
    // Loads on interface DOFs only: the constraint modes hold the exact static response.
    const VecX u = reduced_static(cb.Phi, c.K, F);
    CHECK_CLOSE_NAMED("the static response to the tip loads in your Phi's span",
                      u, u_exact, (Tolerance{1e-8 * u_scale, 1e-8}), constraint_hint(c.K, c.tip, cb.Phi.leftCols(3)));
    CHECK_CLOSE(cb.K_bar, MatX(cb.Phi.transpose() * c.K * cb.Phi), (Tolerance{1e-9 * max_abs(c.K), 1e-9}),
                with_formula("your K_bar is not the reduced stiffness matrix of your returned Phi", "K_bar = Phi^T K Phi"));
    CHECK_CLOSE(cb.M_bar, MatX(cb.Phi.transpose() * c.M * cb.Phi), (Tolerance{1e-9 * max_abs(c.M), 1e-9}),
                with_formula("your M_bar is not the reduced mass matrix of your returned Phi", "M_bar = Phi^T M Phi"));

    // Contrast: the same number of clamped vibration modes does not give the static solution,
    // so the check above is a property of the constraint modes.
    const VecX u_modal = reduced_static(mode_shapes(c.K, c.M, 3 + k), c.K, F);
    const double modal_error = (u_modal - u_exact).norm() / u_exact.norm();
    CAPTURE(modal_error);
    INFO("hint: test oracle: a modal basis of the same size must miss the static solution");
    CHECK(modal_error > 1e-3);
  }
}

GRADED_TEST("craig_bampton constraint and normal mode columns of a free frame", "[M06][T3][points=2]") {
  const FeModel fe = l_frame();
  const FeMatrices fm = assemble(fe, MassMatrixType::consistent);
  const int n = fe.num_dofs(), last = fe.num_nodes() - 1;
  // The far end first, and the DOFs of each node shuffled: columns follow this order.
  const std::vector<int> interface = {3 * last + 1, 3 * last, 3 * last + 2, 2, 0, 1};
  const std::vector<int> interior = complement(n, interface);
  const int n_b = 6, k = 4;
  const MatX K_ii = pick(fm.K, interior, interior), M_ii = pick(fm.M, interior, interior);
  const VecX fixed = eigenvalues(K_ii, M_ii).head(k);  // fixed-interface omega^2
  CAPTURE(fixed.transpose());

  const ReducedBasis cb = craig_bampton(fm.K, fm.M, interface, k);
  {
    INFO("hint: " << kSizeHint);
    CHECK(cb.num_rigid == 0);
    REQUIRE(cb.Phi.rows() == n);
    REQUIRE(cb.Phi.cols() == n_b + k);
  }
  // Constraint modes: unit at their own interface DOF, zero at the others, Psi on the interior.
  const MatX constraint = cb.Phi.leftCols(n_b);
  CHECK_CLOSE_NAMED("your constraint modes at the interface DOFs",
                    MatX(pick(constraint, interface, {0, 1, 2, 3, 4, 5})), MatX(MatX::Identity(n_b, n_b)), kExact,
                    "constraint mode r is 1 at its own interface DOF interface[r] and 0 at the other interface DOFs "
                    "(rows in the original DOF order, columns in the order of the interface)");
  CHECK_CLOSE_NAMED("your constraint modes (the first n_b columns of Phi)",
                    constraint, constraint_modes(fm.K, interface), (Tolerance{1e-8, 1e-8}),
                    constraint_hint(fm.K, interface, constraint));

  // Normal modes: zero on the interface, M_ii-normalised fixed-interface modes.
  const MatX normal = cb.Phi.rightCols(k);
  CHECK_CLOSE_NAMED("your normal modes at the interface DOFs",
                    MatX(pick(normal, interface, {0, 1, 2, 3})), MatX(MatX::Zero(n_b, k)), kExact,
                    "normal-mode columns vanish at the interface DOFs: rows interface[r] are zero after the first "
                    "n_b columns");
  const MatX Mn = normal.transpose() * fm.M * normal, Kn = normal.transpose() * fm.K * normal;
  const MatX En = normal.transpose() * normal;
  CHECK_CLOSE_NAMED("the modal mass matrix of your normal modes",
                    Mn, MatX(MatX::Identity(k, k)), (Tolerance{1e-9, 1e-9}),
                    diagnose(flat(Mn), flat(MatX(MatX::Identity(k, k))),
                             {{with_formula("your normal modes normalised with the identity instead of M_ii",
                                            "K_ii phi = omega^2 M_ii phi, phi^T M_ii phi = 1"),
                               flat(MatX(Mn - En + MatX::Identity(k, k)))}},
                             with_formula("your normal modes not M_ii-normalised", "phi^T M_ii phi = 1"),
                             Tolerance{1e-8, 1e-8}));
  CHECK_CLOSE_NAMED("the modal stiffness matrix of your normal modes",
                    Kn, MatX(fixed.asDiagonal()), (Tolerance{1e-9 * fixed(k - 1), 1e-8}),
                    with_formula("your fixed-interface modes: the lowest modes of the interior rows and columns only "
                                 "(normal modes of the full K instead of K_ii are wrong), written to rows interior[r]",
                                 "K_ii phi = omega^2 M_ii phi"));
  CHECK_CLOSE(cb.M_bar, MatX(cb.Phi.transpose() * fm.M * cb.Phi), (Tolerance{1e-9 * max_abs(fm.M), 1e-9}),
              with_formula("your M_bar is not the reduced mass matrix of your returned Phi", "M_bar = Phi^T M Phi"));
  CHECK_CLOSE(cb.K_bar, MatX(cb.Phi.transpose() * fm.K * cb.Phi), (Tolerance{1e-9 * max_abs(fm.K), 1e-9}),
              with_formula("your K_bar is not the reduced stiffness matrix of your returned Phi", "K_bar = Phi^T K Phi"));
}

GRADED_TEST("craig_bampton frequencies are upper bounds that decrease to the full ones", "[M06][T3][points=1]") {
  const Cantilever c = cantilever(1.2, 8, steel(0.03), Vec2(0.3, 0.2), 0.7);
  const int n = static_cast<int>(c.K.rows()), n_i = n - 3;
  const VecX full = frequencies(c.K, c.M);
  VecX previous;
  for (int k : {0, 1, 2, 3, 4, 6, 10, n_i}) {
    CAPTURE(k);
    const ReducedBasis cb = craig_bampton(c.K, c.M, c.tip, k);
    {
      INFO("hint: " << kSizeHint);
      REQUIRE(cb.Phi.rows() == n);
      REQUIRE(cb.Phi.cols() == 3 + k);
    }
    const VecX reduced = frequencies(MatX(cb.Phi.transpose() * c.K * cb.Phi), MatX(cb.Phi.transpose() * c.M * cb.Phi));
    CAPTURE(reduced.transpose(), full.head(3 + k).transpose());
    const std::string hint =
        with_formula("your reduced frequencies break Rayleigh-Ritz: the i-th frequency of (K_bar, M_bar) is never "
                     "below the i-th full one and falls as modes are added; check the blocks of Phi in the "
                     "original DOF order", "Phi = [[I, 0], [Psi, Phi_i]]");
    for (int i = 0; i < 3 + k; ++i) {
      CAPTURE(i);
      INFO("hint: " << hint);
      CHECK(reduced(i) >= full(i) * (1 - 1e-8));
      if (i < previous.size()) CHECK(reduced(i) <= previous(i) * (1 + 1e-8));
    }
    if (k >= 4) {
      // The first frequency converges fast with fixed-interface modes.
      CHECK_NEAR_NAMED("the first natural frequency of your Craig-Bampton model",
                       reduced(0), full(0), (Tolerance{0.0, 1e-4}), hint);
    }
    if (k == n_i) {
      CHECK_CLOSE_NAMED("the natural frequencies of your Craig-Bampton model with all n_i normal modes",
                        reduced, full, (Tolerance{1e-7 * full(n - 1), 1e-8}),
                        "with all n_i fixed-interface modes Phi is square and invertible: the reduced pair has every "
                        "frequency of the full model");
    }
    previous = reduced;
  }
}

GRADED_TEST("craig_bampton rejects an interface that does not hold the body and bad arguments", "[M06][T3][points=1]") {
  const FeModel fe = straight_beam(1.0, 4, steel(0.02), Vec2(0.2, 0.1), 0.3);
  const FeMatrices fm = assemble(fe, MassMatrixType::consistent);
  const int n = fe.num_dofs();
  // One whole node holds a free beam: its constraint modes are the rigid motions.
  const std::vector<int> node2 = node_dofs({2});
  const ReducedBasis ok = craig_bampton(fm.K, fm.M, node2, 2);
  {
    INFO("hint: " << kSizeHint);
    REQUIRE(ok.Phi.rows() == n);
    REQUIRE(ok.Phi.cols() == 5);
  }
  CHECK_CLOSE_NAMED("your constraint modes for node 2 as the interface",
                    MatX(ok.Phi.leftCols(3)), constraint_modes(fm.K, node2), (Tolerance{1e-8, 1e-8}),
                    constraint_hint(fm.K, node2, ok.Phi.leftCols(3)));

  auto rejects = [&](const std::vector<int>& interface, int modes, const std::string& what) {
    check_throws_mentioning<std::invalid_argument>([&] { craig_bampton(fm.K, fm.M, interface, modes); }, "",
                                                   "craig_bampton must throw std::invalid_argument for " + what);
  };
  rejects({0}, 1, "a singular K_ii: fixing only u_x of node 0 leaves the free beam rigid motions");
  rejects({0, 1}, 1, "a singular K_ii: a hinge at node 0 leaves the rotation about it free");
  rejects({}, 1, "an empty interface");
  rejects({0, 1, 2, 1}, 1, "a repeated interface DOF");
  rejects({0, 1, -1}, 1, "an interface DOF below 0");
  rejects({0, 1, n}, 1, "an interface DOF beyond n - 1");
  rejects(node2, -1, "num_modes = -1");
  rejects(node2, n - 2, "num_modes above the n_i = n - 3 interior DOFs");
}

// ---- T4 -------------------------------------------------------------------------------------

namespace {

struct FreeBeamCase {
  FeModel fe;
  FeMatrices fm;
  RigidOracle rigid;
  std::vector<int> interface;
  ReducedBasis cb;   // built in the test
  VecX cb_elastic;   // nonzero frequencies of the Craig-Bampton pair
};

FreeBeamCase free_beam_case(unsigned seed, int k) {
  Random rnd(seed);
  FreeBeamCase f;
  const int elements = 12;
  f.fe = straight_beam(1.6, elements, steel(0.025), Vec2(rnd.uniform(0.5, 1.5), rnd.uniform(-1.5, -0.5)),
                       rnd.uniform(0.2, 1.3));
  f.fm = assemble(f.fe, MassMatrixType::consistent);
  f.rigid = rigid_oracle(f.fe, MassMatrixType::consistent);
  f.interface = node_dofs({0, elements});
  f.cb = craig_bampton_oracle(f.fm.K, f.fm.M, f.interface, k);
  const VecX w = frequencies(f.cb.K_bar, f.cb.M_bar);
  f.cb_elastic = w.tail(w.size() - 3);
  return f;
}

}  // namespace

GRADED_TEST("ffrf_basis of a Craig-Bampton basis is diagonal with the rigid modes first", "[M06][T4][points=2]") {
  const int k = 4;
  const FreeBeamCase f = free_beam_case(6401, k);
  const int n = f.fe.num_dofs();
  const RigidOracle& o = f.rigid;
  CAPTURE(f.cb_elastic.transpose());

  const ReducedBasis b = ffrf_basis(f.fe, f.fm, f.cb);
  {
    INFO("hint: num_rigid = 3: Phi = [Phi_r, Phi_f] starts with the three rigid-body modes");
    CHECK(b.num_rigid == 3);
  }
  {
    INFO("hint: Phi = [Phi_r, Phi_f] has n rows and at least the three rigid columns; M_bar and K_bar match it");
    REQUIRE(b.Phi.rows() == n);
    REQUIRE(b.Phi.cols() >= 3);
    REQUIRE(b.M_bar.rows() == b.Phi.cols());
    REQUIRE(b.M_bar.cols() == b.Phi.cols());
    REQUIRE(b.K_bar.rows() == b.Phi.cols());
    REQUIRE(b.K_bar.cols() == b.Phi.cols());
  }
  const int m = static_cast<int>(b.Phi.cols()), e = m - 3;
  CAPTURE(m);
  const MatX Phi_r = b.Phi.leftCols(3), Phi_f = b.Phi.rightCols(e);
  CHECK_CLOSE_NAMED("the first three columns of your Phi (Phi_r)",
                    Phi_r, rigid_columns(f.fe, o.centroid), (Tolerance{1e-10, 1e-10}),
                    "Phi = [Phi_r, Phi_f]: the first three columns are rigid_body_modes(fe, M).Phi_r, about the "
                    "centroid");
  // The elastic columns carry no rigid motion.
  CHECK_CLOSE_NAMED("the mass coupling of the rigid motions with your Phi_f",
                    MatX(rigid_columns(f.fe, o.centroid).transpose() * f.fm.M * Phi_f), MatX(MatX::Zero(3, e)),
                    (Tolerance{1e-8 * std::sqrt(o.mass), 0.0}),
                    with_formula("your Phi_f: rigid content not removed, so that Phi_f carries rigid motion",
                                 "T_e = Phi - Phi_r (Phi_r^T M Phi_r)^{-1} Phi_r^T M Phi, Phi_r^T M Phi_f = 0"));
  {
    INFO("hint: dependent columns not dropped (or too many dropped): the constraint modes of a free body contain "
         "its three rigid motions, so n_b + k - 3 elastic columns remain");
    CHECK(e == 6 + k - 3);
  }
  // M_bar = diag(m, m, J, 1, ..., 1), from the returned Phi and as returned.
  VecX diag_M(m);
  diag_M << o.mass, o.mass, o.inertia, VecX::Ones(e);
  const MatX Mb = b.Phi.transpose() * f.fm.M * b.Phi;
  CHECK_CLOSE_NAMED("the reduced mass matrix of your returned Phi",
                    Mb, MatX(diag_M.asDiagonal()), (Tolerance{1e-8 * o.mass, 1e-9}),
                    with_formula("your Phi_f: columns not M-normalised before the stiffness is diagonalised",
                                 "S = T_e V_kept diag(g_kept)^{-1/2}, Phi^T M Phi = diag(m, m, J, 1, ..., 1)"));
  CHECK_CLOSE(b.M_bar, Mb, (Tolerance{1e-8 * o.mass, 1e-9}),
              with_formula("your M_bar is not the reduced mass matrix of your returned Phi", "M_bar = Phi^T M Phi"));
  // K_bar = diag(0, 0, 0, omega^2 ascending), omega the nonzero Craig-Bampton frequencies.
  const MatX Kb = b.Phi.transpose() * f.fm.K * b.Phi;
  const double w2_max = f.cb_elastic(f.cb_elastic.size() - 1) * f.cb_elastic(f.cb_elastic.size() - 1);
  CHECK_CLOSE_NAMED("the reduced stiffness matrix of your returned Phi, against its diagonal",
                    Kb, MatX(Kb.diagonal().asDiagonal()), (Tolerance{1e-9 * w2_max, 0.0}),
                    with_formula("your Phi_f: stiffness not diagonalised", "Phi_f = S Z, S^T K S = Z diag(omega^2) Z^T "
                                 "(ascending)"));
  CHECK_CLOSE(b.K_bar, Kb, (Tolerance{1e-9 * w2_max, 1e-9}),
              with_formula("your K_bar is not the reduced stiffness matrix of your returned Phi", "K_bar = Phi^T K Phi"));
  if (e == f.cb_elastic.size()) {
    VecX diag_K(m);
    diag_K << 0.0, 0.0, 0.0, f.cb_elastic.cwiseProduct(f.cb_elastic);
    CHECK_CLOSE_NAMED("the diagonal of the reduced stiffness matrix of your returned Phi",
                      VecX(Kb.diagonal()), diag_K, (Tolerance{1e-9 * w2_max, 1e-8}),
                      with_formula("your K_bar's diagonal is not the nonzero frequencies squared of the input basis, "
                                   "ascending: check the M-normalisation and that the stiffness is diagonalised",
                                   "K_bar = diag(0, 0, 0, omega^2 ascending)"));
  }
}

GRADED_TEST("ffrf_basis keeps the span and the frequencies of the Craig-Bampton basis", "[M06][T4][points=1]") {
  for (int k : {0, 3}) {
    CAPTURE(k);
    const FreeBeamCase f = free_beam_case(6402 + k, k);
    const ReducedBasis b = ffrf_basis(f.fe, f.fm, f.cb);
    {
      INFO("hint: Phi = [Phi_r, Phi_f] has n rows and n_b + k = " << 6 + k << " columns here");
      REQUIRE(b.Phi.rows() == f.fe.num_dofs());
      REQUIRE(b.Phi.cols() == 6 + k);
      REQUIRE(b.K_bar.rows() == 6 + k);
    }
    // The constraint modes of a free beam hold its rigid motions: span([Phi_r, Phi_f]) = span(CB).
    const double lost = outside_span(f.cb.Phi, b.Phi, f.fm.M), added = outside_span(b.Phi, f.cb.Phi, f.fm.M);
    CAPTURE(lost, added);
    CHECK_NEAR_NAMED("the part of the input basis outside the span of your Phi", lost, 0.0, (Tolerance{1e-12, 0.0}),
                     "the span of [Phi_r, Phi_f] must hold every input column: only the rigid content moves to Phi_r, "
                     "and only dependent directions are dropped");
    CHECK_NEAR_NAMED("the part of your Phi outside the span of the input basis", added, 0.0, (Tolerance{1e-12, 0.0}),
                     with_formula("your Phi_f leaves the span of the input basis: combine the input columns minus their "
                                  "rigid content only", "Phi_f = S Z, S = T_e V diag(g)^{-1/2}"));
    const VecX got = diagonal_frequencies(b.K_bar, 3);
    CAPTURE(got.transpose(), f.cb_elastic.transpose());
    CHECK_CLOSE_NAMED("the elastic frequencies sqrt(K_bar_ii) of your basis", got, f.cb_elastic,
                      (Tolerance{1e-6 * f.cb_elastic(f.cb_elastic.size() - 1), 1e-8}),
                      "your elastic frequencies are not the Craig-Bampton frequencies without the three zeros, "
                      "ascending");
  }
}
