// Module 2, task T1: Newton-Raphson position analysis (visible tests).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <string>

#include "fmbd/constraints.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/newton_raphson.hpp"
#include "grading.hpp"
#include "kinematic_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m02;

namespace {

const char* const kResidualsHint =
    "result.residuals holds |C| before each step and at the end: iterations + 1 entries, the last one "
    "<= tolerance";

}  // namespace

GRADED_TEST("newton_raphson slider-crank from a perturbed guess matches the closed form",
            "[M02][T1][points=1]") {
  const auto p = slider_crank_parameters(0.1, 0.3, 0.0, 2.0);
  const Model model = examples::slider_crank(p);
  Random rnd(201);
  for (double t : {0.35, 1.2, 2.6}) {
    const double A = p.A0 + p.omega * t;
    const VecX exact = slider_crank_exact(p, A);
    VecX guess = exact;
    guess += rnd.vector(9, -0.03, 0.03);
    const auto result = newton_or_fail(model, guess, t);
    if (!result) continue;
    const VecX& q = result->q;
    CAPTURE(t, A);
    // C = 0, evaluated independently of the solver.
    CHECK_CLOSE_NAMED("C at your q", constraints(model, q, t), VecX::Zero(9), (Tolerance{1e-9, 0}),
                      with_formula("your q does not satisfy C(q, t) = 0: iterate Newton steps until |C| <= "
                                   "tolerance", "C_q dq = -C, then q += dq"));
    CHECK_CLOSE_NAMED("your q", q, align_angles(exact, q), (Tolerance{1e-8, 1e-8}),
                      with_formula("your q is not the assembled slider-crank: add the step, do not subtract it",
                                   "C_q dq = -C, then q += dq"));
    // Slider position x = r cos A + sqrt(l^2 - r^2 sin^2 A) and the crank pin B = r (cos A, sin A).
    CHECK_NEAR_NAMED("the slider's x in your q", q(6), examples::slider_crank_closed_form(p.r, p.l, A).x,
                     (Tolerance{1e-8, 1e-8}), "slider x must equal r cos A + sqrt(l^2 - r^2 sin^2 A)");
    const Vec2 B(p.r * std::cos(A), p.r * std::sin(A));
    CHECK_CLOSE_NAMED("the crank's end B at your q", body_point(q, 0, Vec2(p.r / 2, 0)), B, (Tolerance{1e-8, 0}),
                      "the crank pin B must sit at r (cos A, sin A)");
    CHECK_CLOSE_NAMED("the rod's end B at your q", body_point(q, 1, Vec2(-p.l / 2, 0)), B, (Tolerance{1e-8, 0}),
                      "the rod end B must meet the crank pin at r (cos A, sin A)");
    // Residual history.
    INFO("hint: " << kResidualsHint);
    CHECK(result->iterations >= 1);
    CHECK(result->residuals.size() == static_cast<std::size_t>(result->iterations) + 1);
    if (!result->residuals.empty()) {
      CHECK(result->residuals.front() == Approx(constraints(model, guess, t).norm()).epsilon(1e-9));
      CHECK(result->residuals.back() <= NewtonOptions{}.tolerance);
      CHECK(result->residuals.back() == Approx(constraints(model, q, t).norm()).margin(1e-14));
    }
  }
}

GRADED_TEST("newton_raphson exact guess returns it with zero iterations", "[M02][T1][points=1]") {
  const auto p = slider_crank_parameters(0.1, 0.3, 0.4, 2.0);
  const Model model = examples::slider_crank(p);
  const double t = 0.7;
  const VecX exact = slider_crank_exact(p, p.A0 + p.omega * t);
  const auto result = newton_or_fail(model, exact, t);
  if (!result) return;
  {
    INFO("hint: check |C| <= tolerance before taking a step: an exact guess needs 0 iterations; " << kResidualsHint);
    CHECK(result->iterations == 0);
    CHECK(result->residuals.size() == 1);
  }
  CHECK_CLOSE_NAMED("your q", result->q, exact, (Tolerance{1e-12, 0}), "an exact guess must be returned unchanged");
  // Wrong size: std::invalid_argument.
  INFO("hint: check q_guess.size() == model.num_coordinates() first (Model::check_size)");
  CHECK_THROWS_AS(newton_raphson(model, VecX::Zero(8), t), std::invalid_argument);
}

