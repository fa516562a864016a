// Project tests (not graded) of the given code of module 4, continued from integration.test.cpp:
// the same mechanism in other units, Model::add_point_at, the Trajectory's named access, and the
// paths of solve_augmented. They link the reference variant of stages 1-4.
#include <unistd.h>

#include <Eigen/LU>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fmbd/constraints.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/forward_dynamics.hpp"
#include "fmbd/mass_matrix.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/integrators.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/projection.hpp"
#include "fmbd/simulation.hpp"
#include "fmbd/singular_instant.hpp"
#include "grading.hpp"
#include "integration_models.hpp"

using namespace fmbd;
using fmbd::testing::Tolerance;
using namespace fmbd::integration_testing;

namespace {

// A four-bar of slender rods (mass 2 kg per m of length, J = m L^2 / 12) swinging under gravity
// from rest at crank angle 0.5, built in units where a kilogram is `kg` and a metre is `m`:
// the same mechanism in any units.
struct Units {
  double kg, m;
};

struct ScaledFourBar {
  Model model;
  VecX q0;
  explicit ScaledFourBar(Units u) {
    const examples::FourBarParameters p;  // lengths in m
    const Vec2 O2(0, 0), O4(p.d, 0), B = p.a * Vec2(std::cos(p.theta0), std::sin(p.theta0));
    Vec2 C;
    REQUIRE(examples::four_bar_joint_C(p, p.theta0, C));
    model.set_gravity(Vec2(0, -kG * u.m));
    q0.resize(9);
    PointId from = model.add_point(ground, O2 * u.m, "O2");
    const Vec2 ends[4] = {O2, B, C, O4};
    const char* names[3] = {"crank", "coupler", "rocker"};
    for (int k = 0; k < 3; ++k) {
      const Vec2 a = ends[k], b = ends[k + 1], mid = 0.5 * (a + b);
      const double L = (b - a).norm(), mass = 2 * L, phi = std::atan2(b.y() - a.y(), b.x() - a.x());
      const BodyId body = model.add_body(names[k], mass * u.kg, mass * L * L / 12 * u.kg * u.m * u.m,
                                         Vec3(mid.x() * u.m, mid.y() * u.m, phi));
      q0.segment<3>(3 * k) << mid * u.m, phi;
      model.add_revolute(std::string("joint ") + names[k], from,
                         model.add_point(body, Vec2(-0.5 * L * u.m, 0), std::string(names[k]) + " start"));
      from = model.add_point(body, Vec2(0.5 * L * u.m, 0), std::string(names[k]) + " end");
    }
    model.add_revolute("joint O4", from, model.add_point(ground, O4 * u.m, "O4"));
  }
};

}  // namespace

TEST_CASE("simulate: the same mechanism in other units gives the same motion", "[integration]") {
  // Tiny (1e-6 kg and 0.01 m units, J ~ 1e-12 kg m^2), in g and mm, and with masses 1e-4: the
  // rank decisions, the consistency check and the projection tolerance are relative to the
  // model's own scales, so each run is the SI run in other units.
  const ScaledFourBar si({1.0, 1.0});
  SimulationOptions o;
  o.step = 1e-3;
  o.stabilisation = Stabilisation::projection;
  o.output_interval = 0.1;
  const Trajectory reference = simulate(si.model, si.q0, VecX::Zero(9), 0.0, 1.0, o);
  REQUIRE(reference.t.size() == 11);
  REQUIRE(std::abs(reference.q.back()(2) - si.q0(2)) > 0.1);  // it does swing
  for (const Units u : {Units{1e-6, 0.01}, Units{1e3, 1e3}, Units{1e-4, 1.0}, Units{1e4, 1e-3}}) {
    CAPTURE(u.kg, u.m);
    const ScaledFourBar scaled(u);
    const Trajectory s = simulate(scaled.model, scaled.q0, VecX::Zero(9), 0.0, 1.0, o);
    REQUIRE(s.t.size() == reference.t.size());
    for (std::size_t i = 0; i < s.t.size(); ++i) {
      CAPTURE(s.t[i]);
      for (int k = 0; k < 9; ++k) {
        const double unit = k % 3 == 2 ? 1.0 : u.m;  // angles have no unit
        CHECK(s.q[i](k) / unit == Approx(reference.q[i](k)).margin(1e-9));
      }
      // Energy in kg m^2/s^2: relative to the SI energy scale.
      CHECK(s.energy[i] / (u.kg * u.m * u.m) == Approx(reference.energy[i]).margin(1e-9));
    }
  }
}

