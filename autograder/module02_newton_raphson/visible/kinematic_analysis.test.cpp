// Module 2, task T6: kinematic analysis over a time grid (visible tests).
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "fmbd/examples.hpp"
#include "fmbd/kinematic_analysis.hpp"
#include "grading.hpp"
#include "kinematic_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m02;

namespace {

std::vector<double> grid(double t0, double t1, int steps) {
  std::vector<double> t(steps + 1);
  for (int k = 0; k <= steps; ++k) t[k] = t0 + (t1 - t0) * k / steps;
  return t;
}

// Sizes of every list of the solution; false (with a failed check) if any is off.
bool check_sizes(const KinematicSolution& s, const std::vector<double>& times, int n) {
  INFO("hint: kinematic_analysis appends one entry per time to t, q, qd, qdd and iterations, each of size n");
  const std::size_t m = times.size();
  bool ok = s.t.size() == m && s.q.size() == m && s.qd.size() == m && s.qdd.size() == m && s.iterations.size() == m;
  CHECK(ok);
  for (std::size_t k = 0; ok && k < m; ++k)
    ok = s.q[k].size() == n && s.qd[k].size() == n && s.qdd[k].size() == n;
  CHECK(ok);
  if (ok) CHECK(s.t == times);
  return ok;
}

}  // namespace

GRADED_TEST("kinematic_analysis slider-crank over a full crank turn matches the closed form", "[M02][T6][points=1]") {
  const auto p = slider_crank_parameters(0.1, 0.3, 0.0, 2.0);
  const Model model = examples::slider_crank(p);
  const std::vector<double> times = grid(0.0, 2 * kPi / p.omega, 48);
  auto exact = [&](double s) { return slider_crank_exact(p, p.A0 + p.omega * s); };
  VecX guess = exact(0.0);
  guess(6) += 0.01;
  guess(4) -= 0.005;
  const KinematicSolution s = kinematic_analysis(model, guess, times);
  if (!check_sizes(s, times, 9)) return;
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double t = times[k], A = p.A0 + p.omega * t;
    const auto x = examples::slider_crank_closed_form(p.r, p.l, A);
    CAPTURE(k, t);
    CHECK_CLOSE(s.q[k], align_angles(exact(t), s.q[k]), (Tolerance{1e-8, 1e-8}),
                "positions at each time must solve C(q, t_k) = 0: solve_positions(model, guess, t_k, options)");
    CHECK_NEAR(s.q[k](6), x.x, (Tolerance{1e-8, 1e-8}), "slider x(A) at each time");
    CHECK_CLOSE(s.qd[k], path_rate(exact, t), (Tolerance{1e-7, 1e-7}),
                "velocities at each time: solve_velocities(model, q_k, t_k) at the new positions and time");
    CHECK_NEAR(s.qd[k](6), x.dx_dA * p.omega, (Tolerance{1e-9, 1e-8}), "slider speed x'(A) omega at each time");
    CHECK_CLOSE(s.qdd[k], path_acceleration(exact, t), (Tolerance{1e-5, 1e-5}),
                "accelerations at each time: solve_accelerations(model, q_k, qd_k, t_k) with the new q_k and qd_k");
    CHECK_NEAR(s.qdd[k](6), x.d2x_dA2 * p.omega * p.omega, (Tolerance{1e-8, 1e-7}),
               "slider acceleration x''(A) omega^2 at each time");
  }
}

