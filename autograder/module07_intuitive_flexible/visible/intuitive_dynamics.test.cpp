// Module 7, tasks T4 to T6: M_bar in the system's M, gravity and -K_bar q in its Q_a, and the systems built
// on them (visible tests). The oracles: Phi^T M_FE Phi from the FE matrices, the rigid-body kinetic
// energy of a uniform beam (m = rho A L, J = m L^2 / 12), minus the gradient (central
// differences) of the potential V = -g^T (m R + A S_f q_f) + 1/2 q_f^T K_ff q_f written out from
// the FE matrices, the static Ritz solution of a clamped beam in the body's own reduced basis,
// and a rigid uniform rod pendulum built with the rigid bodies of modules 1 to 4.
#include <cmath>
#include <stdexcept>
#include <string>

#include "fmbd/fe_assembly.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/intuitive_flexible.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/simulation.hpp"
#include "fmbd/statics.hpp"
#include "flexible_checks.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m07;

namespace {

// Q against minus the gradient of V, block by block with the hints of the likely slips. With
// `strain` false, V is gravity's potential only (flexible_gravity_force).
void check_body_forces(const FlexibleBodyData& d, const VecX& q, const Vec2& g, const VecX& Q, bool strain,
                       const std::string& label) {
  CAPTURE(label, q.transpose(), g.transpose());
  Potential V = potential_of(d, g);
  if (!strain) V.K_ff.setZero();
  const VecX expected = -finite_difference_jacobian([&](const VecX& x) { return VecX::Constant(1, V(x)); }, q, 1e-6)
                             .row(0)
                             .transpose();
  {
    INFO("hint: Q has 3 + n_f entries: (Q_R, Q_theta, Q_f)");
    REQUIRE(Q.size() == q.size());
  }
  const int n_f = static_cast<int>(q.size()) - 3;
  const double scale = std::max(1.0, expected.cwiseAbs().maxCoeff());
  const Tolerance tol{1e-6 * scale, 1e-6};
  const Mat2 A = rot(q(2));
  const VecX q_f = elastic_part(q);

  const Vec2 Q_R = Q.head<2>(), Q_R_expected = expected.head<2>();
  CHECK_CLOSE_NAMED("Q_R, the frame rows of your forces", Q_R, Q_R_expected, tol,
                    diagnose(Q_R, Q_R_expected, {{"your gravity on the frame is g, not the weight (data.mass)", g}},
                             with_formula("your gravity on the frame is not the body's weight", "Q_R = m g, m = "
                                          "data.mass"),
                             tol));

  const double moment = expected(2);
  const char* moment_formula = "Q_theta = g^T A I~ S_f q_f, minus dV/dtheta";
  CHECK_NEAR_NAMED("Q_theta, the angle row of your forces", Q(2), moment, tol,
                   diagnose(as_matrix(Q(2)), as_matrix(moment),
                            {{with_formula("your gravity moment is 0: the gravity moment needs S_f (S_f = 0 only for an "
                                           "M-orthogonal basis)", moment_formula),
                              as_matrix(0.0)},
                             {with_formula("your gravity moment sign is flipped", moment_formula), as_matrix(-moment)}},
                            with_formula("your gravity moment is not minus the derivative of the potential by theta",
                                         moment_formula),
                            tol));

  const VecX Q_f = Q.tail(n_f), Q_f_expected = expected.tail(n_f);
  const VecX elastic = V.K_ff * q_f, gravity = V.S_f.transpose() * (A.transpose() * g);
  CHECK_CLOSE_NAMED(
      "the elastic rows Q_f of your forces", Q_f, Q_f_expected, tol,
      diagnose(
          Q_f, Q_f_expected,
          {{"your elastic force sign is flipped: the elastic force pulls q_f back to zero", VecX(gravity + elastic)},
           {with_formula("your Q_f: gravity on the elastic coordinates needs S_f", "Q_f = S_f^T A^T g"),
            VecX(-elastic)},
           {"your Q_f turns gravity into the frame by A: gravity in the frame is A^T g",
            VecX(V.S_f.transpose() * (A * g) - elastic)},
           {"your Q_f: the elastic force -K_bar q is missing", VecX(gravity)},
           {"your Q_f: elastic force sign is flipped, and gravity needs S_f", VecX(elastic)}},
          with_formula("your Q_f is not minus the derivative of the potential by q_f",
                       strain ? "Q_f = S_f^T A^T g - K_ff q_f" : "Q_f = S_f^T A^T g"),
          tol));
}

// The body's block that add_intuitive_forces adds to a system's Q_a, the body at coordinates
// `at` of `extra` more; the other rows must stay as they were.
VecX added_forces(const FlexibleBodyData& d, const VecX& q_j, const Vec2& g, Random& rnd) {
  const int n = static_cast<int>(q_j.size()), at = 2, size = n + 5;
  VecX q = rnd.vector(size, -1.0, 1.0), qd = rnd.vector(size, -1.0, 1.0);
  q.segment(at, n) = q_j;
  const VecX before = rnd.vector(size, -1.0, 1.0);
  VecX Q_a = before;
  add_intuitive_forces(d, q, qd, g, at, Q_a);
  VecX others = Q_a - before;
  others.segment(at, n).setZero();
  CHECK_CLOSE_NAMED("what your add_intuitive_forces adds outside the body's rows", others, VecX(VecX::Zero(size)),
                    (Tolerance{0.0, 0.0}),
                    "add_intuitive_forces adds to the body's rows at .. at + 3 + n_f only, with +=");
  return (Q_a - before).segment(at, n);
}

// A state of a body with data d: frame anywhere, elastic coordinates of order `deflection` of its
// length scale.
VecX body_state(const FlexibleBodyData& d, Random& rnd, double deflection) {
  VecX q(3 + d.num_modes());
  q.head<2>() = rnd.vec2(-2.0, 2.0);
  q(2) = rnd.uniform(-3.0, 3.0);
  q.tail(d.num_modes()) = rnd.vector(d.num_modes(), -1.0, 1.0) * deflection * std::sqrt(d.mass);
  return q;
}

}  // namespace