TEST_CASE("Model::add_point_at places a point at a global position of the initial configuration", "[integration]") {
  // A double pendulum entered as published, by its joint positions: O = (0, 0), A = (0.3, -0.4),
  // B = (0.3, -0.9); each link's centroid at mid-link, turned by its own angle.
  Model m;
  const Vec2 O(0, 0), A(0.3, -0.4), B(0.3, -0.9);
  const BodyId upper = m.add_body("upper", 1.0, 0.02, Vec3(0.15, -0.2, std::atan2(-0.4, 0.3)));
  const BodyId lower = m.add_body("lower", 1.0, 0.02, Vec3(0.3, -0.65, 0.3));  // any angle
  m.add_revolute("O", m.add_point_at(ground, O, "O ground"), m.add_point_at(upper, O, "O upper"));
  m.add_revolute("A", m.add_point_at(upper, A, "A upper"), m.add_point_at(lower, A, "A lower"));
  const PointId tip = m.add_point_at(lower, B, "B");
  // Oracle: the joints close at q0 (module 1's constraints), and the points lie where given.
  const VecX q0 = m.initial_guess();
  CHECK(constraints(m, q0, 0.0).norm() < 1e-15);
  CHECK((m.point(tip).s_bar - rotation(-0.3) * (B - Vec2(0.3, -0.65))).norm() < 1e-15);
  CHECK(m.point(m.find_point("O upper")).s_bar.norm() == Approx(0.25));
  CHECK_THROWS_AS(m.add_point_at(BodyId{7}, O, "nowhere"), ModelError);
}

TEST_CASE("Trajectory: named access to a body, the multipliers and the reactions", "[integration]") {
  // The rod from rest at phi = 0 (horizontal): at the start the pivot carries m g / 4 upwards
  // (the classical result for a rod released about one end: R = m g - m a_G, a_G = 3 g / 4).
  const Rod rod;
  SimulationOptions o;
  o.step = 1e-3;
  o.output_interval = 0.01;
  const Trajectory plain = simulate(rod.model, Rod::q(0.0), Rod::qd(0.0, 0.0), 0.0, 0.5, o);
  CHECK(plain.lambda.empty());
  CHECK_THROWS_MENTIONING(plain.reactions(rod.model, "pivot"), std::logic_error, "record_multipliers");
  o.record_multipliers = true;
  const Trajectory s = simulate(rod.model, Rod::q(0.0), Rod::qd(0.0, 0.0), 0.0, 0.5, o);
  REQUIRE(s.lambda.size() == s.t.size());
  const std::vector<Vec3> poses = s.body(rod.model, "rod");
  REQUIRE(poses.size() == s.t.size());
  for (std::size_t i = 0; i < s.t.size(); ++i) CHECK((poses[i] - s.q[i].head<3>()).norm() == 0.0);
  const std::vector<JointReaction> r = s.reactions(rod.model, "pivot");
  REQUIRE(r.size() == s.t.size());
  CHECK(r[0].on_j.force.y() == Approx(kG / 4).epsilon(1e-9));
  CHECK(r[0].on_j.force.x() == Approx(0.0).margin(1e-9));
  // Later on: the reaction balances gravity and the centroid's acceleration, F = m a_G - m g,
  // with a_G from the recorded motion by central differences of the recorded velocities.
  for (std::size_t i = 1; i + 1 < s.t.size(); ++i) {
    CAPTURE(s.t[i]);
    const Vec2 a = (s.qd[i + 1].head<2>() - s.qd[i - 1].head<2>()) / (s.t[i + 1] - s.t[i - 1]);
    CHECK((r[i].on_j.force - (a - Vec2(0, -kG))).norm() < 1e-2 * kG);  // O(dt^2) differences
  }
  CHECK(s.multipliers(rod.model, "pivot").front().size() == 2);
  CHECK_THROWS_MENTIONING(s.body(rod.model, "crank"), std::invalid_argument, "no body 'crank' (the model has 'rod')");
  CHECK_THROWS_MENTIONING(s.multipliers(rod.model, "hinge"), std::invalid_argument, "'pivot'");
}

