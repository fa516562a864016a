// Project tests (not graded) of forward dynamics with redundant constraints (given code of module
// 4, solve_augmented's rank-revealing path): q_ddot is unique whenever M is positive definite on
// the null space of C_q, only lambda is not, and the engine reports the minimum-norm lambda. Each
// redundant model is checked against an equivalent model without the redundancy. simulate() and
// forward_dynamics() are exercise functions, so this program links the reference variant.
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "fmbd/applied_forces.hpp"
#include "fmbd/constraints.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/forward_dynamics.hpp"
#include "fmbd/gamma.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/mass_matrix.hpp"
#include "fmbd/simulation.hpp"
#include "grading.hpp"

using namespace fmbd;

namespace {

constexpr double kG = 9.81;

double relative_error(const VecX& actual, const VecX& expected) {
  return (actual - expected).norm() / expected.norm();
}

// Largest difference between the poses of body `name` in two runs with the same output times.
double largest_difference(const Model& a, const Trajectory& ta, const Model& b, const Trajectory& tb,
                          const std::string& name) {
  const std::vector<Vec3> pa = ta.body(a, name), pb = tb.body(b, name);
  REQUIRE(pa.size() == pb.size());
  double worst = 0;
  for (std::size_t i = 0; i < pa.size(); ++i) worst = std::max(worst, (pa[i] - pb[i]).cwiseAbs().maxCoeff());
  return worst;
}

SimulationOptions rk4(double h, Stabilisation stabilisation = Stabilisation::none) {
  SimulationOptions o;
  o.integrator = Integrator::rk4;
  o.step = h;
  o.stabilisation = stabilisation;
  o.output_interval = 0.01;
  return o;
}

// A door (mass 12 kg, J = 1.5 kg m^2, centroid 0.4 m from its hinge axis at the origin) under
// gravity and a constant closing torque, on one hinge or on two coaxial hinges (two revolute
// joints at the same axis point, each with its own points). `mass` and `inertia` scale the door.
struct Door {
  static constexpr double L = 0.4;
  Model model;
  explicit Door(int hinges, double mass = 12.0, double inertia = 1.5) {
    model.set_gravity(Vec2(0, -kG));
    const BodyId door = model.add_body("door", mass, inertia, Vec3(L, 0, 0));
    for (int k = 0; k < hinges; ++k) {
      const std::string name = k == 0 ? "upper" : "lower";
      model.add_revolute(name + " hinge", model.add_point(ground, Vec2::Zero(), name + " frame"),
                         model.add_point(door, Vec2(-L, 0), name + " leaf"));
    }
    model.add_torque("closer", door, DriveFunction::constant(-2.0));
  }
  static VecX q(double phi) { return (VecX(3) << L * std::cos(phi), L * std::sin(phi), phi).finished(); }
  static VecX qd(double phi, double w) {
    return (VecX(3) << -L * w * std::sin(phi), L * w * std::cos(phi), w).finished();
  }
};

// A parallelogram of cranks of length a at x = 0 and d (and, with a third crank, at d/2) joined by
// a coupler, under gravity. The third crank is redundant: rank C_q = 11 of 12 rows. With two
// cranks each weighs 1.5 times as much, so that both linkages have the same inertia J and weight
// moment G about the crank angle theta: J theta'' = -G cos(theta) on both.
struct Parallelogram {
  static constexpr double a = 0.2, d = 0.6, m_crank = 0.6, J_crank = 0.6 * a * a / 12, m_coupler = 1.8,
                          J_coupler = 1.8 * d * d / 12;
  Model model;
  std::vector<double> x;  // the cranks' ground pivots
  explicit Parallelogram(int cranks) : x(cranks == 3 ? std::vector<double>{0, d / 2, d} : std::vector<double>{0, d}) {
    model.set_gravity(Vec2(0, -kG));
    const double share = 3.0 / cranks;
    std::vector<BodyId> crank;
    for (double xk : x) {
      const std::string tag = xk == 0 ? "1" : xk == d ? "3" : "2";
      crank.push_back(model.add_body("crank " + tag, share * m_crank, share * J_crank));
    }
    const BodyId coupler = model.add_body("coupler", m_coupler, J_coupler);
    for (std::size_t k = 0; k < x.size(); ++k) {
      const std::string tag = model.bodies()[crank[k].index].name;
      model.add_revolute("pivot of " + tag, model.add_point(ground, Vec2(x[k], 0), "ground under " + tag),
                         model.add_point(crank[k], Vec2(-a / 2, 0), "foot of " + tag));
      model.add_revolute("top of " + tag, model.add_point(crank[k], Vec2(a / 2, 0), "head of " + tag),
                         model.add_point(coupler, Vec2(x[k] - d / 2, 0), "coupler at " + tag));
    }
  }
  VecX q(double theta) const {
    const Vec2 e(std::cos(theta), std::sin(theta));
    VecX q(3 * x.size() + 3);
    for (std::size_t k = 0; k < x.size(); ++k) q.segment<3>(3 * k) << Vec2(x[k], 0) + 0.5 * a * e, theta;
    q.tail<3>() << Vec2(d / 2, 0) + a * e, 0.0;
    return q;
  }
  VecX qd(double theta, double w) const {
    const Vec2 n(-std::sin(theta), std::cos(theta));
    VecX qd(3 * x.size() + 3);
    for (std::size_t k = 0; k < x.size(); ++k) qd.segment<3>(3 * k) << 0.5 * a * w * n, w;
    qd.tail<3>() << a * w * n, 0.0;
    return qd;
  }
  // theta'' = -G cos(theta) / J.
  static double theta_ddot(double theta) {
    const double J = 3 * (J_crank + m_crank * a * a / 4) + m_coupler * a * a;
    const double G = kG * (3 * m_crank * a / 2 + m_coupler * a);
    return -G * std::cos(theta) / J;
  }
};

}  // namespace

