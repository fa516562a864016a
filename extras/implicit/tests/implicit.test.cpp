// Project tests (not graded) of the implicit integrator of module 4, the generalised-alpha
// method (generalized_alpha.hpp), and of simulate()'s errors when an explicit integrator blows up.
//
// The oracles are independent of the integrator: the amplification matrix of the method on a
// linear oscillator built here from the published recurrences, closed-form solutions of linear
// oscillators (modal superposition with Eigen's eigensolver), Dormand-Prince with a tight
// tolerance for a non-linear pendulum, and RK4 at a step below its stability limit for the
// flexible slider-crank. The given code calls exercise functions (forward_dynamics, the FFRF mass
// matrix, ...), so this program links the reference stages.
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "fmbd/constraints.hpp"
#include "fmbd/energy.hpp"
#include "fmbd/ffrf.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/generalized_alpha.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/simulation.hpp"
#include "grading.hpp"

using namespace fmbd;
using fmbd::testing::Tolerance;

namespace {

constexpr double kG = 9.81;

// A uniform rod (m = 1, L = 1) hinged at one end to the ground at the origin, optionally with a
// motor torque T(t).
struct Rod {
  Model model;
  explicit Rod(DriveFunction torque = DriveFunction::constant(0.0)) {
    model.set_gravity(Vec2(0, -kG));
    const BodyId rod = model.add_body("rod", 1.0, 1.0 / 12, Vec3(0.5, 0, 0));
    model.add_revolute("pivot", model.add_point(ground, Vec2::Zero(), "O"), model.add_point(rod, Vec2(-0.5, 0), "end"));
    model.add_torque("motor", rod, torque);
  }
  static VecX q(double phi) { return (VecX(3) << 0.5 * std::cos(phi), 0.5 * std::sin(phi), phi).finished(); }
  static VecX qd(double phi, double w) {
    return (VecX(3) << -0.5 * w * std::sin(phi), 0.5 * w * std::cos(phi), w).finished();
  }
};

// Disks hinged at their centres to the ground at the origin, coupled by rotational springs: disk 0
// to the ground (k[0]), disk i to disk i-1 (k[i]). Linear: J phi_ddot = -K phi, with x = y = 0.
struct TorsionChain {
  Model model;
  VecX J, k;
  TorsionChain(const VecX& inertias, const VecX& stiffnesses) : J(inertias), k(stiffnesses) {
    const PointId O = model.add_point(ground, Vec2::Zero(), "O");
    BodyId previous = ground;
    for (Eigen::Index i = 0; i < J.size(); ++i) {
      const std::string name = "disk " + std::to_string(i);
      const BodyId b = model.add_body(name, 1.0, J(i));
      model.add_revolute(name + " bearing", O, model.add_point(b, Vec2::Zero(), name + " centre"));
      model.add_rsda(name + " spring", previous, b, k(i), 0.0, 0.0);
      previous = b;
    }
  }
  int size() const { return static_cast<int>(J.size()); }
  VecX state(const VecX& angles) const {
    VecX q = VecX::Zero(3 * size());
    for (int i = 0; i < size(); ++i) q(3 * i + 2) = angles(i);
    return q;
  }
  VecX angles(const VecX& q) const {
    VecX a(size());
    for (int i = 0; i < size(); ++i) a(i) = q(3 * i + 2);
    return a;
  }
  MatX stiffness() const {
    MatX K = MatX::Zero(size(), size());
    for (int i = 0; i < size(); ++i) {
      K(i, i) += k(i);
      if (i > 0) {
        K(i - 1, i - 1) += k(i);
        K(i - 1, i) -= k(i);
        K(i, i - 1) -= k(i);
      }
    }
    return K;
  }
};

// Closed-form free vibration of M x_ddot + K x = 0 by modal superposition.
struct ModalSolution {
  VecX omega;  // ascending
  MatX Phi;    // mass-normalised mode shapes
  MatX M;
  ModalSolution(const MatX& mass, const MatX& K) : M(mass) {
    Eigen::GeneralizedSelfAdjointEigenSolver<MatX> es(K, M);
    omega = es.eigenvalues().cwiseSqrt();
    Phi = es.eigenvectors();
  }
  VecX at(const VecX& x0, const VecX& v0, double t) const {
    const VecX eta = Phi.transpose() * M * x0, eta_dot = Phi.transpose() * M * v0;
    VecX x = VecX::Zero(x0.size());
    for (Eigen::Index i = 0; i < omega.size(); ++i)
      x += Phi.col(i) * (eta(i) * std::cos(omega(i) * t) + eta_dot(i) / omega(i) * std::sin(omega(i) * t));
    return x;
  }
  // Energy 1/2 (eta_dot^2 + omega^2 eta^2) of mode i.
  double energy(int i, const VecX& x, const VecX& v) const {
    const double eta = Phi.col(i).dot(M * x), eta_dot = Phi.col(i).dot(M * v);
    return 0.5 * (eta_dot * eta_dot + omega(i) * omega(i) * eta * eta);
  }
};

double observed_order(double e_coarse, double e_fine) { return std::log2(e_coarse / e_fine); }

// The amplification matrix of the method on x_ddot = -omega^2 x for the state (x, v, a), from the
// recurrences of Arnold & Bruls with x_ddot_n = -omega^2 x_n at every step.
Eigen::Matrix3d amplification(const GeneralizedAlphaCoefficients& c, double omega_h) {
  const double w2 = omega_h * omega_h;  // with h = 1
  Eigen::Matrix3d A;
  for (int j = 0; j < 3; ++j) {
    const Eigen::Vector3d s = Eigen::Vector3d::Unit(j);
    const double x = s(0), v = s(1), a = s(2);
    // (1 - am) a1 + am a = (1 - af)(-w2 x1) + af (-w2 x),  x1 = x + v + (1/2 - beta) a + beta a1.
    const double rhs = -(1 - c.alpha_f) * w2 * (x + v + (0.5 - c.beta) * a) - c.alpha_f * w2 * x - c.alpha_m * a;
    const double a1 = rhs / ((1 - c.alpha_m) + (1 - c.alpha_f) * w2 * c.beta);
    const double x1 = x + v + (0.5 - c.beta) * a + c.beta * a1;
    const double v1 = v + (1 - c.gamma) * a + c.gamma * a1;
    A.col(j) = Eigen::Vector3d(x1, v1, a1);
  }
  return A;
}

double spectral_radius(const Eigen::Matrix3d& A) {
  return Eigen::EigenSolver<Eigen::Matrix3d>(A).eigenvalues().cwiseAbs().maxCoeff();
}

}  // namespace

