// Project tests of the given code for flexible bodies, continued from flexible.test.cpp: the
// example builders, static equilibrium, simulation, beam points and the slider-crank's parameters.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "fmbd/applied_forces.hpp"
#include "fmbd/constraints.hpp"
#include "fmbd/energy.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/fe_assembly.hpp"
#include "fmbd/fe_model.hpp"
#include "fmbd/ffrf.hpp"
#include "fmbd/flexible_body.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/intuitive_flexible.hpp"
#include "fmbd/gamma.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/marker.hpp"
#include "fmbd/mass_matrix.hpp"
#include "fmbd/model.hpp"
#include "fmbd/reduction.hpp"
#include "fmbd/simulation.hpp"
#include "fmbd/statics.hpp"
#include "grading.hpp"

#include "flexible_support.hpp"

using namespace fmbd;
using namespace fmbd::flexible_testing;
using fmbd::testing::Random;
using fmbd::testing::Tolerance;
using fmbd::testing::finite_difference_jacobian;

// ---- the examples --------------------------------------------------------------------------

TEST_CASE("example builders: consistent initial conditions for both formulations", "[flexible]") {
  for (const BodyFactory& make_body : {BodyFactory(make_intuitive_body), BodyFactory(make_ffrf_body)}) {
    FlexiblePendulumParameters pp;
    pp.elements = 6;
    FlexibleSliderCrankParameters sp;
    SpinUpBeamParameters up;
    up.elements = 6;
    for (const FlexibleExample& ex :
         {flexible_pendulum(pp, make_body), flexible_slider_crank(sp, make_body), spin_up_beam(up, make_body)}) {
      const Model& m = ex.model;
      REQUIRE(ex.q0.size() == m.num_coordinates());
      REQUIRE(ex.qd0.size() == m.num_coordinates());
      REQUIRE(ex.data);
      CHECK(m.body(ex.flexible).is_flexible());
      CHECK(&data_of(m, ex.flexible) == ex.data.get());
      const ConstraintEvaluation e = evaluate_constraints(m, ex.q0, 0.0);
      CHECK(e.C.norm() < 1e-12);
      CHECK((e.Cq * ex.qd0 + e.Ct).norm() < 1e-10 * std::max(1.0, ex.qd0.norm()));
      CHECK(ex.qd0.segment(m.offset(ex.flexible) + 3, ex.data->num_modes()).isZero(0.0));
      CHECK(ex.q0.segment(m.offset(ex.flexible) + 3, ex.data->num_modes()).isZero(0.0));
    }
  }
}

TEST_CASE("example builders: an initial elastic state and velocity, with the frames made consistent", "[flexible]") {
  Random rnd(907);
  for (const BodyFactory& make_body : {BodyFactory(make_intuitive_body), BodyFactory(make_ffrf_body)}) {
    FlexiblePendulumParameters pp;
    pp.elements = 6;
    pp.modes = 2;
    FlexibleSliderCrankParameters sp;
    sp.crank_angle = 0.7;
    SpinUpBeamParameters up;
    up.elements = 6;
    const auto with_state = [&rnd](auto p, int n_f) {
      p.initial.q_f = rnd.vector(n_f, -1e-3, 1e-3);
      p.initial.q_f_dot = rnd.vector(n_f, -0.1, 0.1);
      return p;
    };
    const auto pendulum = with_state(pp, 2);
    const auto crank = with_state(sp, 3 * 2 - 3 + sp.modes);
    const auto spin = with_state(up, up.modes);
    const std::vector<std::pair<FlexibleExample, InitialElasticState>> cases{
        {flexible_pendulum(pendulum, make_body), pendulum.initial},
        {flexible_slider_crank(crank, make_body), crank.initial},
        {spin_up_beam(spin, make_body), spin.initial}};
    for (const auto& [ex, initial] : cases) {
      const Model& m = ex.model;
      const int at = m.offset(ex.flexible) + 3, n_f = ex.data->num_modes();
      CHECK_CLOSE(VecX(ex.q0.segment(at, n_f)), initial.q_f, kTight, "q_f as given");
      CHECK_CLOSE(VecX(ex.qd0.segment(at, n_f)), initial.q_f_dot, kTight, "q_f_dot as given");
      const ConstraintEvaluation e = evaluate_constraints(m, ex.q0, 0.0);
      CHECK_CLOSE(e.C, VecX::Zero(e.C.size()), (Tolerance{1e-11, 0}), "C = 0 with the elastic state");
      CHECK_CLOSE(VecX(e.Cq * ex.qd0 + e.Ct), VecX::Zero(e.C.size()), (Tolerance{1e-10, 0}), "C_dot = 0");
    }
    // The pendulum's hinge node stays at the origin while the body bends: its frame moved.
    const FlexibleExample bent = flexible_pendulum(pendulum, make_body);
    CHECK_CLOSE(point_position(bent.model, bent.model.find_point("beam start"), bent.q0), Vec2::Zero(),
                (Tolerance{1e-11, 0}), "the hinge node at the origin");
    CHECK(!bent.q0.head(3).isApprox(flexible_pendulum(pp, make_body).q0.head(3)));
  }
  FlexibleSliderCrankParameters wrong;
  wrong.initial.q_f = VecX::Zero(4);
  CHECK_THROWS_MENTIONING(flexible_slider_crank(wrong), std::invalid_argument,
                          "flexible_slider_crank: initial.q_f has 4 entries; the flexible body has 5 elastic coordinates");
}

