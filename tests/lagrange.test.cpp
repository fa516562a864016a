// Project tests (not graded) of the given code of module 3: the applied-force assembly's checks,
// the energies and the non-conservative power against hand computations, solve_multipliers and
// its errors, inverse_dynamics over a grid, and the model builder's checks of the force elements.
// The given code calls module 1-3 exercise functions (point_position, gravity_force, ...), so
// this program links the reference stages.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "fmbd/applied_forces.hpp"
#include "fmbd/constraints.hpp"
#include "fmbd/energy.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/inverse_dynamics.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/model.hpp"
#include "grading.hpp"

using namespace fmbd;
using fmbd::testing::Tolerance;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr Tolerance kTight{1e-12, 1e-12};

VecX vec(std::initializer_list<double> values) {
  VecX v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index k = 0;
  for (double x : values) v(k++) = x;
  return v;
}

// The undriven slider-crank at crank angle 0.5 (8 equations, 9 coordinates).
struct UndrivenSliderCrank {
  examples::SliderCrankParameters p;
  Model model;
  VecX q;
  UndrivenSliderCrank() {
    p.A0 = 0.5;
    p.driven = false;
    model = examples::slider_crank(p);
    q = examples::slider_crank_configuration(p, p.A0);
  }
};

}  // namespace

TEST_CASE("applied_forces: coinciding spring-damper points are named", "[lagrange]") {
  Model m;
  const BodyId b = m.add_body("b", 1.0, 0.1);
  const PointId g = m.add_point(ground, Vec2(0.5, 0.0), "anchor");
  const PointId p = m.add_point(b, Vec2(0.5, 0.0), "hook");
  m.add_tsda("coil", g, p, 10.0, 0.2, 1.0);
  const VecX q = VecX::Zero(3), qd = VecX::Zero(3);
  CHECK_THROWS_MENTIONING(applied_forces(m, q, qd, 0.0), std::domain_error,
                          "spring-damper 'coil': its points 'anchor' and 'hook' coincide");
  // Apart, the spring pulls: hook at (0.5 + 1, 0) with L0 = 0.2 and k = 10: f = 8 towards the anchor.
  const VecX q2 = vec({1.0, 0.0, 0.0});
  CHECK_CLOSE(applied_forces(m, q2, qd, 0.0), vec({-8.0, 0.0, 0.0}), kTight, "stretched spring on the hook");
  CHECK_THROWS_MENTIONING(applied_forces(m, VecX::Zero(4), qd, 0.0), std::invalid_argument, "q");
  CHECK_THROWS_MENTIONING(applied_forces(m, q, VecX::Zero(2), 0.0), std::invalid_argument, "q_dot");
}

TEST_CASE("applied_forces: gravity, a torque and a rotational spring to the ground", "[lagrange]") {
  Model m;
  const BodyId a = m.add_body("a", 2.0, 0.1), b = m.add_body("b", 3.0, 0.2);
  m.set_gravity(Vec2(1.0, -10.0));
  m.add_torque("spin", b, DriveFunction::linear(1.0, 2.0));
  CHECK_THROWS_MENTIONING(m.add_point_force("on ground", m.add_point(ground, Vec2(1, 1), "G"), Vec2(100, 100)),
                          ModelError, "point 'G' is on the ground");
  m.add_rsda("twist", a, ground, 4.0, 0.0, 0.0);
  const VecX q = vec({0, 0, 0.25, 1, 1, 0}), qd = VecX::Zero(6);
  // a: gravity (2, -20), RSDA on body i with theta = 0 - 0.25: T = -1, +T on a. b: (3, -30), torque 1 + 2 t.
  CHECK_CLOSE(applied_forces(m, q, qd, 0.5), vec({2, -20, -1, 3, -30, 2}), kTight, "assembly by hand");
}