GRADED_TEST("add_intuitive_mass of free-free modes: the body's block of M is M_bar = diag(m, m, J, I)",
            "[M07][T4][points=2]") {
  Random rnd(7401);
  for (MassMatrixType type : {MassMatrixType::consistent, MassMatrixType::lumped}) {
    const double L = 1.3, side = 0.02;
    const int elements = 8;
    const FeModel fe = straight_beam(L, elements, steel(side), Vec2(0.4, 0.1), 0.3);
    const FlexibleBodyData d = flexible_body_data(fe, type, 4);
    const bool consistent = type == MassMatrixType::consistent;
    CAPTURE(consistent ? "consistent" : "lumped");
    const int n = 3 + d.num_modes(), n_f = d.num_modes();
    // The body at coordinates 4 .. 4 + n of a system of n + 6, whose M holds other entries already.
    const int at = 4, size = n + 6;
    VecX q = rnd.vector(size, -1.0, 1.0);
    q(at + 2) = rnd.uniform(-3.0, 3.0);
    const VecX entries = rnd.vector(size * size, -1.0, 1.0);
    const MatX before = Eigen::Map<const MatX>(entries.data(), size, size);
    MatX system = before;
    add_intuitive_mass(d, q, at, system);
    MatX others = system - before;
    others.block(at, at, n, n).setZero();
    CHECK_CLOSE_NAMED("what your add_intuitive_mass adds outside the body's block", others,
                      MatX(MatX::Zero(size, size)), (Tolerance{0.0, 0.0}),
                      "M_bar in M: add the body's block at rows and columns at .. at + 3 + n_f only, with +=");
    const MatX added = (system - before).block(at, at, n, n);
    CHECK_CLOSE_NAMED(
        "what your add_intuitive_mass adds, against its transpose", added, MatX(added.transpose()),
        (Tolerance{1e-12, 1e-12}),
        "M_bar in M: add it with += (the body's block must change by the symmetric M_bar, not be overwritten)");
    // The oracles: a uniform beam of mass m = rho A L and inertia J (below), its free-free modes
    // mass-normalised, and omega_i^2 = (beta_i^2 / L^2)^2 E I / (rho A) of the Euler-Bernoulli
    // free-free beam, beta_i L = 4.7300, 7.8532 (Blevins, Formulas for natural frequency and mode
    // shape, table 8-1).
    const double m = kSteelRho * side * side * L;
    const Tolerance mass_tol{1e-10 * m, 1e-10};
    const MatX M = added;
    const MatX M_rigid = M.topLeftCorner(3, 3);
    MatX rigid_expected = MatX::Zero(3, 3);
    rigid_expected(0, 0) = rigid_expected(1, 1) = m;
    // J: the consistent matrix holds the linear field of a rotation exactly, J = m L^2 / 12. The
    // HRZ lumped one puts m/n at the inner nodes and m/(2n) at the ends (the trapezoidal rule of
    // the integral of x^2: a factor 1 + 2/n^2) and m_e l^2/78 of rotary inertia at each end of
    // each element (n elements: 12/(39 n^2) of m L^2 / 12).
    const double n_el = elements;
    rigid_expected(2, 2) = m * L * L / 12 * (consistent ? 1.0 : 1.0 + 2 / (n_el * n_el) + 12 / (39 * n_el * n_el));
    CHECK_CLOSE_NAMED("the frame block of your M_bar", M_rigid, rigid_expected, mass_tol,
                      diagnose(flat(M_rigid), flat(rigid_expected),
                               {{"M_bar needs M_FE: Phi^T M_FE Phi, not Phi^T Phi",
                                 flat(MatX((d.basis.Phi.transpose() * d.basis.Phi).topLeftCorner(3, 3)))}},
                               "M_bar's frame block is the rigid mass matrix diag(m, m, J): Phi^T M_FE Phi", mass_tol));
    const MatX coupling = M.topRightCorner(3, n_f), elastic = M.bottomRightCorner(n_f, n_f);
    CHECK_CLOSE_NAMED("the coupling block of your M_bar", coupling, MatX(MatX::Zero(3, n_f)),
                      (Tolerance{1e-10 * m, 0.0}),
                      "M_bar of free-free modes has no coupling block: they are M-orthogonal to the rigid motions");
    CHECK_CLOSE_NAMED("the elastic block of your M_bar", elastic, MatX(MatX::Identity(n_f, n_f)),
                      (Tolerance{1e-9, 1e-9}),
                      with_formula("your M_bar's elastic block is not the identity of mass-normalised modes",
                                   "M_bar = Phi^T M_FE Phi"));

    if (consistent) {
      // A rigid motion (q_f_dot = 0) of the uniform beam: T = 1/2 (m |R_dot|^2 + J theta_dot^2).
      VecX qd = VecX::Zero(n);
      qd.head<3>() = rnd.vec3(-2.0, 2.0);
      const double T = 0.5 * qd.dot(M * qd);
      const double T_expected = 0.5 * (m * qd.head<2>().squaredNorm() + m * L * L / 12 * qd(2) * qd(2));
      CHECK_NEAR_NAMED("the kinetic energy of a rigid motion with your M_bar", T, T_expected, (Tolerance{0.0, 1e-9}),
                       with_formula("your M_bar gives a rigid motion the wrong kinetic energy",
                                    "M_bar = Phi^T M_FE Phi; T = 1/2 (m |R_dot|^2 + J theta_dot^2)"));
    }
  }
}