TEST_CASE("example builders: free-free modes chosen by kind, bending and axial", "[flexible]") {
  // A free-free beam: bending omega_1 = 4.7300408^2 sqrt(EI / (rho A L^4)), axial omega_1 = pi / L sqrt(E / rho).
  FlexibleSliderCrankParameters p;
  p.elements = 40;
  p.basis = BodyBasis::free_free_modes;
  p.selection.bending = 2;
  p.selection.axial = 1;
  const FlexibleExample ex = flexible_slider_crank(p);
  REQUIRE(ex.data->num_modes() == 3);
  Eigen::GeneralizedSelfAdjointEigenSolver<MatX> eig(ex.data->K_ff, ex.data->M_ff);
  const Section s = square_section(p.E, p.rho, p.rod_side);
  const double L = p.rod_length;
  const double bending = 4.7300408 * 4.7300408 * std::sqrt(s.E * s.I / (s.rho * s.A * std::pow(L, 4)));
  const double axial = kPi / L * std::sqrt(s.E / s.rho);
  const VecX omega = eig.eigenvalues().cwiseSqrt();
  CHECK_NEAR(omega(0), bending, (Tolerance{0, 1e-3}), "the first bending mode");
  CHECK_NEAR(omega(2), axial, (Tolerance{0, 1e-3}), "the first axial mode, above the second bending one");
  CHECK(omega(1) > 2 * bending);
  CHECK(omega(1) < axial);

  FlexibleSliderCrankParameters only_axial = p;
  only_axial.selection.bending = 0;
  CHECK_NEAR(VecX(Eigen::GeneralizedSelfAdjointEigenSolver<MatX>(flexible_slider_crank(only_axial).data->K_ff,
                                                                  flexible_slider_crank(only_axial).data->M_ff)
                      .eigenvalues()
                      .cwiseSqrt())(0),
             axial, (Tolerance{0, 1e-3}), "an axial mode alone");
  FlexibleSliderCrankParameters cb = p;
  cb.basis = BodyBasis::craig_bampton;
  CHECK_THROWS_MENTIONING(flexible_slider_crank(cb), std::invalid_argument, "needs BodyBasis::free_free_modes");
  FlexibleSliderCrankParameters too_many = p;
  too_many.elements = 2;
  too_many.selection.axial = 3;
  CHECK_THROWS_MENTIONING(flexible_slider_crank(too_many), std::invalid_argument, "asked for 2 and 3");
}