// ---- the parameters ---------------------------------------------------------------------------

TEST_CASE("generalized_alpha: coefficients from rho_inf and the spectral radius they give", "[implicit]") {
  const GeneralizedAlphaCoefficients trapezoidal = GeneralizedAlphaCoefficients::from_rho_inf(1.0);
  CHECK(trapezoidal.alpha_m == Approx(0.5));
  CHECK(trapezoidal.alpha_f == Approx(0.5));
  CHECK(trapezoidal.gamma == Approx(0.5));
  CHECK(trapezoidal.beta == Approx(0.25));
  const GeneralizedAlphaCoefficients annihilating = GeneralizedAlphaCoefficients::from_rho_inf(0.0);
  CHECK(annihilating.alpha_m == Approx(-1.0));
  CHECK(annihilating.alpha_f == Approx(0.0).margin(1e-15));
  CHECK(annihilating.gamma == Approx(1.5));
  CHECK(annihilating.beta == Approx(1.0));
  for (double rho : {0.0, 0.3, 0.6, 0.8, 0.95, 1.0}) {
    CAPTURE(rho);
    const GeneralizedAlphaCoefficients c = GeneralizedAlphaCoefficients::from_rho_inf(rho);
    // Second-order accuracy: gamma = 1/2 + alpha_f - alpha_m.
    CHECK(c.gamma == Approx(0.5 + c.alpha_f - c.alpha_m));
    // The spectral radius tends to rho_inf for omega h -> infinity, and to 1 for omega h -> 0.
    CHECK(spectral_radius(amplification(c, 1e7)) == Approx(rho).margin(1e-4));
    CHECK(spectral_radius(amplification(c, 1e-4)) == Approx(1.0).margin(1e-7));
    // Unconditionally stable: never above 1.
    for (double wh : {0.1, 1.0, 3.0, 10.0, 100.0, 1e4}) CHECK(spectral_radius(amplification(c, wh)) <= 1.0 + 1e-6);
  }
  CHECK_THROWS_MENTIONING(GeneralizedAlphaCoefficients::from_rho_inf(1.2), std::invalid_argument, "rho_inf");
  CHECK_THROWS_MENTIONING(GeneralizedAlphaCoefficients::from_rho_inf(-0.1), std::invalid_argument, "rho_inf");
  CHECK_THROWS_AS(GeneralizedAlphaCoefficients::from_rho_inf(std::numeric_limits<double>::quiet_NaN()),
                  std::invalid_argument);
}