GRADED_TEST("kinematic_analysis four-bar through a full crank turn keeps the loop closed", "[M02][T6][points=1]") {
  const auto p = four_bar_parameters(0.1, 0.3, 0.25, 0.3, 0.5, 1.5);
  const Model model = examples::four_bar(p);
  const std::vector<double> times = grid(0.0, 2 * kPi / p.omega, 60);
  auto exact = [&](double s) { return four_bar_configuration(p, p.theta0 + p.omega * s); };
  const KinematicSolution s = kinematic_analysis(model, model.initial_guess(), times);
  if (!check_sizes(s, times, 9)) return;
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double t = times[k], theta = p.theta0 + p.omega * t;
    const VecX& q = s.q[k];
    CAPTURE(k, t);
    const char* hint = "positions at each time must solve C(q, t_k) = 0 (solve_positions from the guess)";
    // Joints coincide, O2 and O4 stay on the ground: loop closure from the link geometry.
    CHECK_CLOSE_NAMED("the four-bar's loop closure at your q", four_bar_closure(p, q), VecX::Zero(8),
                      (Tolerance{1e-9, 0}), hint);
    CHECK_NEAR_NAMED("your crank angle minus the driven angle", std::remainder(q(2) - theta, 2 * kPi), 0.0,
                     (Tolerance{1e-9, 0}), "the crank angle follows the driver");
    // Link lengths between the joint positions, computed from the coordinates.
    const Vec2 B = body_point(q, 0, Vec2(p.a / 2, 0)), C = body_point(q, 2, Vec2(-p.c / 2, 0));
    CHECK_NEAR_NAMED("the coupler's length |B - C| at your q", (B - C).norm(), p.b, (Tolerance{1e-9, 0}), hint);
    CHECK_NEAR_NAMED("the crank's length |B| at your q", B.norm(), p.a, (Tolerance{1e-9, 0}), hint);
    CHECK_NEAR_NAMED("the rocker's length |C - D| at your q", (C - Vec2(p.d, 0)).norm(), p.c, (Tolerance{1e-9, 0}),
                     hint);
    // Same assembly branch as the closed form, and its rates.
    CHECK_CLOSE_NAMED("your q", q, align_angles(exact(t), q), (Tolerance{1e-8, 1e-8}), hint);
    CHECK_CLOSE(s.qd[k], path_rate(exact, t), (Tolerance{1e-7, 1e-7}),
                "velocities at each time: solve_velocities(model, q_k, t_k)");
    CHECK_CLOSE(s.qdd[k], path_acceleration(exact, t), (Tolerance{1e-5, 1e-5}),
                "accelerations at each time: solve_accelerations(model, q_k, qd_k, t_k)");
  }
}

GRADED_TEST("kinematic_analysis starts each step from the previous solution", "[M02][T6][points=1]") {
  const auto p = slider_crank_parameters(0.1, 0.3, 0.3, 2.0);
  const Model model = examples::slider_crank(p);
  const std::vector<double> times = grid(0.5, 0.5 + 2 * kPi / p.omega, 72);
  VecX guess = slider_crank_exact(p, p.A0 + p.omega * 0.5);
  guess(6) += 0.05;
  const KinematicSolution s = kinematic_analysis(model, guess, times);
  if (!check_sizes(s, times, 9)) return;
  std::ostringstream counts;
  for (int i : s.iterations) counts << i << ' ';
  INFO("iterations: " << counts.str());
  INFO("hint: after the first time, start Newton from the solution of the previous time step, extrapolated "
       "q + qd dt + 1/2 qdd dt^2; then one to three iterations suffice. Record the iteration count of each step");
  CHECK(s.iterations.front() >= 1);
  for (std::size_t k = 1; k < s.iterations.size(); ++k) {
    CAPTURE(k);
    CHECK(s.iterations[k] >= 1);
    CHECK(s.iterations[k] <= 3);
  }
}

GRADED_TEST("kinematic_analysis rejects times that do not increase", "[M02][T6][points=1]") {
  const auto p = slider_crank_parameters(0.1, 0.3, 0.0, 2.0);
  const Model model = examples::slider_crank(p);
  const VecX guess = slider_crank_exact(p, p.A0);
  const std::string hint =
      "times must increase strictly: throw std::invalid_argument naming the index of the offending time";
  check_throws_mentioning<std::invalid_argument>(
      [&] { kinematic_analysis(model, guess, {0.0, 0.1, 0.2, 0.15, 0.3}); }, "3", hint);
  check_throws_mentioning<std::invalid_argument>([&] { kinematic_analysis(model, guess, {0.0, 0.1, 0.1}); }, "2",
                                                 hint);
  // A single time is fine.
  const KinematicSolution s = kinematic_analysis(model, guess, {0.4});
  CHECK(s.q.size() == 1);
}