GRADED_TEST("flexible_gravity_force is minus the gradient of the potential of gravity on the body's mass",
            "[M07][T5][points=3]") {
  Random rnd(7402);
  // M-orthogonal free-free modes (S_f = 0): gravity acts on R only.
  const FeModel beam = straight_beam(1.0, 8, steel(0.015), Vec2(-0.2, 0.3), -0.5);
  const FlexibleBodyData modal = flexible_body_data(beam, MassMatrixType::lumped, 3);
  for (int trial = 0; trial < 2; ++trial) {
    const Vec2 g(rnd.uniform(-3.0, 3.0), rnd.uniform(-12.0, -8.0));
    const VecX q = body_state(modal, rnd, 0.01);
    check_body_forces(modal, q, g, flexible_gravity_force(modal, q, g), false,
                      "free-free modes, trial " + std::to_string(trial));
  }
  // Cantilever shapes, not M-orthogonal to the rigid modes (module 8 uses them): S_f != 0 loads
  // q_f and theta.
  const FeModel fe = straight_beam(1.0, 8, steel(0.015));
  const FeMatrices fm = assemble(fe, MassMatrixType::consistent);
  const FlexibleBodyData raw = flexible_body_data(fe, MassMatrixType::consistent, cantilever_basis(fe, fm, 2));
  {
    const Potential V = potential_of(raw, Vec2(0, -1));
    CAPTURE(V.S_f);
    INFO("hint: test oracle: the cantilever shapes have a first moment S_f != 0");
    REQUIRE(max_abs(V.S_f) > 1e-3 * std::sqrt(raw.mass));
  }
  for (int trial = 0; trial < 2; ++trial) {
    const Vec2 g(rnd.uniform(-3.0, 3.0), rnd.uniform(-12.0, -8.0));
    const VecX q = body_state(raw, rnd, 0.01);
    check_body_forces(raw, q, g, flexible_gravity_force(raw, q, g), false,
                      "cantilever basis, trial " + std::to_string(trial));
  }
}