TEST_CASE("redundant constraints: a door on two coaxial hinges moves as on one hinge, and they share the load",
          "[redundant]") {
  const Door one(1), two(2);
  for (const auto& [phi, w] : {std::pair<double, double>{0.3, 1.7}, {-1.2, 0.0}, {2.5, -3.0}}) {
    CAPTURE(phi, w);
    const Accelerations a1 = forward_dynamics(one.model, Door::q(phi), Door::qd(phi, w), 0.0);
    const Accelerations a2 = forward_dynamics(two.model, Door::q(phi), Door::qd(phi, w), 0.0);
    CHECK(relative_error(a2.qdd, a1.qdd) <= 1e-13);
    CHECK(a1.rank_deficit == 0);
    CHECK(a1.dependent_rows.empty());
    CHECK(a2.rank_deficit == 2);
    CHECK(a2.dependent_rows == std::vector<int>{0, 1, 2, 3});
    // The minimum-norm multipliers: each hinge carries half of the single hinge's load.
    REQUIRE(a2.lambda.size() == 4);
    CHECK(relative_error(a2.lambda.head(2), 0.5 * a1.lambda) <= 1e-12);
    CHECK(relative_error(a2.lambda.tail(2), 0.5 * a1.lambda) <= 1e-12);
  }
  // One second of RK4: the same trajectory to round-off, and the rank deficit reported once, at
  // the start, with the four rows of the two hinges.
  const Trajectory t1 = simulate(one.model, Door::q(0.3), Door::qd(0.3, 1.7), 0.0, 1.0, rk4(1e-3));
  const Trajectory t2 = simulate(two.model, Door::q(0.3), Door::qd(0.3, 1.7), 0.0, 1.0, rk4(1e-3));
  REQUIRE(t2.t.size() == 101);
  CHECK(largest_difference(one.model, t1, two.model, t2, "door") <= 1e-12);
  CHECK(std::abs(t2.energy.back() - t1.energy.back()) <= 1e-12 * std::abs(t1.energy.front()));
  CHECK(t1.rank_deficits.empty());
  REQUIRE(t2.rank_deficits.size() == 1);
  CHECK(t2.rank_deficits.front().t == 0.0);
  CHECK(t2.rank_deficits.front().rows == std::vector<int>{0, 1, 2, 3});
}