TEST_CASE("flexible_slider_crank: velocities, body and point names", "[flexible]") {
  FlexibleSliderCrankParameters p;
  p.crank_length = 0.2;
  p.rod_length = 0.5;
  p.crank_speed = 40.0;
  p.elements = 6;
  for (const BodyFactory& make_body : {BodyFactory(make_intuitive_body), BodyFactory(make_ffrf_body)}) {
    const FlexibleExample ex = flexible_slider_crank(p, make_body);
    const Model& m = ex.model;
    const BodyId crank = m.find_body("crank"), rod = m.find_body("rod"), slider = m.find_body("slider");
    CHECK(rod == ex.flexible);
    CHECK(ex.data->num_modes() == 3 * 2 - 3 + 2);
    const double w = p.crank_speed, l1 = p.crank_length, l2 = p.rod_length;
    // At t = 0 everything lies on the x axis: the crank tip moves up at l1 w, the slider stands,
    // the rod turns at -l1 w / l2 and its centroid (mid-span) moves at half the tip's speed.
    CHECK_CLOSE(Vec3(ex.qd0.segment<3>(m.offset(crank))), Vec3(0.0, 0.5 * l1 * w, w), (Tolerance{1e-10, 1e-10}),
                "crank");
    CHECK_CLOSE(Vec3(ex.qd0.segment<3>(m.offset(rod))), Vec3(0.0, 0.5 * l1 * w, -l1 * w / l2),
                (Tolerance{1e-10, 1e-10}), "rod frame");
    CHECK_CLOSE(Vec3(ex.qd0.segment<3>(m.offset(slider))), Vec3::Zero(), (Tolerance{1e-10, 1e-10}), "slider");
    CHECK(ex.qd0.segment(m.offset(rod) + 3, ex.data->num_modes()).isZero(0.0));
    CHECK_CLOSE(Vec3(ex.q0.segment<3>(m.offset(rod))), Vec3(l1 + l2 / 2, 0.0, 0.0), kTight, "rod frame at rest");
    for (const char* name : {"crank tip", "rod start", "rod end", "slider", "rod mid"}) {
      CAPTURE(name);
      CHECK_NOTHROW(m.find_point(name));
    }
    CHECK(m.point(m.find_point("rod start")).node == 0);
    CHECK(m.point(m.find_point("rod end")).node == p.elements);
    CHECK(m.point(m.find_point("rod mid")).node == p.elements / 2);
    CHECK_CLOSE(point_pose(m, m.find_point("rod mid"), ex.q0).r, Vec2(l1 + l2 / 2, 0.0), kTight, "rod mid");
    CHECK_CLOSE(point_pose(m, m.find_point("crank tip"), ex.q0).r, Vec2(l1, 0.0), kTight, "crank tip");
    CHECK_CLOSE(point_pose(m, m.find_point("rod end"), ex.q0).r, Vec2(l1 + l2, 0.0), kTight, "rod end");
  }
  p.elements = 5;
  const FlexibleExample odd = flexible_slider_crank(p);
  CHECK_THROWS_MENTIONING(odd.model.find_point("rod mid"), ModelError, "unknown point 'rod mid'");
  CHECK_NOTHROW(odd.model.find_point("rod end"));
  CHECK(odd.model.point(odd.model.find_point("rod end")).node == 5);
}