GRADED_TEST("add_intuitive_forces adds gravity and -K_bar q, minus the gradient of V, at the body's rows of Q_a",
            "[M07][T6][points=2]") {
  Random rnd(7403);
  for (MassMatrixType type : {MassMatrixType::lumped, MassMatrixType::consistent}) {
    const FeModel beam = straight_beam(1.1, 8, steel(0.015), Vec2(0.3, -0.2), 0.4);
    const FlexibleBodyData d = flexible_body_data(beam, type, 3);
    for (int trial = 0; trial < 2; ++trial) {
      const Vec2 g(rnd.uniform(-3.0, 3.0), rnd.uniform(-12.0, -8.0));
      const VecX q_j = body_state(d, rnd, 0.01);
      check_body_forces(d, q_j, g, added_forces(d, q_j, g, rnd), true, "free-free modes, trial " + std::to_string(trial));
    }
  }
}

GRADED_TEST("beam clamped to the ground sags under gravity like the FE static solution in its basis",
            "[M07][T6][points=2]") {
  // A stiff steel beam (tip deflection about L / 700) clamped at node 0 to the ground at the
  // origin, along +x, reduced by Craig-Bampton on the clamped node made FFRF-ready.
  const double L = 1.0;
  const int elements = 10;
  const Vec2 g(0.0, -9.81);
  const FeModel fe = straight_beam(L, elements, steel(0.02));
  const FeMatrices fm = assemble(fe, MassMatrixType::consistent);
  const ReducedBasis cb = craig_bampton(fm.K, fm.M, node_dofs({0}), 3);
  const auto data = std::make_shared<const FlexibleBodyData>(
      flexible_body_data(fe, MassMatrixType::consistent, ffrf_basis(fe, fm, cb)));

  // The oracle: the Ritz solution in the same basis, and its tip deflection.
  const VecX u = ritz_static_clamped(*data, 0, g);
  const double tip_sag = u(3 * elements + 1), tip_turn = u(3 * elements + 2);
  const Section s = steel(0.02);
  const double beam_theory = -s.rho * s.A * 9.81 * std::pow(L, 4) / (8 * s.E * s.I);
  CAPTURE(tip_sag, tip_turn, beam_theory);
  CHECK_NEAR(tip_sag, beam_theory, (Tolerance{0.0, 0.02}), "test oracle: the Ritz sag is near w L^4 / (8 E I)");

  Model model;
  model.set_gravity(g);
  const BodyId beam = model.add_flexible_body("beam", make_intuitive_body(data),
                                              frame_for_placement(fe, MassMatrixType::consistent, Vec2::Zero(), 0.0));
  model.add_fixed("clamp", model.add_point(ground, Vec2::Zero(), "wall"), model.add_node_point(beam, 0, "root"));
  model.add_node_point(beam, elements, "tip");

  StaticSolution sol;
  bool converged = true;
  try {
    sol = static_equilibrium(model, model.initial_guess());
  } catch (const KinematicsError& e) {
    converged = false;
    INFO("hint: static equilibrium failed (" << e.what()
         << "): elastic force sign (-K_bar q) and gravity m g in add_intuitive_forces, then the clamp through G_k"
         << kNeedsT4);
    CHECK(converged);
  }
  if (!converged) return;
  const Vec3 tip = pose_oracle(data->nodes[elements], model.body_state(sol.q, beam));
  CAPTURE(sol.q.transpose(), tip.transpose());
  CHECK_NEAR_NAMED(
      "the tip's y of your static solution", tip(1), tip_sag, (Tolerance{0.0, 1e-4}),
      diagnose(as_matrix(tip(1)), as_matrix(tip_sag),
               {{"elastic force sign: -K_bar q, the beam bends up instead of sagging", as_matrix(-tip_sag)},
                {"the beam does not deflect: check -K_bar q and the clamp through the elastic columns of G_k "
                 "(A Phi_t, Phi_psi)",
                 as_matrix(0.0)}},
               "tip sag of the clamped beam: -K_bar q and m g in add_intuitive_forces, the clamp through "
               "G_k (A Phi_t and Phi_psi columns)" +
                   kNeedsT4,
               Tolerance{0.05 * std::abs(tip_sag), 0.05}));
  CHECK_NEAR_NAMED("the tip's angle of your static solution", tip(2), tip_turn, (Tolerance{0.0, 1e-4}),
                   "tip rotation theta + psi of the clamped beam: Phi_psi row of the angle, -K_bar q" + kNeedsT4);
}

