// Project tests (not graded) of the accuracy of the augmented solve (solve_augmented, given code of
// module 4) on every well-posed model: bodies of vanishing inertia, point masses (J = 0) and
// massless links, in any units, against closed forms; the refusal of a model that is not well
// posed; and the IFToMM benchmark A01 (a point mass on a massless link) against its exact
// solution. Runs on the reference variant of stages 1-4.
#include <cmath>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "fmbd/constraints.hpp"
#include "fmbd/energy.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/forward_dynamics.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/projection.hpp"
#include "fmbd/simulation.hpp"
#include "grading.hpp"

using namespace fmbd;

namespace {

constexpr double kG = 9.81, kPi = 3.14159265358979323846;

// A body of mass m and centroidal inertia J whose centroid lies at distance L from a hinge to the
// ground at the origin; phi is the angle of the line hinge-centroid from the x axis. `length`
// and `mass` are the units (1 for m and kg; 1000 and 1000 for mm and g).
struct HingedBody {
  Model model;
  double L, m, J, g;
  HingedBody(double inertia_si, double length = 1.0, double mass = 1.0)
      : L(length), m(mass), J(inertia_si * mass * length * length), g(kG * length) {
    model.set_gravity(Vec2(0, -g));
    const BodyId bob = model.add_body("bob", m, J, Vec3(L, 0, 0));
    model.add_revolute("hinge", model.add_point(ground, Vec2::Zero(), "O"), model.add_point(bob, Vec2(-L, 0), "end"));
  }
  VecX q(double phi) const { return (VecX(3) << L * std::cos(phi), L * std::sin(phi), phi).finished(); }
  VecX qd(double phi, double w) const {
    return (VecX(3) << -L * w * std::sin(phi), L * w * std::cos(phi), w).finished();
  }
  // The closed form: phi'' = -m g L cos(phi) / (J + m L^2), and the centroid's acceleration.
  VecX qdd(double phi, double w) const {
    const double a = -m * g * L * std::cos(phi) / (J + m * L * L);
    return (VecX(3) << -L * (a * std::sin(phi) + w * w * std::cos(phi)),
            L * (a * std::cos(phi) - w * w * std::sin(phi)), a)
        .finished();
  }
};

double relative_error(const VecX& actual, const VecX& expected) {
  return (actual - expected).norm() / expected.norm();
}

// Jacobi's sn(u, k), by the arithmetic-geometric mean (Abramowitz and Stegun 16.4).
double jacobi_sn(double u, double k) {
  std::vector<double> a{1.0}, c{k};
  double b = std::sqrt(1 - k * k);
  while (std::abs(c.back()) > 1e-17 && a.size() < 30) {
    const double a_next = (a.back() + b) / 2;
    c.push_back((a.back() - b) / 2);
    b = std::sqrt(a.back() * b);
    a.push_back(a_next);
  }
  double phi = std::ldexp(a.back() * u, static_cast<int>(a.size()) - 1);
  for (std::size_t n = a.size() - 1; n > 0; --n) phi = (phi + std::asin(c[n] / a[n] * std::sin(phi))) / 2;
  return std::sin(phi);
}

// K(k), the complete elliptic integral of the first kind, by the arithmetic-geometric mean.
double elliptic_K(double k) {
  double a = 1, b = std::sqrt(1 - k * k);
  for (int i = 0; i < 30 && std::abs(a - b) > 1e-16 * a; ++i) std::tie(a, b) = std::pair(0.5 * (a + b), std::sqrt(a * b));
  return kPi / (2 * a);
}

}  // namespace