TEST_CASE("spin_up_profile: derivatives and continuity at the end of the spin-up", "[flexible]") {
  const double W = 2.0, T = 15.0;
  const DriveFunction f = spin_up_profile(W, T);
  auto value = [&](double t) { return VecX::Constant(1, f(t).f); };
  auto rate = [&](double t) { return VecX::Constant(1, f(t).fd); };
  for (double t : {0.7, 3.0, 7.5, 11.2, 14.6, 16.0, 30.0}) {
    CAPTURE(t);
    CHECK_NEAR(f(t).fd, first_derivative(value, t)(0), (Tolerance{1e-8, 1e-8}), "f' = df/dt");
    CHECK_NEAR(f(t).fdd, first_derivative(rate, t)(0), (Tolerance{1e-8, 1e-8}), "f'' = df'/dt");
  }
  // Starts from rest, ends at the rate W with zero acceleration, and continues linearly.
  CHECK_NEAR(f(0.0).f, 0.0, kTight, "f(0)");
  CHECK_NEAR(f(0.0).fd, 0.0, kTight, "f'(0)");
  CHECK_NEAR(f(0.0).fdd, 0.0, kTight, "f''(0)");
  const double eps = 1e-9;
  const DriveValue before = f(T - eps), at = f(T), after = f(T + eps);
  CHECK_NEAR(before.f, W * T / 2, (Tolerance{1e-8, 1e-10}), "f(T-) = W T / 2");
  CHECK_NEAR(at.f, W * T / 2, (Tolerance{1e-12, 1e-12}), "f(T) = W T / 2");
  CHECK_NEAR(after.f, W * T / 2, (Tolerance{1e-8, 1e-10}), "f(T+)");
  CHECK_NEAR(before.fd, W, (Tolerance{1e-8, 1e-10}), "f'(T-) = W");
  CHECK_NEAR(after.fd, W, kTight, "f'(T+) = W");
  CHECK_NEAR(before.fdd, 0.0, (Tolerance{1e-8, 0}), "f''(T-) = 0");
  CHECK_NEAR(after.fdd, 0.0, kTight, "f''(T+) = 0");
  CHECK_NEAR(f(T / 2).fdd, 2 * W / T, (Tolerance{1e-12, 1e-12}), "peak acceleration 2 W / T at mid spin-up");
  CHECK_NEAR(f(40.0).f, W * (40.0 - T / 2), (Tolerance{1e-12, 1e-12}), "after T: W (t - T/2)");
  // The spin_up_beam uses it as the hub's angle.
  const FlexibleExample ex = spin_up_beam();
  const Model& m = ex.model;
  const BodyId hub = m.find_body("hub");
  for (double t : {2.0, 20.0}) {
    VecX q = ex.q0;
    q(m.offset(hub) + 2) = f(t).f;
    CHECK(std::abs(constraints(m, q, t)(m.num_constraints() - 1)) < 1e-12);
  }
}

// ---- static equilibrium ------------------------------------------------------------------------

TEST_CASE("static_equilibrium: a rigid pendulum on a rotational spring under gravity", "[flexible]") {
  const double mass = 2.0, L = 1.2, k = 15.0, g = 9.81;
  Model m;
  m.set_gravity(Vec2(0.0, -g));
  const BodyId rod = m.add_body("rod", mass, mass * L * L / 12, Vec3(L / 2, 0.0, 0.0));
  m.add_revolute("pivot", m.add_point(ground, Vec2::Zero(), "O"), m.add_point(rod, Vec2(-L / 2, 0.0), "end"));
  m.add_rsda("spring", ground, rod, k, 0.0, 0.0);
  // The droop theta below the horizontal: k theta = m g (L/2) cos theta, by bisection.
  double lo = 0.0, hi = kPi / 2;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (k * mid - mass * g * L / 2 * std::cos(mid) < 0 ? lo : hi) = mid;
  }
  const double phi = -0.5 * (lo + hi);
  const StaticSolution s = static_equilibrium(m, m.initial_guess());
  CHECK_CLOSE(s.q, Vec3(L / 2 * std::cos(phi), L / 2 * std::sin(phi), phi), (Tolerance{1e-9, 1e-9}),
              "the closed-form equilibrium angle");
  CHECK(s.iterations > 0);
  CHECK(s.iterations <= StaticOptions{}.max_iterations);
  const ConstraintEvaluation e = evaluate_constraints(m, s.q, 0.0);
  CHECK_CLOSE(VecX(applied_forces(m, s.q, VecX::Zero(3), 0.0) - e.Cq.transpose() * s.lambda), VecX::Zero(3),
              (Tolerance{1e-8, 0}), "Q - C_q^T lambda = 0");
  CHECK_NEAR(s.lambda.norm(), mass * g, (Tolerance{1e-8, 1e-8}), "the pivot carries the weight");
}