GRADED_TEST("newton_raphson converges quadratically near the solution", "[M02][T1][points=1]") {
  const auto p = slider_crank_parameters(0.1, 0.3, 0.3, 2.0);
  const Model model = examples::slider_crank(p);
  Random rnd(202);
  const double t = 0.4;
  const VecX exact = slider_crank_exact(p, p.A0 + p.omega * t);
  VecX guess = exact + rnd.vector(9, -0.05, 0.05);
  NewtonOptions options;
  options.tolerance = 1e-13;
  const auto result = newton_or_fail(model, guess, t, options);
  if (!result) return;
  const std::vector<double>& r = result->residuals;
  std::ostringstream history;
  for (double x : r) history << x << ' ';
  INFO("residual history: " << history.str());
  INFO("hint: " << with_formula("your Newton-Raphson converges quadratically (r_{k+1} <= c r_k^2) only with C_q "
                                "re-evaluated at every iterate and the full step from the Jacobian solve; a frozen "
                                "Jacobian, a damped step or a step without the solve converges linearly",
                                "C_q dq = -C"));
  CHECK(result->iterations <= 6);
  int asymptotic_steps = 0;
  for (std::size_t k = 0; k + 1 < r.size(); ++k) {
    if (r[k] > 1e-2 || r[k + 1] < 1e-14) continue;  // asymptotic phase, above round-off
    ++asymptotic_steps;
    CAPTURE(k, r[k], r[k + 1]);
    CHECK(r[k + 1] <= 30.0 * r[k] * r[k]);
  }
  CHECK(asymptotic_steps >= 1);
}

GRADED_TEST("newton_raphson out of iterations throws ConvergenceError with count and residual",
            "[M02][T1][points=1]") {
  const auto p = slider_crank_parameters(0.1, 0.3, 0.0, 2.0);
  const Model model = examples::slider_crank(p);
  const double t = 0.5;
  const VecX exact = slider_crank_exact(p, p.omega * t);
  VecX guess = exact;
  guess.segment<2>(0) += Vec2(0.2, -0.15);
  guess(5) += 0.6;
  guess(6) -= 0.25;
  for (int max_iterations : {1, 2}) {
    NewtonOptions options;
    options.max_iterations = max_iterations;
    bool thrown = false;
    CAPTURE(max_iterations);
    INFO("hint: after options.max_iterations steps without |C| <= tolerance call "
         "throw_not_converged(model, q, t, result) with the residual history recorded so far");
    try {
      newton_raphson(model, guess, t, options);
    } catch (const ConvergenceError& e) {
      thrown = true;
      const std::string message = e.what();
      CAPTURE(message);
      CHECK(e.iterations == max_iterations);
      CHECK(std::isfinite(e.residual));
      CHECK(e.residual > options.tolerance);
      CHECK(message.find("after " + std::to_string(max_iterations) + " iteration") != std::string::npos);
      std::ostringstream residual;
      residual << e.residual;
      CHECK(message.find(residual.str()) != std::string::npos);
    }
    CHECK(thrown);
  }
}

GRADED_TEST("newton_raphson redundant driver throws SingularJacobianError naming the rows",
            "[M02][T1][points=1]") {
  const auto p = slider_crank_parameters(0.1, 0.3, 0.2, 1.5);
  Model model = examples::slider_crank(p);
  // The slider x is already fixed by the crank angle: a consistent but redundant driver.
  const double r = p.r, l = p.l, A0 = p.A0, omega = p.omega;
  model.add_point_coordinate_driver(
      "slider x", model.find_point("slider C"), Axis::x,
      DriveFunction::custom(
          [=](double t) {
            const auto x = examples::slider_crank_closed_form(r, l, A0 + omega * t);
            return DriveValue{x.x, x.dx_dA * omega, x.d2x_dA2 * omega * omega};
          },
          "closed-form slider x"));
  const double t = 0.3;
  VecX guess = slider_crank_exact(p, A0 + omega * t);
  guess(1) += 0.01;
  guess(6) += 0.02;
  bool thrown = false;
  INFO("hint: compute the step with solve_min_norm(model, Cq, -C, ...): it detects the redundant rows and "
       "throws SingularJacobianError; do not catch it, and do not invert C_q yourself");
  try {
    newton_raphson(model, guess, t);
  } catch (const SingularJacobianError& e) {
    thrown = true;
    const std::string message = e.what();
    CAPTURE(message);
    auto has_row = [&](int row) { return std::find(e.rows.begin(), e.rows.end(), row) != e.rows.end(); };
    CHECK(has_row(8));  // crank angle driver
    CHECK(has_row(9));  // slider x driver
    CHECK(message.find("crank angle") != std::string::npos);
    CHECK(message.find("slider x") != std::string::npos);
  }
  CHECK(thrown);
}

GRADED_TEST("solve_positions four-bar that cannot close throws UnreachableConfigurationError",
            "[M02][T1][points=1]") {
  // Ground link 1.0 is longer than crank + coupler + rocker = 0.6: the loop cannot close.
  const auto p = four_bar_parameters(0.1, 0.3, 0.2, 1.0, 0.5, 1.0);
  const Model model = examples::four_bar(p);
  bool thrown = false;
  INFO("hint: newton_raphson must throw a KinematicsError (ConvergenceError via throw_not_converged, or "
       "SingularJacobianError from solve_min_norm) when it cannot reach |C| <= tolerance, never loop forever "
       "or return an unconverged q; solve_positions then reports the unreachable configuration");
  try {
    solve_positions(model, model.initial_guess(), 0.0);
  } catch (const UnreachableConfigurationError& e) {
    thrown = true;
    std::string message = e.what();
    CAPTURE(message);
    for (char& c : message) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    CHECK((message.find("cannot close") != std::string::npos || message.find("unreachable") != std::string::npos));
    CHECK(e.residual > 1e-3);
  }
  CHECK(thrown);
}