TEST_CASE("kinetic_energy: 1/2 (m |v|^2 + J w^2) per body", "[lagrange]") {
  Model m;
  m.add_body("a", 2.0, 0.5);
  m.add_body("b", 3.0, 0.1);
  const VecX qd = vec({1, 2, 3, -1, 0, 2});
  // 0.5 * 2 * 5 + 0.5 * 0.5 * 9 + 0.5 * 3 * 1 + 0.5 * 0.1 * 4
  CHECK(kinetic_energy(m, qd) == Approx(8.95).epsilon(1e-14));
  CHECK(kinetic_energy(m, VecX::Zero(6)) == 0.0);
  CHECK_THROWS_MENTIONING(kinetic_energy(m, VecX::Zero(5)), std::invalid_argument, "q_dot");
}

TEST_CASE("potential_energy: gravity, global point forces, springs; not follower forces", "[lagrange]") {
  Model m;
  const BodyId b = m.add_body("b", 2.0, 0.1);
  const PointId tip = m.add_point(b, Vec2(1.0, 0.0), "tip");
  const PointId O = m.add_point(ground, Vec2::Zero(), "O");
  m.set_gravity(Vec2(0.0, -10.0));
  const VecX q = vec({1.0, 3.0, kPi / 2});  // tip at (1, 4)
  CHECK(potential_energy(m, q) == Approx(60.0).epsilon(1e-14));  // -m g^T R = -2 (-10) 3
  m.add_point_force("push", tip, Vec2(4.0, 0.0));
  m.add_point_force("follower", tip, Vec2(7.0, 9.0), Frame::body);
  CHECK(potential_energy(m, q) == Approx(56.0).epsilon(1e-14));  // - F^T r_P = -4
  m.add_tsda("coil", O, tip, 10.0, 2.0, 5.0);
  m.add_rsda("twist", ground, b, 3.0, 0.5, 1.0);
  const double L = std::sqrt(17.0);
  const double expected = 56.0 + 0.5 * 10.0 * (L - 2.0) * (L - 2.0) + 0.5 * 3.0 * (kPi / 2 - 0.5) * (kPi / 2 - 0.5);
  CHECK(potential_energy(m, q) == Approx(expected).epsilon(1e-14));
  CHECK_THROWS_MENTIONING(potential_energy(m, VecX::Zero(4)), std::invalid_argument, "q");
}

TEST_CASE("nonconservative_power: dampers, actuators, torques and follower forces", "[lagrange]") {
  Model m;
  const BodyId b = m.add_body("b", 1.0, 0.1);
  const PointId tip = m.add_point(b, Vec2(1.0, 0.0), "tip");
  const PointId far = m.add_point(ground, Vec2(3.0, 0.0), "far");
  m.add_torque("spin", b, DriveFunction::linear(2.0, 1.0));                  // T(1) = 3
  m.add_point_force("follower", tip, Vec2(0.0, 5.0), Frame::body);          // F_g = (0, 5)
  m.add_point_force("global", tip, Vec2(8.0, 8.0));                         // in V, not here
  m.add_tsda("damper", far, tip, 7.0, 1.0, 4.0, DriveFunction::constant(1.5));
  m.add_rsda("twist", ground, b, 9.0, 0.0, 0.5, DriveFunction::constant(0.25));
  const VecX q = VecX::Zero(3), qd = vec({1.0, 0.0, 2.0});
  // v_tip = (1, 0) + 2 (0, 1) = (1, 2). Torque 3 * 2 = 6; follower (0, 5)^T (1, 2) = 10.
  // Damper: d = tip - far = (-2, 0), u = (-1, 0), L_dot = -1: -(4 (-1) + 1.5)(-1) = -2.5.
  // RSDA: theta_dot = 2: -(0.5 * 2 + 0.25) * 2 = -2.5.
  CHECK(nonconservative_power(m, q, qd, 1.0) == Approx(11.0).epsilon(1e-14));
  CHECK(nonconservative_power(m, q, VecX::Zero(3), 1.0) == 0.0);
}