TEST_CASE("solve_augmented: a hinged body's accelerations and hinge force are the closed form for every inertia ratio, "
          "J / (m L^2) = 1e-3 ... 1e-15 and 0, in SI and in g and mm",
          "[accuracy]") {
  const double phi = 0.7, w = 1.3;
  for (const double ratio : {1e-3, 1e-6, 1e-9, 1e-11, 1e-12, 1e-13, 1e-14, 1e-15, 0.0}) {
    for (const auto& [length, mass] : {std::pair{1.0, 1.0}, std::pair{1000.0, 1000.0}}) {
      INFO("J / (m L^2) = " << readable(ratio) << ", units of " << readable(length) << " and "
                             << readable(mass) << " per m and kg");
      const HingedBody p(ratio, length, mass);
      const Accelerations a = forward_dynamics(p.model, p.q(phi), p.qd(phi, w), 0.0);
      const VecX exact = p.qdd(phi, w);
      const double error = relative_error(a.qdd, exact);
      INFO("relative error of q_ddot " << readable(error));
      CHECK(error <= 1e-10);
      // The hinge force on the body, C_q^T lambda = Q - M q_ddot, from the closed form.
      const MatX Cq = evaluate_constraints(p.model, p.q(phi), 0.0).Cq;
      const Vec2 force = -(Cq.transpose() * a.lambda).head<2>();
      const Vec2 expected = p.m * (exact.head<2>() - Vec2(0, -p.g));
      CHECK((force - expected).norm() <= 1e-10 * expected.norm());
    }
  }
}

TEST_CASE("solve_augmented: a massless link carrying a disk swings as a point pendulum and the disk keeps its spin",
          "[accuracy]") {
  // The link (m = J = 0) is hinged to the ground at the origin and, at its other end, to the
  // disk's centre: the disk's spin decouples, and the link angle psi obeys psi'' = -g cos(psi) / L.
  const double L = 0.8, m = 2.0, J = 0.3, psi = 0.4, w = 0.9, spin = 2.0;
  Model model;
  model.set_gravity(Vec2(0, -kG));
  const BodyId link = model.add_body("link", 0.0, 0.0, Vec3(L / 2, 0, 0));
  const BodyId disk = model.add_body("disk", m, J, Vec3(L, 0, 0));
  model.add_revolute("pivot", model.add_point(ground, Vec2::Zero(), "O"), model.add_point(link, Vec2(-L / 2, 0), "A"));
  model.add_revolute("hub", model.add_point(link, Vec2(L / 2, 0), "B"), model.add_point(disk, Vec2::Zero(), "centre"));
  const Vec2 u(std::cos(psi), std::sin(psi)), n(-std::sin(psi), std::cos(psi));
  VecX q(6), qd(6);
  q << L / 2 * u, psi, L * u, 1.0;
  qd << L / 2 * w * n, w, L * w * n, spin;
  const double a = -kG * std::cos(psi) / L;
  VecX exact(6);
  exact << L / 2 * (a * n - w * w * u), a, L * (a * n - w * w * u), 0.0;
  const Accelerations result = forward_dynamics(model, q, qd, 0.0);
  CHECK(relative_error(result.qdd, exact) <= 1e-12);
  // Energy over two swings (RK4 with projection): T + V of the disk alone, the link has none.
  SimulationOptions o;
  o.step = 1e-3;
  o.stabilisation = Stabilisation::projection;
  o.integrate_work = false;
  const Trajectory run = simulate(model, q, qd, 0.0, 4.0, o);
  double worst = 0;
  for (double e : run.energy) worst = std::max(worst, std::abs(e - run.energy.front()));
  INFO("largest change of the energy " << readable(worst) << " J");
  CHECK(worst <= 1e-9 * (m * kG * L + 0.5 * J * spin * spin));
}

TEST_CASE("project_velocities: a point mass keeps the tangential part of its velocity (the M-norm ignores phi)",
          "[accuracy]") {
  const HingedBody p(0.0, 1.5, 2.0);
  const double phi = 0.3;
  const Vec2 u(std::cos(phi), std::sin(phi)), n(-std::sin(phi), std::cos(phi));
  VecX qd(3);
  qd << 0.4 * u + 1.1 * n, -7.0;  // a radial part, and a phi_dot that the M-norm does not weigh
  const VecX projected = project_velocities(p.model, p.q(phi), qd, 0.0);
  const VecX expected = p.qd(phi, 1.1 / p.L);
  CHECK(relative_error(projected, expected) <= 1e-12);
}