TEST_CASE("static_equilibrium: a clamped flexible beam under gravity deflects by w L^4 / (8 EI)", "[flexible]") {
  const double L = 1.0, g = 9.81;
  const Section s = kSteel;
  const FeModel fe = straight_beam(L, 8, s);
  const FeMatrices mats = assemble(fe, MassMatrixType::consistent);
  const ReducedBasis cb = craig_bampton(mats.K, mats.M, node_dofs({0}), 5);
  const DataPtr data = std::make_shared<const FlexibleBodyData>(
      flexible_body_data(fe, MassMatrixType::consistent, ffrf_basis(fe, mats, cb)));
  const double w = s.rho * s.A * g, tip = w * std::pow(L, 4) / (8 * s.E * s.I);
  for (const BodyFactory& make_body : {BodyFactory(make_intuitive_body), BodyFactory(make_ffrf_body)}) {
    Model m;
    m.set_gravity(Vec2(0.0, -g));
    const BodyId beam =
        m.add_flexible_body("beam", make_body(data), frame_for_placement(fe, MassMatrixType::consistent, Vec2::Zero(), 0.0));
    m.add_fixed("clamp", m.add_point(ground, Vec2::Zero(), "wall"), m.add_node_point(beam, 0, "root"));
    const PointId P = m.add_node_point(beam, 8, "tip");
    const StaticSolution st = static_equilibrium(m, m.initial_guess());
    const Pose root = point_pose(m, m.find_point("root"), st.q), end = point_pose(m, P, st.q);
    CHECK_CLOSE(root.r, Vec2::Zero(), (Tolerance{1e-12, 0}), "the root stays clamped");
    CHECK_NEAR(root.phi, 0.0, (Tolerance{1e-12, 0}), "and level");
    CHECK_NEAR(end.r.y(), -tip, (Tolerance{0, 1e-3}), "cantilever tip deflection under its weight");
    CHECK_NEAR(end.r.x(), L, (Tolerance{1e-4, 0}), "the tip hardly moves along the beam");
    const ConstraintEvaluation e = evaluate_constraints(m, st.q, 0.0);
    const VecX r = applied_forces(m, st.q, VecX::Zero(m.num_coordinates()), 0.0) - e.Cq.transpose() * st.lambda;
    CHECK(r.norm() < 1e-8);
    CHECK_NEAR(Vec2(st.lambda.head<2>()).norm(), data->mass * g, (Tolerance{1e-8, 1e-8}), "the clamp carries the weight");
  }
}

TEST_CASE("static_equilibrium: a body without supports has no equilibrium", "[flexible]") {
  auto refuses = [](const Model& m) {
    bool thrown = false;
    try {
      static_equilibrium(m, m.initial_guess());
    } catch (const SingularJacobianError&) {
      thrown = true;
    } catch (const ConvergenceError&) {
      thrown = true;
    }
    return thrown;
  };
  Model rigid;
  rigid.set_gravity(Vec2(0.0, -9.81));
  rigid.add_body("free", 1.0, 0.1);
  CHECK(refuses(rigid));
  Model flexible;
  flexible.set_gravity(Vec2(0.0, -9.81));
  flexible.add_flexible_body("free", make_intuitive_body(beam_data(1.0, 4, MassMatrixType::lumped, 2)));
  CHECK(refuses(flexible));
  CHECK_THROWS_AS(static_equilibrium(flexible, VecX::Zero(flexible.num_coordinates() + 1)), std::invalid_argument);
}

// ---- simulation ----------------------------------------------------------------------------