// ---- accuracy -----------------------------------------------------------------------------------

TEST_CASE("generalized_alpha: second order on a linear oscillator against the closed form", "[implicit]") {
  // One disk on a torsion spring: J = 0.5, k = 8, omega = 4 rad/s, released from 0.3 rad.
  const TorsionChain chain((VecX(1) << 0.5).finished(), (VecX(1) << 8.0).finished());
  const double phi0 = 0.3, t_end = 2.0;
  for (double rho : {0.0, 0.5, 0.8, 1.0}) {
    CAPTURE(rho);
    GeneralizedAlphaOptions o;
    o.rho_inf = rho;
    std::vector<double> errors;
    for (double h : {0.02, 0.01, 0.005}) {
      const Trajectory tr = generalized_alpha(chain.model, chain.state(VecX::Constant(1, phi0)), VecX::Zero(3), 0.0,
                                              t_end, h, o);
      REQUIRE(tr.steps == static_cast<int>(std::lround(t_end / h)));
      double e = 0;
      for (std::size_t i = 0; i < tr.t.size(); ++i)
        e = std::max(e, std::abs(tr.q[i](2) - phi0 * std::cos(4.0 * tr.t[i])));
      errors.push_back(e);
    }
    INFO("errors " << errors[0] << " " << errors[1] << " " << errors[2]);
    CHECK(errors[2] > 1e-7);  // well above the Newton tolerance
    CHECK(observed_order(errors[0], errors[1]) >= 1.8);
    CHECK(observed_order(errors[0], errors[1]) <= 2.3);
    CHECK(observed_order(errors[1], errors[2]) >= 1.8);
    CHECK(observed_order(errors[1], errors[2]) <= 2.3);
  }
}

TEST_CASE("generalized_alpha: second order on a pendulum, with C = 0 at position level", "[implicit]") {
  // A rod released from 0.4 rad above the horizontal; the reference is Dormand-Prince at a tight
  // tolerance with projection.
  const Rod rod;
  const VecX q0 = Rod::q(0.4), qd0 = Rod::qd(0.4, 0.0);
  const double t_end = 1.0;
  SimulationOptions ref;
  ref.integrator = Integrator::dormand_prince;
  ref.rtol = 1e-12;
  ref.atol = 1e-13;
  ref.step = 1e-4;
  ref.max_step = 0.01;
  ref.stabilisation = Stabilisation::projection;
  ref.projection.tolerance = 1e-13;
  const Trajectory reference = simulate(rod.model, q0, qd0, 0.0, t_end, ref);
  const VecX exact = reference.q.back(), exact_rate = reference.qd.back();

  for (bool project : {false, true}) {
    CAPTURE(project);
    GeneralizedAlphaOptions o;
    o.project_velocities = project;
    std::vector<double> errors, rate_errors;
    for (double h : {0.02, 0.01, 0.005}) {
      const Trajectory tr = generalized_alpha(rod.model, q0, qd0, 0.0, t_end, h, o);
      REQUIRE(tr.t.back() == Approx(t_end));
      errors.push_back(std::abs(tr.q.back()(2) - exact(2)));
      rate_errors.push_back(std::abs(tr.qd.back()(2) - exact_rate(2)));
      double position_drift = 0, velocity_drift = 0;
      for (std::size_t i = 0; i < tr.t.size(); ++i) {
        position_drift = std::max(position_drift, tr.position_drift[i]);
        velocity_drift = std::max(velocity_drift, tr.velocity_drift[i]);
        CHECK(tr.position_drift[i] == Approx(constraints(rod.model, tr.q[i], tr.t[i]).norm()).margin(1e-15));
      }
      CAPTURE(h, position_drift, velocity_drift);
      CHECK(position_drift < 1e-10);  // index 3: C = 0 to the Newton tolerance
      if (project) {
        CHECK(velocity_drift < 1e-10);
      } else {
        CHECK(velocity_drift > 1e-12);  // C_dot = 0 is not imposed ...
        CHECK(velocity_drift < 20.0 * h * h);  // ... but holds to O(h^2)
      }
    }
    INFO("angle errors " << errors[0] << " " << errors[1] << " " << errors[2]);
    INFO("rate errors " << rate_errors[0] << " " << rate_errors[1] << " " << rate_errors[2]);
    CHECK(observed_order(errors[0], errors[1]) >= 1.8);
    CHECK(observed_order(errors[0], errors[1]) <= 2.3);
    CHECK(observed_order(errors[1], errors[2]) >= 1.8);
    CHECK(observed_order(errors[1], errors[2]) <= 2.3);
    CHECK(observed_order(rate_errors[1], rate_errors[2]) >= 1.8);
    CHECK(observed_order(rate_errors[1], rate_errors[2]) <= 2.3);
  }
}