TEST_CASE("redundant constraints: a parallelogram with a third crank moves as the plain parallelogram",
          "[redundant]") {
  const Parallelogram plain(2), redundant(3);
  REQUIRE(evaluate_constraints(redundant.model, redundant.q(0.5), 0.0).C.norm() < 1e-15);
  for (const auto& [theta, w] : {std::pair<double, double>{0.5, 2.0}, {1.2, -1.0}, {2.4, 0.0}}) {
    CAPTURE(theta, w);
    const Accelerations a2 = forward_dynamics(plain.model, plain.q(theta), plain.qd(theta, w), 0.0);
    const Accelerations a3 = forward_dynamics(redundant.model, redundant.q(theta), redundant.qd(theta, w), 0.0);
    CHECK(a2.rank_deficit == 0);
    CHECK(a3.rank_deficit == 1);
    CHECK_FALSE(a3.dependent_rows.empty());
    // Crank 1 and the coupler: the same accelerations, and the closed form theta''.
    const double exact = Parallelogram::theta_ddot(theta);
    CHECK(relative_error(a3.qdd.head<3>(), a2.qdd.head<3>()) <= 1e-12);
    CHECK(relative_error(a3.qdd.tail<3>(), a2.qdd.tail<3>()) <= 1e-12);
    CHECK(std::abs(a3.qdd(2) - exact) <= 1e-12 * std::abs(exact));
    CHECK(std::abs(a3.qdd(5) - exact) <= 1e-12 * std::abs(exact));  // the redundant crank turns with the others
  }
  // One second of RK4 with and without projection, swinging between theta = -2.2 and -0.94 (away
  // from the flat positions theta = 0 and pi, where both linkages lose a rank more): the same
  // motion to round-off.
  for (Stabilisation s : {Stabilisation::none, Stabilisation::projection}) {
    CAPTURE(static_cast<int>(s));
    const Trajectory t2 = simulate(plain.model, plain.q(-1.0), plain.qd(-1.0, 2.0), 0.0, 1.0, rk4(1e-3, s));
    const Trajectory t3 = simulate(redundant.model, redundant.q(-1.0), redundant.qd(-1.0, 2.0), 0.0, 1.0, rk4(1e-3, s));
    REQUIRE(t3.t.size() == 101);
    CHECK(largest_difference(plain.model, t2, redundant.model, t3, "crank 1") <= 1e-10);
    CHECK(largest_difference(plain.model, t2, redundant.model, t3, "coupler") <= 1e-10);
    CHECK(std::abs(t3.energy.back() - t3.energy.front()) <= 1e-8 * std::abs(t3.energy.front()));
    CHECK(t2.rank_deficits.empty());
    REQUIRE(t3.rank_deficits.size() == 1);
    CHECK(t3.rank_deficits.front().t == 0.0);
  }
}

TEST_CASE("redundant constraints: lambda is the minimum-norm set, and its reactions balance M q_ddot = Q",
          "[redundant]") {
  // `tolerance` of lambda against the pseudo-inverse: it grows as 1 / sigma near a singular position.
  auto check = [](const Model& model, const VecX& q, const VecX& qd, int deficit, double tolerance = 1e-12) {
    const Accelerations a = forward_dynamics(model, q, qd, 0.0);
    CHECK(a.rank_deficit == deficit);
    const ConstraintEvaluation e = evaluate_constraints(model, q, 0.0);
    const MatX M = mass_matrix(model, q);
    const VecX Q = applied_forces(model, q, qd, 0.0), gamma = constraint_gamma(model, q, qd, 0.0);
    const VecX inertia = M * a.qdd, reaction = e.Cq.transpose() * a.lambda;
    // The equations of motion and the acceleration constraints hold to round-off.
    CHECK((inertia + reaction - Q).norm() <= 1e-13 * (inertia.norm() + reaction.norm() + Q.norm()));
    CHECK((e.Cq * a.qdd - gamma).norm() <= 1e-13 * ((e.Cq.cwiseAbs() * a.qdd.cwiseAbs()).norm() + gamma.norm()));
    // The pseudo-inverse of C_q^T (an SVD of the unscaled matrix) gives the same lambda.
    Eigen::JacobiSVD<MatX> svd(e.Cq.transpose(), Eigen::ComputeThinU | Eigen::ComputeThinV);
    svd.setThreshold(1e-9);
    REQUIRE(svd.rank() == e.Cq.rows() - deficit);
    CHECK(relative_error(a.lambda, VecX(svd.solve(Q - inertia))) <= tolerance);
    // Every other set of multipliers differs by a vector y of the left null space of C_q
    // (y^T C_q = 0), and lambda is orthogonal to it.
    Eigen::JacobiSVD<MatX> left(e.Cq, Eigen::ComputeFullU);
    const MatX null = left.matrixU().rightCols(deficit);
    CHECK((null.transpose() * e.Cq).norm() <= 1e-12 * e.Cq.norm());
    CHECK((null.transpose() * a.lambda).norm() <= 1e-12 * a.lambda.norm());
  };
  const Parallelogram redundant(3);
  check(redundant.model, redundant.q(0.5), redundant.qd(0.5, 2.0), 1);
  check(redundant.model, redundant.q(2.0), redundant.qd(2.0, -4.0), 1);
  // Near the flat position a second small pivot lifts the redundancy's zero pivot above the
  // structured path's tolerance (it would pass with one lambda of many); the deficit is still
  // found, and lambda is still the minimum-norm set.
  for (double theta : {1e-2, 1e-3, 3e-4}) {
    CAPTURE(theta);
    check(redundant.model, redundant.q(theta), redundant.qd(theta, 2.0), 1, 1e-12 / theta);
  }
  const Door two(2);
  check(two.model, Door::q(0.3), Door::qd(0.3, 1.7), 2);
}