namespace {

// Simulates the pendulum for 0.3 s and checks the trajectory's sizes and its energy drift.
void check_pendulum_energy(const BodyFactory& make_body) {
  FlexiblePendulumParameters p;
  p.elements = 6;
  p.modes = 2;
  p.mass_type = MassMatrixType::lumped;
  p.E = 2e9;  // soft, so that it bends visibly while it falls
  const FlexibleExample ex = flexible_pendulum(p, make_body);
  SimulationOptions o;
  o.integrator = Integrator::dormand_prince;
  o.rtol = 1e-8;
  o.atol = 1e-10;
  o.step = 1e-4;
  o.max_step = 0.01;
  const double t_end = 0.3;
  const Trajectory tr = simulate(ex.model, ex.q0, ex.qd0, 0.0, t_end, o);
  const std::size_t N = tr.t.size();
  REQUIRE(N > 2);
  CHECK(tr.q.size() == N);
  CHECK(tr.qd.size() == N);
  CHECK(tr.energy.size() == N);
  CHECK(tr.step.size() == N);
  CHECK(tr.work_done.size() == N);
  CHECK(tr.position_drift.size() == N);
  CHECK(tr.velocity_drift.size() == N);
  CHECK(tr.t.front() == 0.0);
  CHECK_NEAR(tr.t.back(), t_end, (Tolerance{1e-12, 0}), "the run ends at t_end");
  CHECK(tr.q.back().size() == ex.model.num_coordinates());
  CHECK(tr.qd.back().size() == ex.model.num_coordinates());
  // The beam has fallen: energy of the order of m g L/2 has moved from V to T, and it vibrates.
  const double scale = ex.data->mass * p.gravity * p.length / 2;
  const Model& m = ex.model;
  CHECK(kinetic_energy(m, tr.q.back(), tr.qd.back()) > 0.1 * scale);
  INFO("q_f at the end: " << tr.q.back().tail(p.modes).transpose());
  CHECK(tr.q.back().tail(p.modes).norm() > 1e-4);
  double drift = 0, worst_c = 0;
  for (std::size_t i = 0; i < N; ++i) {
    drift = std::max(drift, std::abs(tr.energy[i] - tr.energy.front()));
    worst_c = std::max(worst_c, tr.position_drift[i]);
  }
  CHECK_NEAR(tr.energy.front(), kinetic_energy(m, ex.q0, ex.qd0) + potential_energy(m, ex.q0), kTight,
             "energy = T + V");
  CHECK_NEAR(tr.energy.back(), kinetic_energy(m, tr.q.back(), tr.qd.back()) + potential_energy(m, tr.q.back()),
             kTight, "energy = T(q, q_dot) + V");
  INFO("energy drift " << drift << " J of a scale " << scale << " J, worst |C| " << worst_c << ", " << N << " points");
  CHECK(drift < 1e-7 * scale);
  CHECK(worst_c < 1e-8);
}

}  // namespace

TEST_CASE("simulate: a free flexible pendulum conserves its energy (intuitive body; FFRF with lumped mass)",
          "[flexible]") {
  SECTION("intuitive") { check_pendulum_energy(make_intuitive_body); }
  SECTION("FFRF") { check_pendulum_energy(make_ffrf_body); }
}

TEST_CASE("beam_point and deflection_at: the element shape functions between the nodes", "[flexible]") {
  for (const int elements : {5, 6}) {
    CAPTURE(elements);
    FlexiblePendulumParameters p;
    p.elements = elements;
    const FlexibleExample ex = flexible_pendulum(p, make_ffrf_body);
    const DeformableBody& beam = *ex.model.body(ex.flexible).deformable;
    const int at = ex.model.offset(ex.flexible), n_f = beam.num_modes();
    VecX q = ex.q0;
    q.segment<3>(at) << 0.2, -0.3, 0.4;  // the frame: anywhere, turned
    // Rigid motion only: the beam is the straight line through its nodes, without deflection.
    const Vec2 x0 = beam.node_position(0), axis = (beam.node_position(elements) - x0).normalized();
    for (double s : {0.0, 0.13, 0.5, 0.77, 1.0}) {
      CHECK((beam_point(ex, q, s) - (Vec2(0.2, -0.3) + rotation(0.4) * (x0 + s * axis))).norm() < 1e-13);
      CHECK(std::abs(deflection_at(ex, q, s)) < 1e-13);
    }
    for (int k = 0; k < n_f; ++k) q(at + 3 + k) = 0.01 * (k % 2 ? -1.0 : 1.0) / (k + 1);
    const VecX zero = VecX::Zero(3 + n_f), q_body = ex.model.body_state(q, ex.flexible);
    const double l = p.length / elements;
    // In the frame: the displacement along and across the beam at s, and the node rotations.
    const Mat2 A = rotation(0.4);
    auto local = [&](double s) {
      const Vec2 d = A.transpose() * (beam_point(ex, q, s) - Vec2(0.2, -0.3)) - (x0 + s * axis);
      return Vec2(d.dot(axis), axis.x() * d.y() - axis.y() * d.x());
    };
    for (int k = 0; k <= elements; ++k) {
      CAPTURE(k);
      const NodeMarker m = beam.node_marker(k, q_body, zero);
      // At a node: the node itself.
      CHECK((beam_point(ex, q, k * l) - m.pose.head<2>()).norm() < 1e-12);
      // The slope across the beam at the node is the node's rotation (one-sided difference
      // into an element that has the node).
      const double delta = 1e-6 * l, s = k * l, side = k < elements ? 1.0 : -1.0;
      const double slope = (local(s + side * delta).y() - local(s).y()) / (side * delta);
      CHECK(slope == Approx(m.pose.z() - 0.4).margin(1e-6));
    }
    for (int e = 0; e < elements; ++e) {
      // Inside an element: linear along, cubic across (zero fourth and second differences).
      Vec2 d[5];
      for (int j = 0; j < 5; ++j) d[j] = local((e + 0.1 + 0.2 * j) * l);
      const double scale = std::max(1e-6, d[0].norm());
      CHECK(std::abs(d[0].x() - 2 * d[1].x() + d[2].x()) < 1e-9 * scale);
      CHECK(std::abs(d[0].y() - 4 * d[1].y() + 6 * d[2].y() - 4 * d[3].y() + d[4].y()) < 1e-9 * scale);
    }
    // Mid-span is at length / 2, a node or not.
    CHECK(midspan_deflection(ex, q) == Approx(deflection_at(ex, q, 0.5 * p.length)).margin(1e-15));
    CHECK(std::abs(midspan_deflection(ex, q)) > 1e-6);
    CHECK_THROWS_MENTIONING(beam_point(ex, q, 1.5), std::invalid_argument, "outside the beam");
    CHECK_THROWS_MENTIONING(beam_point(ex, q, -0.1), std::invalid_argument, "outside the beam");
  }
}