TEST_CASE("solve_multipliers: solves C_q^T lambda = rhs for a driven model", "[lagrange]") {
  examples::SliderCrankParameters p;
  p.A0 = 0.7;
  const Model model = examples::slider_crank(p);
  const VecX q = examples::slider_crank_configuration(p, p.A0);
  const MatX Cq = constraint_jacobian(model, q, 0.0);
  const VecX rhs = vec({1, -2, 3, 0.5, 0, -1, 2, 0.25, 4});
  const VecX lambda = solve_multipliers(model, Cq, rhs);
  CHECK_CLOSE(Cq.transpose() * lambda, rhs, (Tolerance{1e-10, 1e-10}), "C_q^T lambda = rhs");
  CHECK_THROWS_MENTIONING(solve_multipliers(model, Cq, VecX::Zero(8)), std::invalid_argument, "right-hand side");
}

TEST_CASE("solve_multipliers: an undriven model is refused with its degrees of freedom", "[lagrange]") {
  const UndrivenSliderCrank s;
  const MatX Cq = constraint_jacobian(s.model, s.q, 0.0);
  REQUIRE(Cq.rows() == 8);
  CHECK_THROWS_MENTIONING(solve_multipliers(s.model, Cq, VecX::Zero(9)), std::invalid_argument,
                          "1 degree(s) of freedom without a driver");
  CHECK_THROWS_MENTIONING(solve_multipliers(s.model, Cq, VecX::Zero(9)), std::invalid_argument, "m = 8");
  // More equations than coordinates: redundant.
  Model over = examples::slider_crank();
  over.add_absolute_angle_driver("slider angle", over.find_body("slider"), DriveFunction::constant(0.0));
  const VecX q = examples::slider_crank_configuration({}, 0.0);
  CHECK_THROWS_MENTIONING(solve_multipliers(over, constraint_jacobian(over, q, 0.0), VecX::Zero(9)),
                          std::invalid_argument, "remove the 1 redundant equation(s)");
}

TEST_CASE("solve_multipliers: a redundant driver throws SingularJacobianError with its rows", "[lagrange]") {
  UndrivenSliderCrank s;
  s.model.add_absolute_angle_driver("slider angle", s.model.find_body("slider"), DriveFunction::constant(0.0));
  const MatX Cq = constraint_jacobian(s.model, s.q, 0.0);
  REQUIRE(Cq.rows() == 9);
  bool thrown = false;
  try {
    solve_multipliers(s.model, Cq, VecX::Ones(9));
  } catch (const SingularJacobianError& e) {
    thrown = true;
    const std::string message = e.what();
    CAPTURE(message);
    // Row 7: the guide's angle equation; row 8: the driver of the same angle.
    CHECK(std::find(e.rows.begin(), e.rows.end(), 7) != e.rows.end());
    CHECK(std::find(e.rows.begin(), e.rows.end(), 8) != e.rows.end());
    CHECK(message.find("absolute-angle driver 'slider angle'") != std::string::npos);
    CHECK(message.find("translational joint 'slider guide' (equation 2 of 2)") != std::string::npos);
    CHECK(message.find("rank 8 < 9") != std::string::npos);
  }
  CHECK(thrown);
}

TEST_CASE("inverse_dynamics: the kinematics and one multiplier vector per time", "[lagrange]") {
  examples::SliderCrankParameters p;
  p.A0 = 0.3;
  Model model = examples::slider_crank(p);
  model.set_gravity(Vec2(0.0, -9.81));
  const std::vector<double> times = {0.0, 0.1, 0.2, 0.3};
  const InverseDynamicsSolution s = inverse_dynamics(model, examples::slider_crank_configuration(p, p.A0), times);
  REQUIRE(s.kinematics.q.size() == times.size());
  REQUIRE(s.lambda.size() == times.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    CAPTURE(k);
    CHECK_CLOSE(s.lambda[k],
                lagrange_multipliers(model, s.kinematics.q[k], s.kinematics.qd[k], s.kinematics.qdd[k], times[k]),
                kTight, "lambda at each time from lagrange_multipliers at that state");
  }
}