TEST_CASE("solve_augmented: each of its paths solves [M C_q^T; C_q 0] (x; y) = (top; bottom)", "[integration]") {
  // The four-bar (9 coordinates, 9 rows with its driver) at its initial guess; the oracle is the
  // residual of the unscaled system and Eigen's full-pivot LU of the same dense matrix.
  const Model model = examples::four_bar();
  const VecX q = model.initial_guess();
  const MatX Cq = evaluate_constraints(model, q, 0.0).Cq;
  const Eigen::Index n = Cq.cols(), m = Cq.rows();
  // M per body, with a full block for each body (as a flexible body has); a coupled SPD M (no
  // longer block diagonal); and a non-symmetric M (an implicit integrator's).
  MatX M_bodies = mass_matrix(model, q);
  for (Eigen::Index b = 0; b < n; b += 3) {
    M_bodies(b, b + 2) = M_bodies(b + 2, b) = 0.3 * std::sqrt(M_bodies(b, b) * M_bodies(b + 2, b + 2));
    M_bodies(b + 1, b + 2) = M_bodies(b + 2, b + 1) = -0.2 * std::sqrt(M_bodies(b + 1, b + 1) * M_bodies(b + 2, b + 2));
  }
  MatX coupling = MatX::Zero(n, n);
  coupling(0, 4) = coupling(4, 0) = 0.01;
  const MatX M_coupled = M_bodies + coupling;
  MatX M_skew = M_bodies;
  M_skew(1, 7) = 0.02;
  const VecX top = VecX::LinSpaced(n, -1.0, 2.0), bottom = VecX::LinSpaced(m, 0.5, -0.5);
  for (const auto& [M, name] : {std::pair<const MatX*, const char*>{&M_bodies, "a mass matrix per body"},
                                {&M_coupled, "a coupled SPD matrix"},
                                {&M_skew, "a non-symmetric matrix"}}) {
    CAPTURE(name);
    MatX A = MatX::Zero(n + m, n + m);
    A << *M, Cq.transpose(), Cq, MatX::Zero(m, m);
    VecX b(n + m);
    b << top, bottom;
    const VecX oracle = A.fullPivLu().solve(b);
    for (int repeat = 0; repeat < 2; ++repeat) {  // the second solve reuses the first one's buffers
      const Accelerations a = solve_augmented(model, *M, Cq, top, bottom, "test");
      VecX x(n + m);
      x << a.qdd, a.lambda;
      CHECK((A * x - b).norm() <= 1e-10 * b.norm());
      CHECK((x - oracle).norm() <= 1e-9 * oracle.norm());
    }
  }
  // A redundant row (the first one twice) whose right-hand side contradicts the first: the
  // constraint equations have no solution, and the rows are named, whatever the path. (With a
  // consistent right-hand side it solves: tests/redundant.test.cpp.)
  MatX redundant = Cq;
  redundant.row(m - 1) = Cq.row(0);
  for (const MatX* M : std::initializer_list<const MatX*>{&M_bodies, &M_coupled}) {
    try {
      solve_augmented(model, *M, redundant, top, bottom, "test");
      FAIL("a redundant row was not reported");
    } catch (const SingularJacobianError& e) {
      CHECK_FALSE(e.rows.empty());
      CHECK(std::string(e.what()).find("no solution") != std::string::npos);
    }
  }
}

TEST_CASE("SingularInstant: fixed steps stop short of a predicted rank loss and span it", "[integration]") {
  // A margin that falls as sigma = a |t - t_c| (a = 1.2 / s, t_c = 0.72003 s) seen at the ends of
  // steps of h = 1e-4 s: the safe distance d = 1e-3 / a = 8.3e-4 s is capped at 2 h.
  const double h = 1e-4, a = 1.2, t_c = 0.72003, d = 2 * h;
  SingularInstant plan(0.0, h);
  auto observe_step = [&](double t) { plan.observe(t, a * std::abs(t - t_c)); };
  double t = 0.7;
  observe_step(t - h);
  observe_step(t);
  while (plan.step_from(t, plan.next_grid_point(t)).end == plan.next_grid_point(t)) {
    CHECK(plan.next_grid_point(t) < t_c - d + 1e-12);  // the plain steps end at least d before t_c
    t = plan.next_grid_point(t);
    observe_step(t);
  }
  const SingularInstant::Step stop = plan.step_from(t, plan.next_grid_point(t));
  CHECK_FALSE(stop.spans);
  CHECK(std::abs(stop.end - (t_c - d)) <= 1e-12);  // the step stops d short of the instant
  observe_step(stop.end);
  const SingularInstant::Step span = plan.step_from(stop.end, plan.next_grid_point(stop.end));
  CHECK(span.spans);
  CHECK(std::abs(span.instant - t_c) <= 1e-12);  // the predicted instant
  CHECK(std::abs(span.end - (t_c + 3 * d)) <= 1e-12);  // the instant at a quarter of the spanning step
  // After it the margin rises: plain steps to the grid, the first at least h / 16 away.
  observe_step(span.end);
  const double next = plan.next_grid_point(span.end);
  CHECK(next - span.end >= h / 16);
  CHECK(std::abs(next / h - std::round(next / h)) < 1e-9);
  CHECK(plan.step_from(span.end, next).end == next);
  // A margin that does not fall, or stays above kWatch, changes no step.
  SingularInstant steady(0.0, h), far(0.0, h);
  for (double s : {0.0, h, 2 * h}) {
    steady.observe(s, 0.0);  // a redundant constraint: dependent throughout
    far.observe(s, 0.2 - s);
  }
  CHECK(steady.step_from(2 * h, 3 * h).end == 3 * h);
  CHECK(far.step_from(2 * h, 3 * h).end == 3 * h);
}
