// Project tests (not graded) of the given code of module 4: simulate()'s option and consistency
// checks and its errors, the monitors, Trajectory::write_csv, error_norm,
// consistent_initial_conditions and the paths of solve_augmented. simulate() calls the exercise
// functions (forward_dynamics, the integrators, the projections), so this program links the
// reference variant of stages 1-4.
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
#include "grading.hpp"
#include "integration_models.hpp"

using namespace fmbd;
using fmbd::testing::Tolerance;
using namespace fmbd::integration_testing;

namespace {

// The lines of tr.write_csv(), through a temporary file named after `name`.
std::vector<std::string> written_csv(const Trajectory& tr, const std::string& name) {
  const std::string path =
      (std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()) + ".csv")).string();
  tr.write_csv(path);
  std::vector<std::string> lines;
  {
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
  }
  std::remove(path.c_str());
  return lines;
}

int count_fields(const std::string& line) {
  int fields = 1;
  for (char c : line) fields += c == ',';
  return fields;
}

}  // namespace

TEST_CASE("simulate: bad options throw invalid_argument naming the option", "[integration]") {
  const Rod rod;
  const VecX q0 = Rod::q(0.2), qd0 = Rod::qd(0.2, 0.0);
  SimulationOptions o;
  o.step = -1e-3;
  CHECK_THROWS_MENTIONING(simulate(rod.model, q0, qd0, 0.0, 1.0, o), std::invalid_argument, "step must be positive");
  o.step = 0.0;
  CHECK_THROWS_MENTIONING(simulate(rod.model, q0, qd0, 0.0, 1.0, o), std::invalid_argument, "step must be positive");
  o.step = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_MENTIONING(simulate(rod.model, q0, qd0, 0.0, 1.0, o), std::invalid_argument, "step must be positive");
  o = SimulationOptions{};
  CHECK_THROWS_MENTIONING(simulate(rod.model, q0, qd0, 1.0, 1.0, o), std::invalid_argument, "t_end must be after t0");
  CHECK_THROWS_MENTIONING(simulate(rod.model, q0, qd0, 2.0, 1.0, o), std::invalid_argument, "t_end must be after t0");
  o.integrator = Integrator::dormand_prince;
  o.rtol = 0.0;
  CHECK_THROWS_MENTIONING(simulate(rod.model, q0, qd0, 0.0, 1.0, o), std::invalid_argument, "rtol must be positive");
  o.rtol = 1e-6;
  o.min_step = -1.0;
  CHECK_THROWS_MENTIONING(simulate(rod.model, q0, qd0, 0.0, 1.0, o), std::invalid_argument, "min_step");
  o = SimulationOptions{};
  o.stabilisation = Stabilisation::baumgarte;
  o.baumgarte = Baumgarte{-1.0, 5.0};
  CHECK_THROWS_MENTIONING(simulate(rod.model, q0, qd0, 0.0, 1.0, o), std::invalid_argument, "must not be negative");
  // Wrong sizes name the argument.
  CHECK_THROWS_AS(simulate(rod.model, VecX::Zero(2), qd0, 0.0, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(simulate(rod.model, q0, VecX::Zero(4), 0.0, 1.0), std::invalid_argument);
}

TEST_CASE("simulate: inconsistent initial conditions name the constraint row", "[integration]") {
  const Rod rod;
  VecX q0 = Rod::q(0.2);
  q0(1) += 0.01;  // the hinge opens along y: equation 2 of the revolute joint
  CHECK_THROWS_MENTIONING(simulate(rod.model, q0, Rod::qd(0.2, 0.0), 0.0, 1.0), std::invalid_argument,
                          "inconsistent initial conditions: C(q0)");
  CHECK_THROWS_MENTIONING(simulate(rod.model, q0, Rod::qd(0.2, 0.0), 0.0, 1.0), std::invalid_argument,
                          "revolute joint 'pivot' (equation 2 of 2)");
  VecX qd0 = Rod::qd(0.2, 1.0);
  qd0(0) += 0.05;  // the hinge would open along x
  CHECK_THROWS_MENTIONING(simulate(rod.model, Rod::q(0.2), qd0, 0.0, 1.0), std::invalid_argument,
                          "C_q q_dot0 + C_t");
  CHECK_THROWS_MENTIONING(simulate(rod.model, Rod::q(0.2), qd0, 0.0, 1.0), std::invalid_argument,
                          "revolute joint 'pivot' (equation 1 of 2)");
  // Below the 1e-6 threshold the run starts.
  VecX q_close = Rod::q(0.2);
  q_close(0) += 1e-8;
  CHECK_NOTHROW(simulate(rod.model, q_close, Rod::qd(0.2, 0.0), 0.0, 0.01));
}

namespace {

// Runs `model` from q0 at rest with explicit Euler and a step far beyond its stability limit
// and checks that the blow-up ends in an IntegrationError naming the time, the step and a
// coordinate of body 'mass', not in NaN output.
void check_blow_up(const Model& model, const VecX& q0, double step) {
  SimulationOptions o;
  o.integrator = Integrator::euler;
  o.step = step;
  bool thrown = false;
  try {
    simulate(model, q0, VecX::Zero(q0.size()), 0.0, 1000.0, o);
  } catch (const IntegrationError& e) {
    thrown = true;
    const std::string what = e.what();
    CAPTURE(what, e.t, e.step);
    CHECK((what.find("NaN or Inf") != std::string::npos || what.find("has blown up") != std::string::npos));
    CHECK(what.find("(step ") != std::string::npos);
    CHECK(what.find("body 'mass'") != std::string::npos);
    CHECK(std::isfinite(e.t));
    CHECK(e.t > 0.0);
    CHECK(e.t < 1000.0);
    CHECK(e.step > 0);
    CHECK(e.step < 1000.0 / step);
  }
  CHECK(thrown);
}

}  // namespace

TEST_CASE("simulate: a blow-up throws IntegrationError with the time and the step instead of NaN output",
          "[integration]") {
  // A free body on a stiff rotational spring (linear in the state): explicit Euler with a step
  // 100 times 1/omega multiplies the amplitude by about 100 per step until it overflows.
  Model model;
  const BodyId b = model.add_body("mass", 1.0, 1e-4);
  model.add_rsda("stiff torsion spring", ground, b, 1.0, 0.0, 0.0);
  check_blow_up(model, (VecX(3) << 0.0, 0.0, 0.1).finished(), 1.0);
}

// Given-code bug (module04_integration/src/simulation.cpp): with a non-linear force the right-hand
// side overflows while the state is still finite, and solve_augmented's KinematicsError ("the
// augmented system contains NaN or Inf") escapes simulate() without the time and the step.
TEST_CASE("simulate: a blow-up of a non-linear spring throws IntegrationError too", "[integration]") {
  Model model;
  const BodyId b = model.add_body("mass", 1.0, 0.1);
  model.add_tsda("stiff spring", model.add_point(ground, Vec2::Zero(), "anchor"), model.add_point(b, Vec2::Zero(), "c"),
                 1e6, 0.5, 0.0);
  check_blow_up(model, (VecX(3) << 0.6, 0.0, 0.0).finished(), 0.1);
}

// A locked mechanism: a plate welded to the ground at its hinge, and a driver that asks it to
// turn (phi = t^2 / 2). Position and velocity are consistent at t = 0, but no acceleration
// satisfies both the weld and the driver. (A weld and a hinge alone are redundant but consistent:
// they run, tests/redundant.test.cpp.)
namespace {
Model locked_plate() {
  Model model;
  model.set_gravity(Vec2(0, -kG));
  const BodyId b = model.add_body("plate", 2.0, 0.3);
  const PointId O = model.add_point(ground, Vec2::Zero(), "O");
  const PointId c = model.add_point(b, Vec2::Zero(), "centre");
  model.add_revolute("hinge", O, c);
  model.add_fixed("weld", O, c);
  model.add_absolute_angle_driver("spin", b, DriveFunction::polynomial({0.0, 0.0, 0.5}));
  return model;
}
}  // namespace

TEST_CASE("simulate: a locked mechanism throws SingularJacobianError naming the rows", "[integration]") {
  const Model model = locked_plate();
  try {
    simulate(model, VecX::Zero(3), VecX::Zero(3), 0.0, 1.0);
    FAIL("no exception");
  } catch (const SingularJacobianError& e) {
    const std::string what = e.what();
    CAPTURE(what);
    CHECK(!e.rows.empty());
    CHECK(what.find("the constraint equations have no solution") != std::string::npos);
    CHECK(what.find("locked") != std::string::npos);
    CHECK(what.find("weld") != std::string::npos);
    CHECK(what.find("spin") != std::string::npos);
  }
}

// Given-code bug (simulation.cpp): the singular matrix is first met by the power monitor's call
// of forward_dynamics before the first step (and likewise after each step and in the
// projections), outside the right-hand side that appends "at t = ... (step ...)". Remove
TEST_CASE("simulate: SingularJacobianError names the time", "[integration]") {
  CHECK_THROWS_MENTIONING(simulate(locked_plate(), VecX::Zero(3), VecX::Zero(3), 0.0, 1.0), SingularJacobianError,
                          "at t = 0");
}

TEST_CASE("simulate: StepSizeError when min_step is too large for the tolerance", "[integration]") {
  const Rod rod;
  SimulationOptions o;
  o.integrator = Integrator::dormand_prince;
  o.rtol = 1e-13;
  o.atol = 1e-15;
  o.step = 0.05;
  o.min_step = 0.01;
  bool thrown = false;
  try {
    simulate(rod.model, Rod::q(0.0), Rod::qd(0.0, 0.0), 0.0, 1.0, o);
  } catch (const StepSizeError& e) {
    thrown = true;
    const std::string what = e.what();
    CAPTURE(what);
    CHECK(what.find("min_step") != std::string::npos);
    CHECK(e.t == 0.0);
    CHECK(e.step == 0);
  }
  CHECK(thrown);
  // StepSizeError is an IntegrationError.
  CHECK_THROWS_AS(simulate(rod.model, Rod::q(0.0), Rod::qd(0.0, 0.0), 0.0, 1.0, o), IntegrationError);
}

TEST_CASE("simulate: monitors of energy, work, drift and step", "[integration]") {
  // A constant torque T from rest: W(t) = T (phi(t) - phi(0)), and E(t) - E(0) = W(t).
  const double T = 3.0;
  const Rod rod(T);
  SimulationOptions o;
  o.step = 1e-3;
  const Trajectory s = simulate(rod.model, Rod::q(-0.5), Rod::qd(-0.5, 0.0), 0.0, 1.0, o);
  REQUIRE(s.t.size() == 1001);
  CHECK(s.steps == 1000);
  CHECK(s.rejected_steps == 0);
  CHECK(s.step.front() == 0.0);
  CHECK(s.step.back() == Approx(1e-3));
  CHECK(s.t.back() == Approx(1.0));
  REQUIRE(s.work_done.size() == s.t.size());
  CHECK(s.work_done.front() == 0.0);
  for (std::size_t i = 0; i < s.t.size(); i += 100) {
    CAPTURE(i);
    const double phi = s.q[i](2), w = s.qd[i](2);
    CHECK(s.work_done[i] == Approx(T * (phi + 0.5)).margin(1e-8));
    const double E = 0.5 * (s.qd[i].head<2>().squaredNorm() + w * w / 12) + kG * s.q[i](1);
    CHECK(s.energy[i] == Approx(E).margin(1e-12));
    CHECK(s.energy[i] - s.energy[0] == Approx(s.work_done[i]).margin(1e-8));
    CHECK(s.position_drift[i] == Approx(constraints(rod.model, s.q[i], s.t[i]).norm()).margin(1e-15));
  }
  // output_interval thins the record but keeps the end point.
  o.output_interval = 0.1;
  const Trajectory thin = simulate(rod.model, Rod::q(-0.5), Rod::qd(-0.5, 0.0), 0.0, 1.0, o);
  CHECK(thin.steps == 1000);
  CHECK(thin.t.size() == 11);
  CHECK(thin.t.back() == Approx(1.0));
  for (std::size_t i = 1; i < thin.t.size(); ++i) CHECK(thin.t[i] - thin.t[i - 1] >= 0.1 - 1e-9);
}

TEST_CASE("simulate: without the work monitor the motion is the same and work_done is empty", "[integration]") {
  // A rod with a motor torque (non-conservative power) and a driven four-bar (driver power):
  // the work integrand is nonzero in both, so the runs with and without it differ only in the
  // monitor. Each integrator, with projection, on an output grid that falls inside steps.
  examples::FourBarParameters p;
  p.omega = 1.5;
  const Model four_bar = examples::four_bar(p);
  const State start = consistent_initial_conditions(four_bar, four_bar.initial_guess(), VecX::Zero(9), 0.0);
  const Rod rod(3.0);
  struct Case {
    const Model& model;
    VecX q0, qd0;
    std::string header;
  };
  const Case cases[] = {{rod.model, Rod::q(-0.5), Rod::qd(-0.5, 0.0), "t,step,energy,position_drift,velocity_drift,q0,q1,q2,qd0,qd1,qd2"},
                        {four_bar, start.q, start.qd, ""}};
  for (const Case& c : cases) {
    for (const Integrator integrator : {Integrator::euler, Integrator::rk4, Integrator::dormand_prince}) {
      SimulationOptions on;
      on.integrator = integrator;
      on.step = 0.01;
      on.output_interval = 0.1;
      on.stabilisation = Stabilisation::projection;
      SimulationOptions off = on;
      off.integrate_work = false;
      const Trajectory a = simulate(c.model, c.q0, c.qd0, 0.0, 1.0, on);
      const Trajectory b = simulate(c.model, c.q0, c.qd0, 0.0, 1.0, off);
      CAPTURE(c.model.num_bodies(), static_cast<int>(integrator));
      REQUIRE(a.work_done.size() == a.t.size());
      CHECK(std::abs(a.work_done.back()) > 1e-2);  // the monitor has something to integrate
      CHECK(b.work_done.empty());
      CHECK(b.steps == a.steps);
      CHECK(b.rejected_steps == a.rejected_steps);
      REQUIRE(b.t.size() == a.t.size());
      for (std::size_t k = 0; k < a.t.size(); ++k) {
        CAPTURE(k);
        CHECK(b.t[k] == a.t[k]);
        CHECK((b.q[k] - a.q[k]).norm() <= 1e-14 * (1 + a.q[k].norm()));
        CHECK((b.qd[k] - a.qd[k]).norm() <= 1e-14 * (1 + a.qd[k].norm()));
        CHECK(b.energy[k] == Approx(a.energy[k]).epsilon(1e-13).margin(1e-13));
        CHECK(b.position_drift[k] == Approx(a.position_drift[k]).margin(1e-15));
      }
      if (c.header.empty()) continue;
      // The CSV has no work column then.
      const std::vector<std::string> lines = written_csv(b, "fmbd_m04_no_work");
      REQUIRE(lines.size() == b.t.size() + 1);
      CHECK(lines[0] == c.header);
      for (std::size_t i = 1; i < lines.size(); ++i) CHECK(count_fields(lines[i]) == 11);
    }
  }
}

TEST_CASE("Trajectory::write_csv writes a header and one line per point", "[integration]") {
  const Rod rod;
  SimulationOptions o;
  o.step = 0.01;
  const Trajectory s = simulate(rod.model, Rod::q(0.1), Rod::qd(0.1, 0.0), 0.0, 0.1, o);
  REQUIRE(s.t.size() == 11);
  const std::vector<std::string> lines = written_csv(s, "fmbd_m04_trajectory");
  REQUIRE(lines.size() == 12);
  CHECK(lines[0] == "t,step,energy,work_done,position_drift,velocity_drift,q0,q1,q2,qd0,qd1,qd2");
  for (std::size_t i = 1; i < lines.size(); ++i) CHECK(count_fields(lines[i]) == 12);
  CHECK(lines[1].rfind("0,0,", 0) == 0);
  std::istringstream last(lines.back());
  double t_last = 0;
  last >> t_last;
  CHECK(t_last == Approx(0.1));
  CHECK_THROWS_MENTIONING(s.write_csv("/nonexistent-directory/x.csv"), std::runtime_error, "cannot open");
}

TEST_CASE("error_norm matches a hand computation", "[integration]") {
  const VecX error = (VecX(2) << 1e-6, -2e-6).finished();
  const VecX y = (VecX(2) << 1.0, -3.0).finished();
  const VecX y_new = (VecX(2) << 2.0, 0.5).finished();
  // scale = atol + rtol max(|y|, |y_new|) = (1e-6 + 2e-3, 1e-6 + 3e-3)
  const double e0 = 1e-6 / 0.002001, e1 = 2e-6 / 0.003001;
  CHECK(error_norm(error, y, y_new, 1e-3, 1e-6) == Approx(std::sqrt((e0 * e0 + e1 * e1) / 2)).epsilon(1e-14));
  CHECK(error_norm(VecX(), VecX(), VecX(), 1e-3, 1e-6) == 0.0);
  // With rtol = 0 it is the RMS of error / atol.
  CHECK(error_norm(error, y, y_new, 0.0, 1e-6) == Approx(std::sqrt((1.0 + 4.0) / 2)).epsilon(1e-14));
}

TEST_CASE("consistent_initial_conditions satisfies the position and velocity equations", "[integration]") {
  examples::FourBarParameters p;
  p.omega = 1.5;  // driven: C_t != 0
  const Model model = examples::four_bar(p);
  const double t = 0.4;
  VecX guess = model.initial_guess();
  guess(2) += 0.05;
  guess(4) -= 0.02;
  const VecX qd_guess = VecX::Constant(9, 0.3);
  const State s = consistent_initial_conditions(model, guess, qd_guess, t);
  const ConstraintEvaluation e = evaluate_constraints(model, s.q, t);
  CHECK(e.C.norm() < 1e-10);
  CHECK((e.Cq * s.qd + e.Ct).norm() < 1e-10);
  CHECK(s.q(2) == Approx(p.theta0 + p.omega * t).margin(1e-10));  // the driver holds
  // The result starts a simulation without complaint.
  SimulationOptions o;
  o.step = 1e-2;
  CHECK_NOTHROW(simulate(model, s.q, s.qd, t, t + 0.1, o));
  // Sizes are checked.
  CHECK_THROWS_AS(consistent_initial_conditions(model, VecX::Zero(8), qd_guess, t), std::invalid_argument);
  CHECK_THROWS_AS(consistent_initial_conditions(model, guess, VecX::Zero(10), t), std::invalid_argument);
}

TEST_CASE("simulate: output lies on the grid t0 + k dt, the last point at t_end, without drift", "[integration]") {
  const Rod rod;
  SimulationOptions o;
  o.step = 1e-3;
  o.output_interval = 0.5;
  const double t0 = 0.1, t_end = 20.1;
  const Trajectory s = simulate(rod.model, Rod::q(0.3), Rod::qd(0.3, 0.0), t0, t_end, o);
  REQUIRE(s.t.size() == 41);
  for (std::size_t k = 0; k < s.t.size(); ++k) {
    CAPTURE(k);
    CHECK(s.t[k] == Approx(t0 + 0.5 * static_cast<double>(k)).epsilon(1e-15).margin(1e-14));
  }
  CHECK(s.t.back() == t_end);
  CHECK(s.steps == 20000);
  // A step that does not divide the interval: the last step is shortened to end at t_end.
  o.step = 0.03;
  o.output_interval = 0.0;
  const Trajectory every = simulate(rod.model, Rod::q(0.3), Rod::qd(0.3, 0.0), 0.0, 1.0, o);
  CHECK(every.t.back() == 1.0);
  CHECK(every.steps == 34);
  CHECK(every.step.back() == Approx(0.01).margin(1e-12));
}

TEST_CASE("simulate: output between steps is the step's Hermite extension, close to the motion", "[integration]") {
  // Output every 0.1 s from steps of 0.03 s: the grid times fall inside steps. Oracle: the same
  // run with steps of 1e-3 s, which land on the grid.
  const Rod rod(2.0);
  SimulationOptions coarse;
  coarse.step = 0.03;
  coarse.output_interval = 0.1;
  SimulationOptions fine = coarse;
  fine.step = 1e-3;
  const Trajectory a = simulate(rod.model, Rod::q(-0.4), Rod::qd(-0.4, 0.0), 0.0, 2.0, coarse);
  const Trajectory b = simulate(rod.model, Rod::q(-0.4), Rod::qd(-0.4, 0.0), 0.0, 2.0, fine);
  REQUIRE(a.t.size() == 21);
  REQUIRE(b.t.size() == 21);
  for (std::size_t k = 0; k < a.t.size(); ++k) {
    CAPTURE(k, a.t[k]);
    CHECK(a.t[k] == Approx(b.t[k]).margin(1e-14));
    // RK4 with h = 0.03 and its cubic extension: errors of order h^4 ~ 1e-6.
    CHECK((a.q[k] - b.q[k]).norm() < 1e-5);
    CHECK((a.qd[k] - b.qd[k]).norm() < 1e-4);
    CHECK(a.work_done[k] == Approx(b.work_done[k]).margin(1e-5));
  }
}

TEST_CASE("simulate: the adaptive integrator gives output on the grid, independent of its steps", "[integration]") {
  const double T = 3.0;
  const Rod rod(T);
  SimulationOptions o;
  o.integrator = Integrator::dormand_prince;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  o.output_interval = 0.05;
  const Trajectory s = simulate(rod.model, Rod::q(-0.5), Rod::qd(-0.5, 0.0), 0.0, 1.0, o);
  REQUIRE(s.t.size() == 21);
  CHECK(s.steps != 20);  // the steps do not follow the grid
  for (std::size_t k = 0; k < s.t.size(); ++k) {
    CAPTURE(k, s.t[k]);
    CHECK(s.t[k] == Approx(0.05 * static_cast<double>(k)).margin(1e-14));
    // Work of a constant torque, W = T (phi - phi0), and the energy balance E - E0 = W: both
    // exact up to the tolerance, also between steps.
    CHECK(s.work_done[k] == Approx(T * (s.q[k](2) + 0.5)).margin(1e-8));
    CHECK(s.energy[k] - s.energy[0] == Approx(s.work_done[k]).margin(1e-8));
  }
  // Every step recorded: the work is integrated with the motion, not by a trapezoid of the power.
  o.output_interval = 0.0;
  const Trajectory all = simulate(rod.model, Rod::q(-0.5), Rod::qd(-0.5, 0.0), 0.0, 1.0, o);
  for (std::size_t k = 0; k < all.t.size(); ++k)
    CHECK(all.energy[k] - all.energy[0] == Approx(all.work_done[k]).margin(1e-9));
}

TEST_CASE("simulate: a non-finite initial state is named as such", "[integration]") {
  const Rod rod;
  VecX q0 = Rod::q(0.2);
  q0(2) = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_MENTIONING(simulate(rod.model, q0, Rod::qd(0.2, 0.0), 0.0, 1.0), std::invalid_argument,
                          "the initial state is not finite: q0 of phi of body 'rod' = nan");
  VecX qd0 = Rod::qd(0.2, 0.0);
  qd0(0) = std::numeric_limits<double>::infinity();
  CHECK_THROWS_MENTIONING(simulate(rod.model, Rod::q(0.2), qd0, 0.0, 1.0), std::invalid_argument,
                          "qd0 of x of body 'rod' = inf");
}

TEST_CASE("simulate: every option is checked on entry, and small numbers read as such", "[integration]") {
  const Rod rod;
  const VecX q0 = Rod::q(0.2), qd0 = Rod::qd(0.2, 0.0);
  SimulationOptions o;
  o.stabilisation = Stabilisation::projection;
  o.projection.tolerance = -1e-10;
  CHECK_THROWS_MENTIONING(simulate(rod.model, q0, qd0, 0.0, 1.0, o), std::invalid_argument,
                          "projection.tolerance must be positive, got -1e-10");
  o.projection.tolerance = 1e-10;
  o.projection.max_iterations = 0;
  CHECK_THROWS_MENTIONING(simulate(rod.model, q0, qd0, 0.0, 1.0, o), std::invalid_argument,
                          "projection.max_iterations must be at least 1");
  o = SimulationOptions{};
  o.output_interval = -0.1;
  CHECK_THROWS_MENTIONING(simulate(rod.model, q0, qd0, 0.0, 1.0, o), std::invalid_argument, "output_interval");
  o = SimulationOptions{};
  o.drift_limit = 0.0;
  CHECK_THROWS_MENTIONING(simulate(rod.model, q0, qd0, 0.0, 1.0, o), std::invalid_argument, "drift_limit");
  o = SimulationOptions{};
  o.integrator = Integrator::dormand_prince;
  o.min_step = 0.1;
  o.max_step = 0.01;
  CHECK_THROWS_MENTIONING(simulate(rod.model, q0, qd0, 0.0, 1.0, o), std::invalid_argument,
                          "min_step = 0.1 s exceeds max_step = 0.01 s");
  o = SimulationOptions{};
  o.step = -1e-12;
  CHECK_THROWS_MENTIONING(simulate(rod.model, q0, qd0, 0.0, 1.0, o), std::invalid_argument, "got -1e-12");
  CHECK_THROWS_MENTIONING(simulate(rod.model, q0, qd0, 0.0, std::numeric_limits<double>::infinity()),
                          std::invalid_argument, "t0 and t_end must be finite");
}

TEST_CASE("simulate: a constraint drift beyond drift_limit is an error, not a quiet monitor", "[integration]") {
  // RK4 with 0.5 s steps on a 1 m pendulum: the hinge comes apart within a few steps.
  const Rod rod;
  SimulationOptions o;
  o.step = 0.5;
  bool thrown = false;
  try {
    simulate(rod.model, Rod::q(-0.5), Rod::qd(-0.5, 0.0), 0.0, 50.0, o);
  } catch (const DriftError& e) {
    thrown = true;
    const std::string what = e.what();
    CAPTURE(what);
    CHECK(what.find("revolute joint 'pivot'") != std::string::npos);
    CHECK(what.find("drift_limit 0.01") != std::string::npos);
    CHECK(e.step > 0);
    CHECK(e.t == Approx(0.5 * e.step));
  }
  CHECK(thrown);
  // With drift_limit = infinity the run records the drift instead.
  o.drift_limit = std::numeric_limits<double>::infinity();
  o.output_interval = 5.0;
  const Trajectory s = simulate(rod.model, Rod::q(-0.5), Rod::qd(-0.5, 0.0), 0.0, 50.0, o);
  CHECK(s.position_drift.back() > 0.01);
  // A fine step stays within the limit: the check does not fire on a sound run.
  o = SimulationOptions{};
  o.step = 1e-3;
  CHECK_NOTHROW(simulate(rod.model, Rod::q(-0.5), Rod::qd(-0.5, 0.0), 0.0, 2.0, o));
}
