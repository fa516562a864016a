// Module 2, task T6: kinematic analysis of other mechanisms and drives (hidden tests).
#include <cmath>
#include <vector>

#include "fmbd/examples.hpp"
#include "fmbd/kinematic_analysis.hpp"
#include "grading.hpp"
#include "kinematic_checks.hpp"
#include "kinematic_hidden_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m02;

namespace {

std::vector<double> grid(double t0, double t1, int steps) {
  std::vector<double> t(steps + 1);
  for (int k = 0; k <= steps; ++k) t[k] = t0 + (t1 - t0) * k / steps;
  return t;
}

void check_against(const KinematicSolution& s, const std::vector<double>& times,
                   const std::function<VecX(double)>& exact) {
  {
    INFO("hint: one entry per time in t, q, qd, qdd and iterations");
    REQUIRE(s.q.size() == times.size());
    REQUIRE(s.qd.size() == times.size());
    REQUIRE(s.qdd.size() == times.size());
    REQUIRE(s.iterations.size() == times.size());
  }
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double t = times[k];
    CAPTURE(k, t);
    CHECK_CLOSE(s.q[k], align_angles(exact(t), s.q[k]), (Tolerance{1e-8, 1e-8}),
                "positions at each time: solve_positions(model, guess, t_k, options)");
    CHECK_CLOSE(s.qd[k], path_rate(exact, t), (Tolerance{1e-7, 1e-7}),
                "velocities at each time: solve_velocities(model, q_k, t_k)");
    CHECK_CLOSE(s.qdd[k], path_acceleration(exact, t), (Tolerance{1e-5, 1e-5}),
                "accelerations at each time: solve_accelerations(model, q_k, qd_k, t_k)");
    if (k > 0) {
      INFO("hint: start each step from the previous solution, extrapolated q + qd dt + 1/2 qdd dt^2");
      CHECK(s.iterations[k] <= 3);
    }
  }
}

}  // namespace

GRADED_TEST("kinematic_analysis arm and collar over several drive periods", "[M02][T6][points=1]") {
  const ArmCollar ac = arm_collar(0.2, DriveFunction::harmonic(0.2, 0.1, 1.5, 0.4),
                                  DriveFunction::harmonic(0.25, 0.08, 2.0, 0.3));
  const std::vector<double> times = grid(0.0, 6.0, 90);
  VecX guess = ac.exact(0.0);
  guess(3) += 0.02;
  guess(1) -= 0.01;
  const KinematicSolution s = kinematic_analysis(ac.model, guess, times);
  check_against(s, times, [&](double t) { return ac.exact(t); });
}

GRADED_TEST("kinematic_analysis slider-crank with a smooth_step crank drive", "[M02][T6][points=1]") {
  auto p = slider_crank_parameters(0.2, 0.5, 0.4, 0.0);
  p.driven = false;
  Model model = examples::slider_crank(p);
  const DriveFunction drive = DriveFunction::smooth_step(0.4, 0.4 + 2 * kPi, 0.15, 1.85);
  model.add_absolute_angle_driver("crank angle", model.find_body("crank"), drive);
  const std::vector<double> times = grid(0.0, 2.0, 100);
  const KinematicSolution s = kinematic_analysis(model, model.initial_guess(), times);
  check_against(s, times, [&](double t) { return slider_crank_exact(p, drive(t).f); });
}