TEST_CASE("solve_augmented: a consistent redundant row gives the solution without it, whatever the path",
          "[redundant]") {
  // The four-bar at its initial guess with its last row (the driver) replaced by a copy of the
  // first, with the same right-hand side: a 1-DOF linkage with one redundant row. The oracle is
  // the same system without the copy (full rank, the structured or general path).
  const Model model = examples::four_bar();
  const VecX q = model.initial_guess();
  const MatX Cq = evaluate_constraints(model, q, 0.0).Cq;
  const Eigen::Index n = Cq.cols(), m = Cq.rows();
  MatX M_coupled = mass_matrix(model, q);
  M_coupled(0, 4) = M_coupled(4, 0) = 0.01;
  MatX M_skew = mass_matrix(model, q);
  M_skew(1, 7) = 0.02;
  const MatX M_bodies = mass_matrix(model, q);
  const VecX top = VecX::LinSpaced(n, -1.0, 2.0);
  VecX bottom = VecX::LinSpaced(m, 0.5, -0.5);
  bottom(m - 1) = bottom(0);
  MatX redundant = Cq;
  redundant.row(m - 1) = Cq.row(0);
  for (const auto& [M, name] : {std::pair<const MatX*, const char*>{&M_bodies, "the mass matrix"},
                                {&M_coupled, "a coupled SPD matrix"},
                                {&M_skew, "a non-symmetric matrix"}}) {
    CAPTURE(name);
    const Accelerations a = solve_augmented(model, *M, redundant, top, bottom, "test");
    const Accelerations oracle = solve_augmented(model, *M, Cq.topRows(m - 1), top, bottom.head(m - 1), "test");
    CHECK(oracle.rank_deficit == 0);
    CHECK(a.rank_deficit == 1);
    CHECK(a.dependent_rows == std::vector<int>{0, static_cast<int>(m - 1)});
    CHECK(relative_error(a.qdd, oracle.qdd) <= 1e-12);
    // The copied row and its original share the original's multiplier; the others are the same.
    CHECK(std::abs(a.lambda(0) - 0.5 * oracle.lambda(0)) <= 1e-12 * oracle.lambda.norm());
    CHECK(std::abs(a.lambda(m - 1) - 0.5 * oracle.lambda(0)) <= 1e-12 * oracle.lambda.norm());
    CHECK(relative_error(a.lambda.segment(1, m - 2), oracle.lambda.segment(1, m - 2)) <= 1e-12);
  }
}

TEST_CASE("redundant constraints: a massless door on two hinges still throws MasslessMotionError", "[redundant]") {
  // Z^T M Z = 0: the hinges leave the door free to turn, and nothing weighs that turn.
  const Door massless(2, 0.0, 0.0);
  try {
    forward_dynamics(massless.model, Door::q(0.3), Door::qd(0.3, 0.0), 0.0);
    FAIL("the massless door was not refused");
  } catch (const MasslessMotionError& e) {
    const std::string what = e.what();
    CAPTURE(what);
    CHECK(e.body == "door");
    CHECK(e.coordinate == 2);
    CHECK(what.find("phi of body 'door'") != std::string::npos);
    CHECK(what.find("dependent rows") != std::string::npos);
    CHECK(what.find("upper hinge") != std::string::npos);
  }
  // A point-mass door (J = 0) on two hinges at its centroid: the same.
  Model point;
  const BodyId door = point.add_body("door", 5.0, 0.0, Vec3(1, 0, 0));
  for (const char* name : {"upper", "lower"})
    point.add_revolute(std::string(name) + " hinge", point.add_point(ground, Vec2(1, 0), std::string(name) + " frame"),
                       point.add_point(door, Vec2::Zero(), std::string(name) + " leaf"));
  CHECK_THROWS_MENTIONING(forward_dynamics(point, point.initial_guess(), VecX::Zero(3), 0.0), MasslessMotionError,
                          "phi of body 'door'");
}