TEST_CASE("generalized_alpha: a point mass on a massless link (J = 0) converges at second order", "[implicit]") {
  // The Newton matrix of a point mass is singular in its M block; the augmented solve takes its
  // general path. The reference is Dormand-Prince at a tight tolerance.
  Model model;
  model.set_gravity(Vec2(0, -kG));
  const BodyId bob = model.add_body("bob", 1.0, 0.0, Vec3(1, 0, 0));
  model.add_revolute("link", model.add_point(ground, Vec2::Zero(), "O"), model.add_point(bob, Vec2(-1, 0), "end"));
  const VecX q0 = model.initial_guess(), qd0 = VecX::Zero(3);
  SimulationOptions ref;
  ref.integrator = Integrator::dormand_prince;
  ref.rtol = ref.atol = 1e-12;
  ref.stabilisation = Stabilisation::projection;
  const double exact = simulate(model, q0, qd0, 0.0, 1.0, ref).q.back()(2);
  std::vector<double> errors;
  for (double h : {0.01, 0.005}) {
    const Trajectory tr = generalized_alpha(model, q0, qd0, 0.0, 1.0, h);
    errors.push_back(std::abs(tr.q.back()(2) - exact));
    CHECK(*std::max_element(tr.position_drift.begin(), tr.position_drift.end()) < 1e-10);
  }
  INFO("angle errors " << errors[0] << " " << errors[1]);
  CHECK(observed_order(errors[0], errors[1]) >= 1.8);
  CHECK(observed_order(errors[0], errors[1]) <= 2.3);
}

// ---- dissipation ----------------------------------------------------------------------------------