TEST_CASE("model builder: force elements are checked and named", "[lagrange][model]") {
  Model m;
  const BodyId b = m.add_body("b", 1.0, 0.5), c = m.add_body("c", 1.0, 0.5);
  const PointId p = m.add_point(b, Vec2(0.5, 0), "p"), p2 = m.add_point(b, Vec2(-0.5, 0), "p2");
  const PointId g = m.add_point(ground, Vec2(1, 2), "g");
  CHECK_THROWS_MENTIONING(m.add_tsda("s", g, p, -1.0, 0.1, 0.0), ModelError,
                          "spring-damper 's': stiffness k must be finite and not negative");
  CHECK_THROWS_MENTIONING(m.add_tsda("s", g, p, 1.0, -0.1, 0.0), ModelError, "free length L0 must be");
  CHECK_THROWS_MENTIONING(m.add_tsda("s", g, p, 1.0, 0.1, -2.0), ModelError, "damping c must be");
  CHECK_THROWS_MENTIONING(m.add_tsda("s", g, p, kNaN, 0.1, 0.0), ModelError, "stiffness k");
  CHECK_THROWS_MENTIONING(m.add_tsda("s", p, p2, 1.0, 0.1, 0.0), ModelError,
                          "spring-damper 's': both points are on body 'b'");
  CHECK_THROWS_MENTIONING(m.add_tsda("s", g, PointId{9}, 1.0, 0.1, 0.0), ModelError, "point 9 does not exist");
  CHECK_THROWS_MENTIONING(m.add_rsda("r", b, c, -3.0, 0.0, 0.0), ModelError,
                          "rotational spring-damper 'r': stiffness k must be finite and not negative");
  CHECK_THROWS_MENTIONING(m.add_rsda("r", b, c, 3.0, 0.0, -1.0), ModelError, "damping c must be");
  CHECK_THROWS_MENTIONING(m.add_rsda("r", b, c, 3.0, kNaN, 0.0), ModelError, "theta0 is not finite");
  CHECK_THROWS_MENTIONING(m.add_rsda("r", c, c, 3.0, 0.0, 0.0), ModelError, "connects body 'c' to itself");
  CHECK_THROWS_MENTIONING(m.add_rsda("r", b, BodyId{7}, 3.0, 0.0, 0.0), ModelError, "body 7 does not exist");
  CHECK_THROWS_MENTIONING(m.add_torque("t", ground, DriveFunction::constant(1.0)), ModelError,
                          "torque 't': a torque on the ground does nothing");
  CHECK_THROWS_MENTIONING(m.add_point_force("f", p, Vec2(kNaN, 0)), ModelError, "point force 'f': F is not finite");
  CHECK_THROWS_MENTIONING(m.set_gravity(Vec2(0, kNaN)), ModelError, "gravity is not finite");
  CHECK(m.forces().empty());
  CHECK(m.gravity() == Vec2::Zero());

  m.add_point_force("f", p, Vec2(1, 0));
  CHECK_THROWS_MENTIONING(m.add_torque("f", b, DriveFunction::constant(1.0)), ModelError, "duplicate force name 'f'");
  CHECK_THROWS_MENTIONING(m.add_tsda("f", g, p, 1.0, 0.1, 0.0), ModelError, "duplicate force name 'f'");
  CHECK_THROWS_MENTIONING(m.add_rsda("", b, c, 1.0, 0.0, 0.0), ModelError, "non-empty name");
  CHECK(m.forces().size() == 1);
  // Zero coefficients are allowed; the ground may be either side of a spring-damper.
  CHECK(m.add_tsda("s", p, g, 0.0, 0.0, 0.0) == 1);
  CHECK(m.add_rsda("r", b, ground, 0.0, 0.0, 0.0) == 2);
  CHECK(m.add_rsda("r2", ground, c, 1.0, -0.5, 0.0) == 3);
  CHECK(std::holds_alternative<Rsda>(m.forces()[3].element));
}