TEST_CASE("redundant constraints: a welded hinge runs (the plate stays put), contradicting drivers are locked",
          "[redundant]") {
  // A revolute joint and a fixed joint at the same point: 5 rows of rank 3 on 3 coordinates. The
  // motion is determined (none), so simulate() runs and reports the dependent rows.
  Model welded;
  welded.set_gravity(Vec2(0, -kG));
  const BodyId b = welded.add_body("plate", 2.0, 0.3);
  const PointId O = welded.add_point(ground, Vec2::Zero(), "O");
  const PointId c = welded.add_point(b, Vec2::Zero(), "centre");
  welded.add_revolute("hinge", O, c);
  welded.add_fixed("weld", O, c);
  SimulationOptions o;
  o.output_interval = 0.1;
  o.record_multipliers = true;
  const Trajectory run = simulate(welded, VecX::Zero(3), VecX::Zero(3), 0.0, 1.0, o);
  CHECK(run.q.back().norm() == 0.0);
  REQUIRE(run.rank_deficits.size() == 1);
  CHECK(run.rank_deficits.front().rows == std::vector<int>{0, 1, 2, 3});
  // The weight is carried half by the hinge and half by the weld's force rows (minimum norm).
  const VecX hinge = run.multipliers(welded, "hinge").back(), weld = run.multipliers(welded, "weld").back();
  CHECK(std::abs(std::abs(hinge(1)) - kG) <= 1e-12 * kG);
  CHECK(std::abs(std::abs(weld(1)) - kG) <= 1e-12 * kG);
  // A driver that asks the welded plate to turn: the acceleration equations have no solution.
  Model locked = welded;
  locked.add_absolute_angle_driver("spin", b, DriveFunction::polynomial({0.0, 0.0, 0.5}));
  try {
    forward_dynamics(locked, VecX::Zero(3), VecX::Zero(3), 0.0);
    FAIL("contradicting constraints were not refused");
  } catch (const SingularJacobianError& e) {
    const std::string what = e.what();
    CAPTURE(what);
    CHECK(std::find(e.rows.begin(), e.rows.end(), 5) != e.rows.end());  // the driver's row
    CHECK(what.find("no solution") != std::string::npos);
    CHECK(what.find("locked") != std::string::npos);
    CHECK(what.find("spin") != std::string::npos);
  }
}

TEST_CASE("singular positions: a parallelogram at and next to its flat position has the accelerations of its branch",
          "[redundant]") {
  // At theta = 0 the loop is flat and C_q loses a rank for an instant (2 degrees of freedom
  // instead of 1); at theta = 1e-7 it has full rank but the augmented matrix looks singular to the
  // general path. Neither is a massless motion: every body has mass. With its two equal cranks
  // the linkage keeps the parallelogram's theta'' = -G cos(theta) / J.
  const Parallelogram plain(2);
  for (const auto& [theta, deficit, tolerance] :
       {std::tuple<double, int, double>{0.0, 1, 1e-13}, {1e-9, 1, 1e-13}, {1e-7, 0, 1e-8}}) {
    for (double w : {0.0, 2.0}) {
      CAPTURE(theta, w);
      const Accelerations a = forward_dynamics(plain.model, plain.q(theta), plain.qd(theta, w), 0.0);
      CHECK(a.rank_deficit == deficit);
      const double exact = Parallelogram::theta_ddot(theta);
      CHECK(std::abs(a.qdd(2) - exact) <= tolerance * std::abs(exact));
      CHECK(std::abs(a.qdd(5) - exact) <= tolerance * std::abs(exact));
    }
  }
}