TEST_CASE("generalized_alpha: rho_inf = 1 keeps the energy of a stiff linear chain, rho_inf < 1 damps its stiff mode",
          "[implicit]") {
  // Two disks: a soft spring to the ground and a stiff one between them. omega h of the stiff mode
  // is far beyond any explicit limit, that of the soft mode small.
  const TorsionChain chain((VecX(2) << 0.2, 0.1).finished(), (VecX(2) << 2.0, 2e6).finished());
  const ModalSolution modes(MatX(chain.J.asDiagonal()), chain.stiffness());
  const double h = 0.01;
  REQUIRE(modes.omega(0) * h < 0.05);
  REQUIRE(modes.omega(1) * h > 50.0);
  // Both modes excited, the stiff one with a small amplitude.
  const VecX x0 = 0.3 * modes.Phi.col(0) / modes.Phi.col(0).norm() + 1e-3 * modes.Phi.col(1) / modes.Phi.col(1).norm();
  const VecX q0 = chain.state(x0), qd0 = VecX::Zero(6);
  const double E_soft = modes.energy(0, x0, VecX::Zero(2)), E_stiff = modes.energy(1, x0, VecX::Zero(2));
  const double E0 = kinetic_energy(chain.model, q0, qd0) + potential_energy(chain.model, q0);
  REQUIRE(E0 == Approx(E_soft + E_stiff).epsilon(1e-9));
  const int steps = 60;

  GeneralizedAlphaOptions o;
  o.rho_inf = 1.0;
  o.rtol = 1e-12;
  o.atol = 1e-14;
  const Trajectory conserving = generalized_alpha(chain.model, q0, qd0, 0.0, steps * h, h, o);
  double worst = 0;
  for (std::size_t i = 0; i < conserving.t.size(); ++i) worst = std::max(worst, std::abs(conserving.energy[i] - E0));
  INFO("energy " << E0 << " J, largest change " << worst << " J");
  CHECK(worst < 1e-9 * E0);
  const VecX x_end = chain.angles(conserving.q.back()), v_end = chain.angles(conserving.qd.back());
  CHECK(modes.energy(1, x_end, v_end) == Approx(E_stiff).epsilon(1e-6));
  CHECK(modes.energy(0, x_end, v_end) == Approx(E_soft).epsilon(1e-6));

  for (double rho : {0.0, 0.5, 0.8}) {
    CAPTURE(rho);
    o.rho_inf = rho;
    const Trajectory damped = generalized_alpha(chain.model, q0, qd0, 0.0, steps * h, h, o);
    const VecX x = chain.angles(damped.q.back()), v = chain.angles(damped.qd.back());
    const double stiff = modes.energy(1, x, v), soft = modes.energy(0, x, v);
    // The stiff mode loses its energy by r^2 per step, r the spectral radius of the method at its
    // omega h (close to rho_inf); steps^2 allows for the nearly double eigenvalue -r.
    const GeneralizedAlphaCoefficients c = GeneralizedAlphaCoefficients::from_rho_inf(rho);
    const double r = spectral_radius(amplification(c, modes.omega(1) * h));
    INFO("stiff-mode energy " << E_stiff << " -> " << stiff << ", soft " << E_soft << " -> " << soft << ", r = " << r);
    CHECK(stiff < std::max(1e-20, steps * steps * std::pow(r, 2 * steps)) * E_stiff);
    // The soft mode keeps its energy (rho_inf = 0 damps it most) and follows the closed form.
    CHECK(soft == Approx(E_soft).epsilon(rho > 0 ? 1e-4 : 1e-3));
    const VecX soft_exact = modes.at(x0 - x0.dot(modes.M * modes.Phi.col(1)) * modes.Phi.col(1), VecX::Zero(2),
                                     damped.t.back());
    CHECK_CLOSE(x, soft_exact, (Tolerance{1e-4, 0}), "the soft mode follows the closed form");
    CHECK(damped.energy.back() < E0 - 0.99 * E_stiff);
  }
}

// ---- monitors and the simulate front end --------------------------------------------------------

TEST_CASE("generalized_alpha: the work monitor and the output interval", "[implicit]") {
  // A constant torque T: W(t) = T (phi(t) - phi(0)). With rho_inf = 1 the trapezoidal rule on the
  // power T phi_dot is exactly the position update, so W matches to round-off.
  const double T = 3.0;
  const Rod rod(DriveFunction::constant(T));
  const VecX q0 = Rod::q(-0.5), qd0 = Rod::qd(-0.5, 0.0);
  GeneralizedAlphaOptions o;
  o.rho_inf = 1.0;
  const Trajectory tr = generalized_alpha(rod.model, q0, qd0, 0.0, 1.0, 1e-3, o);
  REQUIRE(tr.t.size() == 1001);
  CHECK(tr.steps == 1000);
  CHECK(tr.rejected_steps == 0);
  CHECK(tr.step.front() == 0.0);
  CHECK(tr.step.back() == Approx(1e-3));
  for (std::size_t i = 0; i < tr.t.size(); i += 100) {
    CAPTURE(i);
    CHECK(tr.work_done[i] == Approx(T * (tr.q[i](2) + 0.5)).margin(1e-9));
    CHECK(tr.energy[i] - tr.energy[0] == Approx(tr.work_done[i]).margin(1e-4));
  }
  // Without the work monitor: the same motion, and work_done stays empty.
  GeneralizedAlphaOptions quiet = o;
  quiet.integrate_work = false;
  const Trajectory same = generalized_alpha(rod.model, q0, qd0, 0.0, 1.0, 1e-3, quiet);
  CHECK(same.work_done.empty());
  REQUIRE(same.t.size() == tr.t.size());
  for (std::size_t i = 0; i < tr.t.size(); ++i) {
    CHECK(same.q[i] == tr.q[i]);
    CHECK(same.energy[i] == tr.energy[i]);
  }
  // output_interval thins the record but keeps the end point.
  const Trajectory thin = generalized_alpha(rod.model, q0, qd0, 0.0, 1.0, 1e-3, o, 0.1);
  CHECK(thin.steps == 1000);
  CHECK(thin.t.size() == 11);
  CHECK(thin.t.back() == Approx(1.0));
  CHECK(thin.q.back() == tr.q.back());
  // project_velocities removes the O(h^2) velocity drift.
  o.rho_inf = 0.8;
  const Trajectory plain = generalized_alpha(rod.model, q0, qd0, 0.0, 0.2, 1e-3, o);
  o.project_velocities = true;
  const Trajectory projected = generalized_alpha(rod.model, q0, qd0, 0.0, 0.2, 1e-3, o);
  CHECK(plain.velocity_drift.back() > 1e-10);
  CHECK(projected.velocity_drift.back() < 1e-12);
}