TEST_CASE("solve_augmented: a model that is not well posed is refused, naming the body and the direction without mass",
          "[accuracy]") {
  {  // a point mass hinged at its own centre: nothing holds or weighs its rotation
    Model model;
    const BodyId bob = model.add_body("bob", 1.0, 0.0, Vec3(1, 0, 0));
    model.add_revolute("hinge", model.add_point(ground, Vec2(1, 0), "O"), model.add_point(bob, Vec2::Zero(), "c"));
    try {
      forward_dynamics(model, model.initial_guess(), VecX::Zero(3), 0.0);
      FAIL("the free rotation of a point mass was not refused");
    } catch (const MasslessMotionError& e) {
      CHECK(e.body == "bob");
      CHECK(e.coordinate == 2);
      CHECK(std::string(e.what()).find("phi of body 'bob'") != std::string::npos);
      CHECK(std::string(e.what()).find("not well posed") != std::string::npos);
    }
  }
  {  // a massless body that nothing holds, beside a well-posed pendulum
    HingedBody p(1e-2);
    p.model.add_body("ghost", 0.0, 0.0, Vec3(3, 0, 0));
    VecX q(6), qd = VecX::Zero(6);
    q << p.q(0.2), 3, 0, 0;
    try {
      forward_dynamics(p.model, q, qd, 0.0);
      FAIL("a massless free body was not refused");
    } catch (const MasslessMotionError& e) {
      CHECK(e.body == "ghost");
    }
  }
  // Negative values are refused when the body is added, with the number readable.
  Model model;
  CHECK_THROWS_MENTIONING(model.add_body("rod", 1.0, -1e-7), ModelError, "inertia must be finite and not negative, got -1e-07");
  CHECK_THROWS_MENTIONING(model.add_body("rod", -0.25, 1.0), ModelError, "got -0.25");
}

TEST_CASE("IFToMM A01: a point mass on a massless link, 2000 s, stays within the benchmark's 1e-3 m of the exact motion",
          "[accuracy]") {
  // A01 (IFToMM library of computational benchmarks, Gonzalez et al.): 1 kg at the end of a
  // massless 1 m link, released at rest from horizontal (P1 at x = +1 m), gravity 9.81 m/s^2 in -y,
  // 2000 s; the error of P1 is measured at 4000 output points and allowed 1e-3 m. The exact motion:
  // sin(theta / 2) = k sn(K - w0 t, k), theta from the downward vertical, k = sin(pi / 4), w0^2 = g / L.
  const HingedBody p(0.0);
  const double k = std::sin(kPi / 4), w0 = std::sqrt(kG / p.L), K = elliptic_K(k);
  const double period = 4 * K / w0;
  SimulationOptions o;
  o.integrator = Integrator::dormand_prince;
  o.rtol = 1e-11;
  o.atol = 1e-11;
  o.max_step = 0.05;
  o.stabilisation = Stabilisation::projection;
  o.output_interval = 0.5;
  o.integrate_work = false;
  const Trajectory run = simulate(p.model, p.q(0.0), p.qd(0.0, 0.0), 0.0, 2000.0, o);
  REQUIRE(run.t.size() == 4001);
  double worst = 0;
  for (std::size_t i = 0; i < run.t.size(); ++i) {
    const double theta = 2 * std::asin(k * jacobi_sn(K - w0 * run.t[i], k));
    const Vec2 exact(p.L * std::sin(theta), -p.L * std::cos(theta));
    worst = std::max(worst, (run.q[i].head<2>() - exact).norm());  // the centroid is P1
  }
  INFO("largest distance of P1 from the exact motion " << readable(worst) << " m (" << run.steps << " steps)");
  CHECK(worst <= 1e-3);
  // The period: after 5T/4 the mass passes the bottom (x = 0) at its full speed sqrt(2 g L), so
  // x / sqrt(2 g L) is the error in time of five quarter periods.
  SimulationOptions fine = o;
  fine.output_interval = 0.0;
  fine.rtol = fine.atol = 1e-13;
  fine.min_step = 1e-14;
  const Trajectory swing = simulate(p.model, p.q(0.0), p.qd(0.0, 0.0), 0.0, 1.25 * period, fine);
  const double time_error = std::abs(swing.q.back()(0)) / std::sqrt(2 * kG * p.L);
  INFO("error in time of 5T/4 " << readable(time_error) << " s, T = " << readable(period) << " s");
  CHECK(time_error <= 1e-10 * period);
}