namespace {

// The N-four-bar mechanism of the library of computational benchmark problems of multibody
// dynamics (problem A02): 2N + 1 slender rods of 1 m and 1 kg, N + 1 cranks on pivots 1 m apart
// joined at their heads by N couplers, under gravity; at t = 0 the cranks stand vertical and
// their heads (B_k) move at 1 m/s along +x. Every half turn the mechanism lies flat, where C_q
// loses N ranks for an instant. On its branch the couplers translate, so theta (every crank's
// angle) obeys J theta'' = -G cos(theta), J = (N + 1)/3 + N, G = 9.81 ((N + 1)/2 + N).
struct FourBarChain {
  Model model;
  VecX q0, qd0;
  int N;
  explicit FourBarChain(int windows) : N(windows) {
    model.set_gravity(Vec2(0, -kG));
    std::vector<BodyId> crank;
    std::vector<double> q, qd;
    for (int k = 0; k <= N; ++k) {
      const std::string name = "crank " + std::to_string(k);
      crank.push_back(model.add_body(name, 1.0, 1.0 / 12));
      model.add_revolute("pivot " + std::to_string(k), model.add_point(ground, Vec2(k, 0), "A" + std::to_string(k)),
                         model.add_point(crank.back(), Vec2(0, -0.5), "foot of " + name));
      q.insert(q.end(), {double(k), 0.5, 0.0});
      qd.insert(qd.end(), {0.5, 0.0, -1.0});
    }
    for (int k = 0; k < N; ++k) {
      const std::string name = "coupler " + std::to_string(k);
      const BodyId coupler = model.add_body(name, 1.0, 1.0 / 12);
      for (int side : {0, 1})
        model.add_revolute(name + " at B" + std::to_string(k + side),
                           model.add_point(crank[k + side], Vec2(0, 0.5), "B" + std::to_string(k + side) + " " + name),
                           model.add_point(coupler, Vec2(side ? 0.5 : -0.5, 0), name + " end " + std::to_string(side)));
      q.insert(q.end(), {k + 0.5, 1.0, 0.0});
      qd.insert(qd.end(), {1.0, 0.0, 0.0});
    }
    q0 = Eigen::Map<const VecX>(q.data(), static_cast<Eigen::Index>(q.size()));
    qd0 = Eigen::Map<const VecX>(qd.data(), static_cast<Eigen::Index>(qd.size()));
  }
  // B0 (the head of crank 0) from theta, the angle of the crank from +x (pi/2 at the start).
  static Vec2 head(double theta) { return Vec2(std::cos(theta), std::sin(theta)); }
  // theta at t = 0, dt, 2 dt, ..., T: RK4 on the one-degree-of-freedom equation, 1e-5 s steps.
  std::vector<double> exact_theta(double dt, double T) const {
    const double J = (N + 1) / 3.0 + N, G = kG * ((N + 1) / 2.0 + N), h = 1e-5;
    auto f = [&](double th) { return -G * std::cos(th) / J; };
    double th = M_PI / 2, w = -1.0;
    std::vector<double> out{th};
    const long per = std::lround(dt / h), steps = std::lround(T / h);
    for (long s = 1; s <= steps; ++s) {
      const double a1 = w, b1 = f(th);
      const double a2 = w + 0.5 * h * b1, b2 = f(th + 0.5 * h * a1);
      const double a3 = w + 0.5 * h * b2, b3 = f(th + 0.5 * h * a2);
      const double a4 = w + h * b3, b4 = f(th + h * a3);
      th += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
      w += h / 6 * (b1 + 2 * b2 + 2 * b3 + b4);
      if (s % per == 0) out.push_back(th);
    }
    return out;
  }
};

}  // namespace

TEST_CASE("singular positions: the N-four-bar benchmark stays on its branch through every flat position",
          "[redundant][singular]") {
  // Four windows (27 coordinates) for 10 s, 400 output points: 14 flat positions. Published
  // tolerance of the benchmark on B0: 1e-3 m (high precision). The projection leaves no residual
  // of C within its tolerance (a neighbouring level set of C, which turns to the other branch at a
  // flat position), so the error falls with the step instead of jumping to 1 m as it did.
  const FourBarChain chain(4);
  const double T = 10.0, dt = T / 400;
  const std::vector<double> theta = chain.exact_theta(dt, T);
  double previous = HUGE_VAL;
  for (const auto& [h, tolerance] : {std::pair<double, double>{1e-2, 1e-5}, {1e-3, 1e-8}, {2.5e-4, 1e-8}}) {
    CAPTURE(h);
    SimulationOptions o = rk4(h, Stabilisation::projection);
    o.output_interval = dt;
    const Trajectory run = simulate(chain.model, chain.q0, chain.qd0, 0.0, T, o);
    REQUIRE(run.t.size() == theta.size());
    double error = 0, drift = 0;
    for (std::size_t i = 0; i < run.t.size(); ++i) {
      const Vec3 c = run.q[i].head<3>();
      const Vec2 B0 = c.head<2>() + 0.5 * Vec2(std::cos(c(2) + M_PI / 2), std::sin(c(2) + M_PI / 2));
      error = std::max(error, (B0 - FourBarChain::head(theta[i])).cwiseAbs().maxCoeff());
      drift = std::max(drift, std::abs(run.energy[i] - run.energy.front()));
    }
    CAPTURE(error, drift, run.rejected_steps);
    CHECK(error <= tolerance);
    CHECK(drift <= 10 * tolerance * std::abs(run.energy.front()));
    if (h == 1e-3) CHECK(error < previous);
    previous = error;
  }
}