// ---- errors ------------------------------------------------------------------------------------------

TEST_CASE("generalized_alpha: bad arguments throw invalid_argument naming them", "[implicit]") {
  const Rod rod;
  const VecX q0 = Rod::q(0.2), qd0 = Rod::qd(0.2, 0.0);
  auto run = [&](double step, const GeneralizedAlphaOptions& o, double t_end = 0.1) {
    return generalized_alpha(rod.model, q0, qd0, 0.0, t_end, step, o);
  };
  GeneralizedAlphaOptions o;
  CHECK_THROWS_MENTIONING(run(0.0, o), std::invalid_argument, "step must be positive");
  CHECK_THROWS_MENTIONING(run(std::numeric_limits<double>::quiet_NaN(), o), std::invalid_argument, "step");
  CHECK_THROWS_MENTIONING(run(-1e-7, o), std::invalid_argument, "step must be positive, got -1e-07");
  CHECK_THROWS_MENTIONING(run(1e-3, o, 0.0), std::invalid_argument, "t_end must be after t0");
  o.rho_inf = 1.5;
  CHECK_THROWS_MENTIONING(run(1e-3, o), std::invalid_argument, "rho_inf");
  o = GeneralizedAlphaOptions{};
  o.rtol = -1e-9;
  CHECK_THROWS_MENTIONING(run(1e-3, o), std::invalid_argument, "rtol must be positive, got -1e-09");
  o = GeneralizedAlphaOptions{};
  o.atol = -1.0;
  CHECK_THROWS_MENTIONING(run(1e-3, o), std::invalid_argument, "atol");
  o = GeneralizedAlphaOptions{};
  o.max_iterations = 0;
  CHECK_THROWS_MENTIONING(run(1e-3, o), std::invalid_argument, "max_iterations");
  o = GeneralizedAlphaOptions{};
  VecX q_bad = q0;
  q_bad(1) += 0.01;
  CHECK_THROWS_MENTIONING(generalized_alpha(rod.model, q_bad, qd0, 0.0, 0.1, 1e-3), std::invalid_argument,
                          "revolute joint 'pivot' (equation 2 of 2)");
  CHECK_THROWS_AS(generalized_alpha(rod.model, VecX::Zero(2), qd0, 0.0, 0.1, 1e-3), std::invalid_argument);
}