GRADED_TEST("very stiff flexible pendulum swings like the rigid rod of module 4", "[M07][T6][points=1]") {
  FlexiblePendulumParameters p;
  p.E = 210e9 * 100;
  p.elements = 6;
  p.modes = 2;
  p.mass_type = MassMatrixType::consistent;
  const FlexibleExample ex = flexible_pendulum(p);
  const double m = p.rho * p.side * p.side * p.length, L = p.length;

  // The rigid uniform rod: hinged at its end at the origin, horizontal at rest.
  Model rigid;
  rigid.set_gravity(Vec2(0.0, -p.gravity));
  const BodyId rod = rigid.add_body("rod", m, m * L * L / 12, Vec3(L / 2, 0.0, 0.0));
  rigid.add_revolute("hinge", rigid.add_point(ground, Vec2::Zero(), "O"), rigid.add_point(rod, Vec2(-L / 2, 0), "end"));

  SimulationOptions o;
  o.integrator = Integrator::rk4;
  o.step = 2e-4;
  o.stabilisation = Stabilisation::projection;
  o.output_interval = 0.01;
  const double t_end = 0.8;
  const Trajectory reference = simulate(rigid, rigid.initial_guess(), VecX::Zero(3), 0.0, t_end, o);
  Trajectory flexible;
  try {
    flexible = simulate(ex.model, ex.q0, ex.qd0, 0.0, t_end, o);
  } catch (const std::runtime_error& e) {
    // Integration and projection failures; NotImplemented (a logic_error) passes through.
    INFO("hint: the stiff pendulum simulation failed (" << e.what()
         << "): elastic force sign (-K_bar q), M_bar in M at the body's coordinates, and node_pose consistent with "
            "node_jacobian (the projection needs both)"
         << kNeedsT4);
    FAIL_CHECK("simulation failed");
    return;
  }
  REQUIRE(flexible.t.size() == reference.t.size());
  const int theta = ex.model.offset(ex.flexible) + 2;
  double worst = 0.0, worst_t = 0.0;
  for (std::size_t i = 0; i < flexible.t.size(); ++i) {
    const double e = std::abs(flexible.q[i](theta) - reference.q[i](2));
    if (e > worst) {
      worst = e;
      worst_t = flexible.t[i];
    }
  }
  CAPTURE(worst, worst_t, flexible.q.back()(theta), reference.q.back()(2));
  CHECK_NEAR_NAMED(
      "the largest difference of your stiff beam's angle from the rigid rod's", worst, 0.0, (Tolerance{1e-4, 0.0}),
      "a very stiff beam must swing like the rigid rod: M_bar (diag(m, m, J, ...)) in M at the body's coordinates, "
      "gravity m g on R, the hinge through G_k and c_k" +
          kNeedsT4);
}