TEST_CASE("singular positions: a redundant parallelogram with projection passes its flat positions",
          "[redundant][singular]") {
  // Three cranks, turning through theta = 0 and pi (about 11 flat positions in 3 s): both linkages
  // lose a rank more there. (It stopped at t = 1.65 s with "no solution".) The same motion as the
  // plain parallelogram, and the same energy throughout.
  const Parallelogram plain(2), redundant(3);
  const SimulationOptions o = rk4(1e-3, Stabilisation::projection);
  const Trajectory t2 = simulate(plain.model, plain.q(0.5), plain.qd(0.5, 12.0), 0.0, 3.0, o);
  const Trajectory t3 = simulate(redundant.model, redundant.q(0.5), redundant.qd(0.5, 12.0), 0.0, 3.0, o);
  REQUIRE(t3.t.size() == 301);
  CHECK(largest_difference(plain.model, t2, redundant.model, t3, "crank 1") <= 1e-8);
  for (const Trajectory* run : {&t2, &t3})
    for (double e : run->energy) CHECK(std::abs(e - run->energy.front()) <= 1e-8 * std::abs(run->energy.front()));
}

TEST_CASE("projection: a coarse Euler step keeps its size, and is not taken for a singular position",
          "[redundant][singular]") {
  // The plain parallelogram released at theta = -1, with Euler at 20 ms: every velocity projection
  // removes much of the kinetic energy, as Euler's drift does at every step; none is an anomaly,
  // so no step is halved (the fixed step the lesson compares) and there is no ProjectionError.
  // Euler's energy error carries the swing from 2 rad/s past the flat position theta = -pi and
  // back (t = 1.3 to 1.6 s); where the margins foretell the instant (t = 1.59 s) the steps span it
  // (Trajectory::stepped_over, two steps of another size), and none is halved.
  const Parallelogram plain(2);
  SimulationOptions o = rk4(0.02, Stabilisation::projection);
  o.integrator = Integrator::euler;
  for (double w : {2.0, 0.0}) {  // also from rest, where the first projections remove nothing
    CAPTURE(w);
    const Trajectory run = simulate(plain.model, plain.q(-1.0), plain.qd(-1.0, w), 0.0, 2.0, o);
    CAPTURE(run.stepped_over);
    CHECK(run.steps >= 100);
    CHECK(run.steps <= 100 + 2 * static_cast<int>(run.stepped_over.size()));
    CHECK(run.rejected_steps == 0);
  }
}

namespace {

// A bar turned by a motor beside a free pendulum (swinging at 5 rad/s, whose RK4 drift at 20 ms is
// what a step of this run usually removes), the motor's angle given by `drive`.
Model motor_beside_pendulum(DriveFunction drive) {
  Model model;
  model.set_gravity(Vec2(0, -9.81));
  const BodyId bar = model.add_body("bar", 1.0, 1.0 / 12);
  model.add_revolute("bearing", model.add_point(ground, Vec2(0, 0), "O"), model.add_point(bar, Vec2(-0.5, 0), "hub"));
  model.add_absolute_angle_driver("motor", bar, std::move(drive));
  const BodyId pendulum = model.add_body("pendulum", 1.0, 1.0 / 12);
  model.add_revolute("hinge", model.add_point(ground, Vec2(3, 0), "P"), model.add_point(pendulum, Vec2(-0.5, 0), "top"));
  return model;
}

}  // namespace

TEST_CASE("projection: a drive whose rate jumps is named, not taken for a singular position", "[redundant][singular]") {
  // The motor's angle is 0 until t = 0.5 s and 2 (t - 0.5) after: its rate jumps, so the velocity
  // the constraints ask for jumps, and every halving of the step across it leaves the same share
  // of the kinetic energy to the velocity projection. C_q keeps full rank: the error names the
  // motor's row and the drive's rate, not a singular position. The same model with a smooth drive
  // (DriveFunction::smooth_step) runs, no step halved.
  VecX q0(6), qd0(6);
  q0 << 0.5, 0, 0, 3.5, 0, 0;
  qd0 << 0, 0, 0, 0, 2.5, 5;
  const SimulationOptions o = rk4(0.02, Stabilisation::projection);
  const Model kinked = motor_beside_pendulum(DriveFunction::custom(
      [](double t) { return t < 0.5 ? DriveValue{} : DriveValue{2 * (t - 0.5), 2, 0}; }, "a ramp from t = 0.5 s"));
  try {
    simulate(kinked, q0, qd0, 0.0, 1.0, o);
    FAIL("no ProjectionError");
  } catch (const ProjectionError& e) {
    const std::string message = e.what();
    CAPTURE(message, e.t);
    CHECK(message.find("'motor'") != std::string::npos);
    CHECK(message.find("rate f' jumps") != std::string::npos);
    CHECK(message.find("singular position") == std::string::npos);
    CHECK(std::abs(e.t - 0.5) < 0.02);
  }
  const Model smooth = motor_beside_pendulum(DriveFunction::smooth_step(0.0, 0.2, 0.4, 0.6));
  const Trajectory run = simulate(smooth, q0, qd0, 0.0, 1.0, o);
  CHECK(run.rejected_steps == 0);
  CHECK(std::abs(run.q.back()(2) - 0.2) < 1e-12);
}