TEST_CASE("generalized_alpha: Newton non-convergence throws NewtonIterationError with the time and the residual",
          "[implicit]") {
  const Rod rod;
  const VecX q0 = Rod::q(0.3), qd0 = Rod::qd(0.3, 0.0);
  GeneralizedAlphaOptions o;
  o.max_iterations = 1;
  o.rtol = 1e-14;
  o.atol = 1e-16;
  bool thrown = false;
  try {
    generalized_alpha(rod.model, q0, qd0, 0.0, 1.0, 0.01, o);
  } catch (const NewtonIterationError& e) {
    thrown = true;
    const std::string what = e.what();
    CAPTURE(what);
    CHECK(what.find("did not converge in 1 iteration") != std::string::npos);
    CHECK(what.find("at t = 0 s (step 0)") != std::string::npos);
    CHECK(what.find("advancing to t = 0.01 s") != std::string::npos);
    CHECK(what.find("residual norm") != std::string::npos);
    CHECK(e.t == 0.0);
    CHECK(e.step == 0);
    CHECK(e.iterations == 1);
    CHECK(std::isfinite(e.residual));
    CHECK(e.residual > 0.0);
  }
  CHECK(thrown);
  // It is an IntegrationError for callers that handle every integrator's errors alike.
  CHECK_THROWS_AS(generalized_alpha(rod.model, q0, qd0, 0.0, 1.0, 0.01, o), IntegrationError);
  o.max_iterations = 10;
  o.rtol = 1e-8;
  o.atol = 1e-10;
  o.project_velocities = true;  // a consistent state to start again from
  const Trajectory fine = generalized_alpha(rod.model, q0, qd0, 0.0, 0.05, 0.01, o);
  // A run that starts at t = 0.05 s names that time.
  o.max_iterations = 1;
  CHECK_THROWS_MENTIONING(generalized_alpha(rod.model, fine.q.back(), fine.qd.back(), 0.05, 1.0, 0.01, o),
                          NewtonIterationError, "at t = 0.05 s");
}

TEST_CASE("generalized_alpha: NaN in the forces throws IntegrationError, never NaN output", "[implicit]") {
  // A motor torque that turns NaN after t = 0.055 s: the step from 0.05 s to 0.06 s meets it.
  const Rod rod(DriveFunction::custom(
      [](double t) {
        const double T = t > 0.055 ? std::numeric_limits<double>::quiet_NaN() : 1.0;
        return DriveValue{T, 0.0, 0.0};
      },
      "a torque that fails"));
  bool thrown = false;
  try {
    generalized_alpha(rod.model, Rod::q(0.0), Rod::qd(0.0, 0.0), 0.0, 1.0, 0.01);
  } catch (const IntegrationError& e) {
    thrown = true;
    const std::string what = e.what();
    CAPTURE(what);
    CHECK(what.find("NaN or Inf") != std::string::npos);
    CHECK(what.find("the equation of motion of") != std::string::npos);
    CHECK(what.find("of body 'rod'") != std::string::npos);
    CHECK(e.t == Approx(0.05));
    CHECK(e.step == 5);
  }
  CHECK(thrown);
}

TEST_CASE("generalized_alpha: a locked mechanism throws SingularJacobianError naming the rows and the time",
          "[implicit]") {
  // A plate welded at its hinge: redundant but consistent, so it runs and stays put. A driver that
  // asks it to turn (phi = t^2 / 2) contradicts the weld: no acceleration satisfies both.
  Model model;
  model.set_gravity(Vec2(0, -kG));
  const BodyId b = model.add_body("plate", 2.0, 0.3);
  const PointId O = model.add_point(ground, Vec2::Zero(), "O");
  const PointId c = model.add_point(b, Vec2::Zero(), "centre");
  model.add_revolute("hinge", O, c);
  model.add_fixed("weld", O, c);
  const Trajectory held = generalized_alpha(model, VecX::Zero(3), VecX::Zero(3), 0.0, 0.1, 0.01);
  CHECK(held.q.back().cwiseAbs().maxCoeff() <= 1e-12);
  model.add_absolute_angle_driver("spin", b, DriveFunction::polynomial({0.0, 0.0, 0.5}));
  CHECK_THROWS_MENTIONING(generalized_alpha(model, VecX::Zero(3), VecX::Zero(3), 0.0, 1.0, 0.01),
                          SingularJacobianError, "at t = 0");
  CHECK_THROWS_MENTIONING(generalized_alpha(model, VecX::Zero(3), VecX::Zero(3), 0.0, 1.0, 0.01),
                          SingularJacobianError, "weld");
}

// ---- a stiff flexible model -------------------------------------------------------------------------

namespace {

// The flexible slider-crank with the full FFRF rod: 10 elements, Craig-Bampton on both end nodes
// with 20 fixed-interface modes, 23 elastic coordinates.
FlexibleExample stiff_slider_crank() {
  FlexibleSliderCrankParameters p;
  p.elements = 10;
  p.modes = 20;
  return flexible_slider_crank(p, make_ffrf_body);
}

}  // namespace