TEST_CASE("flexible_slider_crank: every physical parameter can be set", "[flexible]") {
  FlexibleSliderCrankParameters p;
  p.crank_angle = 0.7;
  p.gravity = 9.81;
  p.crank_inertia = 4e-4;
  p.slider_inertia = 2e-5;
  const FlexibleExample ex = flexible_slider_crank(p, make_ffrf_body);
  const Model& m = ex.model;
  // Assembled at the start angle: closed, the crank at 0.7, the slider where the rigid
  // mechanism puts it, x = r cos A + sqrt(l^2 - r^2 sin^2 A).
  CHECK(constraints(m, ex.q0, 0.0).norm() < 1e-12);
  CHECK((constraint_jacobian(m, ex.q0, 0.0) * ex.qd0 + constraint_time_derivative(m, ex.q0, 0.0)).norm() < 1e-9);
  CHECK(m.body_coordinates(ex.q0, m.find_body("crank")).z() == Approx(0.7));
  const double r = p.crank_length, l = p.rod_length, A = 0.7;
  CHECK(m.body_coordinates(ex.q0, m.find_body("slider")).x() ==
        Approx(r * std::cos(A) + std::sqrt(l * l - r * r * std::sin(A) * std::sin(A))).epsilon(1e-12));
  CHECK(m.gravity().y() == -9.81);
  CHECK(m.body(m.find_body("crank")).inertia == 4e-4);
  CHECK(m.body(m.find_body("slider")).inertia == 2e-5);
  // A rectangular section b x h: the bending frequencies scale with h (omega ~ sqrt(E I / (rho A))
  // = h sqrt(E / (12 rho))), so doubling h doubles them.
  auto lowest_frequency = [](double height) {
    FlexibleSliderCrankParameters q;
    q.basis = BodyBasis::free_free_modes;
    q.rod_width = 0.004;
    q.rod_height = height;
    const FlexibleExample e = flexible_slider_crank(q);
    const Eigen::GeneralizedSelfAdjointEigenSolver<MatX> eig(e.data->K_ff, e.data->M_ff);
    return std::sqrt(eig.eigenvalues().minCoeff());
  };
  CHECK(lowest_frequency(0.01) / lowest_frequency(0.005) == Approx(2.0).epsilon(1e-9));
  p.crank_length = 0.4;
  p.crank_angle = 1.5;
  CHECK_THROWS_MENTIONING(flexible_slider_crank(p), std::invalid_argument, "cannot reach the guide");
}