TEST_CASE("solve_augmented: a chain of 40 windows (243 coordinates) is solved to round-off for masses 12 decades apart",
          "[sparse]") {
  // The structured path's Schur complement is sparse for a model of 48 rows or more whose M couples
  // no bodies (a chain's is banded). Oracle: the componentwise backward error, computed here on the whole
  // dense system, is round-off; the masses and inertias of the bodies range over 12 decades.
  const FourBarChain chain(40);
  const Model& model = chain.model;
  VecX q = chain.q0;
  for (int k = 0; k <= chain.N; ++k) {  // every crank at 1 rad, its coupler translated with it
    q.segment<3>(3 * k) << k + 0.5 * std::cos(1.0), 0.5 * std::sin(1.0), 1.0 - M_PI / 2;
    if (k < chain.N) q.segment<3>(3 * (chain.N + 1 + k)) << k + 0.5 + std::cos(1.0), std::sin(1.0), 0.0;
  }
  const MatX Cq = evaluate_constraints(model, q, 0.0).Cq;
  const Eigen::Index n = Cq.cols(), m = Cq.rows();
  REQUIRE(Eigen::JacobiSVD<MatX>(Cq).rank() == m);
  for (double spread : {0.0, 6.0}) {
    CAPTURE(spread);
    VecX diagonal(n);
    for (Eigen::Index b = 0; b < n / 3; ++b) {  // masses 10^(+-spread) in turn, inertias the other way
      const double scale = std::pow(10.0, (b % 2 ? 1 : -1) * spread);
      diagonal.segment<3>(3 * b) << scale, scale, 1.0 / (12 * scale);
    }
    const MatX M = diagonal.asDiagonal();
    const VecX top = VecX::LinSpaced(n, -1.0, 2.0).cwiseProduct(diagonal), bottom = VecX::LinSpaced(m, 3.0, -1.0);
    const Accelerations a = solve_augmented(model, M, Cq, top, bottom, "test");
    MatX A = MatX::Zero(n + m, n + m);
    A << M, Cq.transpose(), Cq, MatX::Zero(m, m);
    VecX z(n + m), b(n + m);
    z << a.qdd, a.lambda;
    b << top, bottom;
    const VecX residual = b - A * z, scale = A.cwiseAbs() * z.cwiseAbs() + b.cwiseAbs();
    const double error = residual.cwiseAbs().cwiseQuotient(scale).maxCoeff();
    CAPTURE(error);
    CHECK(a.rank_deficit == 0);
    CHECK(error <= augmented_round_off(n + m));
  }
}

TEST_CASE("singular positions: the N-four-bar benchmark with 40 windows (243 coordinates) stays on its branch",
          "[redundant][singular][sparse]") {
  // The published size of the benchmark (A02, N = 40), 1.2 s at h = 1e-3: through the first flat
  // position, where C_q loses 40 ranks for an instant (the sparse path, and the rank-revealing
  // path's divide and conquer SVD). Published tolerance on B0: 1e-3 m.
  const FourBarChain chain(40);
  const double T = 1.2, dt = T / 120;
  const std::vector<double> theta = chain.exact_theta(dt, T);
  SimulationOptions o = rk4(1e-3, Stabilisation::projection);
  o.output_interval = dt;
  const Trajectory run = simulate(chain.model, chain.q0, chain.qd0, 0.0, T, o);
  REQUIRE(run.t.size() == theta.size());
  double error = 0, lowest = HUGE_VAL;
  for (std::size_t i = 0; i < run.t.size(); ++i) {
    const Vec3 c = run.q[i].head<3>();
    const Vec2 B0 = c.head<2>() + 0.5 * Vec2(std::cos(c(2) + M_PI / 2), std::sin(c(2) + M_PI / 2));
    error = std::max(error, (B0 - FourBarChain::head(theta[i])).cwiseAbs().maxCoeff());
    lowest = std::min(lowest, theta[i]);
  }
  CAPTURE(error, lowest, run.rejected_steps);
  REQUIRE(lowest < 0);  // the run passed a flat position
  CHECK(error <= 1e-8);
  CHECK(std::abs(run.energy.back() - run.energy.front()) <= 1e-6 * std::abs(run.energy.front()));
}