TEST_CASE("generalized_alpha: the flexible slider-crank with 23 modes at 100 times RK4's stability limit",
          "[implicit]") {
  const FlexibleExample ex = stiff_slider_crank();
  const Model& m = ex.model;
  REQUIRE(ex.data->num_modes() == 23);
  const int slider = m.offset(m.find_body("slider")), crank = m.offset(m.find_body("crank"));
  const double t_end = 0.02, interval = 1e-3;

  // RK4 is stable below about 8.6e-6 s on this model (measured): the reference runs at 5e-6 s.
  SimulationOptions rk4;
  rk4.integrator = Integrator::rk4;
  rk4.step = 5e-6;
  rk4.output_interval = interval;
  const Trajectory reference = simulate(m, ex.q0, ex.qd0, 0.0, t_end, rk4);
  REQUIRE(reference.t.size() == 21);
  double peak = 0;
  for (const VecX& q : reference.q) peak = std::max(peak, std::abs(midspan_deflection(ex, q)));
  INFO("reference: peak mid-span deflection " << peak << " m");
  REQUIRE(peak > 1e-3);  // the rod bends visibly

  // At 1e-3 s RK4 blows up, and says so with the time and a coordinate, or the joint that came
  // apart first, instead of NaN output.
  rk4.step = 1e-3;
  REQUIRE_THROWS_AS(simulate(m, ex.q0, ex.qd0, 0.0, t_end, rk4), IntegrationError);
  try {
    simulate(m, ex.q0, ex.qd0, 0.0, t_end, rk4);
  } catch (const IntegrationError& e) {
    const std::string what = e.what();
    CAPTURE(what);
    CHECK(what.find("at t = ") != std::string::npos);
    CHECK((what.find("body 'rod'") != std::string::npos || what.find("revolute joint") != std::string::npos));
    CHECK(e.t < t_end);
  }
  // So does it at 1e-5 s, just above its limit.
  rk4.step = 1e-5;
  CHECK_THROWS_AS(simulate(m, ex.q0, ex.qd0, 0.0, t_end, rk4), IntegrationError);

  // Generalised-alpha at 1e-3 s (about 115 times RK4's limit) and 2.5e-4 s.
  for (double h : {1e-3, 2.5e-4}) {
    CAPTURE(h);
    const Trajectory tr = generalized_alpha(m, ex.q0, ex.qd0, 0.0, t_end, h, {}, interval);
    REQUIRE(tr.t.size() == reference.t.size());
    double slider_error = 0, deflection_error = 0, drift = 0;
    for (std::size_t i = 0; i < tr.t.size(); ++i) {
      REQUIRE(tr.t[i] == Approx(reference.t[i]).margin(1e-12));
      REQUIRE(tr.q[i].allFinite());
      REQUIRE(tr.qd[i].allFinite());
      CHECK(std::isfinite(tr.energy[i]));
      CHECK(tr.q[i](crank + 2) == Approx(150.0 * tr.t[i]).margin(1e-9));  // the crank angle (driven: exact)
      slider_error = std::max(slider_error, std::abs(tr.q[i](slider) - reference.q[i](slider)));
      const double deflection = midspan_deflection(ex, tr.q[i]) - midspan_deflection(ex, reference.q[i]);
      deflection_error = std::max(deflection_error, std::abs(deflection));
      drift = std::max(drift, tr.position_drift[i]);
    }
    INFO("slider error " << slider_error << " m, mid-span deflection error " << deflection_error << " m of a peak "
                         << peak << " m, |C| <= " << drift);
    CHECK(drift < 1e-10);
    // The slider's 0.3 m stroke to 1e-4 m: the rigid motion is right at either step. (The 3e-5 m
    // left is the rod's axial vibration, which steps this large filter out; with steps that resolve
    // it the difference falls as h^2.)
    CHECK(slider_error < 1e-4);
    // The deflection is second order in h: 21 % of its peak off at 1e-3 s (the first elastic mode,
    // 1809 rad/s, has under four steps per period), 1.5 % at 2.5e-4 s (measured).
    CHECK(deflection_error < (h > 5e-4 ? 0.5 : 0.05) * peak);
  }
}
