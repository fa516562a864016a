// Module 2, tasks T2 and T5: velocity and acceleration equations (visible tests).
// Positions and velocities come from closed forms, so these tests do not depend on T1.
#include <cmath>
#include <stdexcept>
#include <string>

#include "fmbd/constraints.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/kinematic_analysis.hpp"
#include "grading.hpp"
#include "kinematic_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m02;

// ---- T2: velocities ---------------------------------------------------------------------------

GRADED_TEST("solve_velocities slider-crank matches the closed-form slider speed", "[M02][T2][points=1]") {
  for (const auto& p : {slider_crank_parameters(0.1, 0.3, 0.0, 2.0), slider_crank_parameters(0.15, 0.4, 1.0, -3.0)}) {
    const Model model = examples::slider_crank(p);
    for (double t : {0.2, 0.9, 1.7, 2.8}) {
      const double A = p.A0 + p.omega * t;
      auto exact = [&](double s) { return slider_crank_exact(p, p.A0 + p.omega * s); };
      const VecX q = exact(t);
      const VecX qd = solve_velocities(model, q, t);
      const VecX expected = path_rate(exact, t);
      CAPTURE(p.r, p.l, p.omega, t);
      CHECK_CLOSE_NAMED("your q_dot", qd, expected, (Tolerance{1e-7, 1e-7}), velocity_hint(qd, expected));
      if (qd.size() == 9) {
        const auto x = examples::slider_crank_closed_form(p.r, p.l, A);
        CHECK_NEAR_NAMED("the slider's x_dot in your q_dot", qd(6), x.dx_dA * p.omega, (Tolerance{1e-10, 1e-9}),
                         "your slider's speed differs from the closed form: " + velocity_hint(qd, expected));
        CHECK_NEAR_NAMED("the crank's phi_dot in your q_dot", qd(2), p.omega, (Tolerance{1e-10, 1e-9}),
                         "your crank's rate is not the driver's omega: " + velocity_hint(qd, expected));
      }
    }
  }
}

GRADED_TEST("solve_velocities four-bar matches finite differences of positions", "[M02][T2][points=1]") {
  const auto p = four_bar_parameters(0.1, 0.3, 0.25, 0.3, 0.5, 1.3);
  const Model model = examples::four_bar(p);
  for (double t : {0.0, 0.8, 2.1, 3.9}) {
    auto exact = [&](double s) { return four_bar_configuration(p, p.theta0 + p.omega * s); };
    const VecX q = exact(t);
    const VecX qd = solve_velocities(model, q, t);
    const VecX expected = path_rate(exact, t);
    CAPTURE(t);
    CHECK_CLOSE_NAMED("your q_dot", qd, expected, (Tolerance{1e-7, 1e-7}), velocity_hint(qd, expected));
    // The velocity equation itself, evaluated independently: C_q q_dot + C_t = 0.
    const ConstraintEvaluation e = evaluate_constraints(model, q, t);
    if (qd.size() == 9)
      CHECK_CLOSE_NAMED("the velocity equation's residual at your q_dot", VecX(e.Cq * qd + e.Ct), VecX::Zero(9),
                        (Tolerance{1e-10, 0}), velocity_hint(qd, expected));
  }
}

GRADED_TEST("solve_velocities undriven model throws invalid_argument about degrees of freedom",
            "[M02][T2][points=1]") {
  auto p = slider_crank_parameters(0.1, 0.3, 0.5, 2.0);
  p.driven = false;
  const Model model = examples::slider_crank(p);
  const VecX q = slider_crank_exact(p, p.A0);
  check_throws_mentioning<std::invalid_argument>(
      [&] { solve_velocities(model, q, 0.0); }, "degrees of freedom",
      "solve the velocity equation with solve_square(model, Cq, v, \"velocity equation\"): it rejects a model "
      "with free degrees of freedom (m < n) with std::invalid_argument");
}

// ---- T5: accelerations ------------------------------------------------------------------------

GRADED_TEST("solve_accelerations slider-crank at constant crank speed matches the closed form", "[M02][T5][points=1]") {
  for (const auto& p : {slider_crank_parameters(0.1, 0.3, 0.0, 2.0), slider_crank_parameters(0.12, 0.25, -0.5, 2.5)}) {
    const Model model = examples::slider_crank(p);
    for (double t : {0.3, 1.1, 2.0}) {
      const double A = p.A0 + p.omega * t;
      auto exact = [&](double s) { return slider_crank_exact(p, p.A0 + p.omega * s); };
      const VecX q = exact(t), qd = path_rate(exact, t);
      const VecX qdd = solve_accelerations(model, q, qd, t);
      const VecX expected = path_acceleration(exact, t);
      CAPTURE(p.r, p.l, p.omega, t);
      CHECK_CLOSE_NAMED("your q_ddot", qdd, expected, (Tolerance{1e-5, 1e-5}),
                        acceleration_hint(model, q, qd, t, qdd, expected));
      if (qdd.size() == 9) {
        const auto x = examples::slider_crank_closed_form(p.r, p.l, A);
        CHECK_NEAR_NAMED("the slider's x_ddot in your q_ddot", qdd(6), x.d2x_dA2 * p.omega * p.omega,
                         (Tolerance{1e-8, 1e-7}),
                         "your slider's acceleration differs from the closed form: " +
                             acceleration_hint(model, q, qd, t, qdd, expected));
        CHECK_NEAR_NAMED("the crank's phi_ddot in your q_ddot", qdd(2), 0.0, (Tolerance{1e-8, 0}),
                         "your crank does not turn uniformly: " + acceleration_hint(model, q, qd, t, qdd, expected));
      }
    }
  }
}

GRADED_TEST("solve_accelerations slider-crank with a smooth_step crank drive", "[M02][T5][points=1]") {
  auto p = slider_crank_parameters(0.1, 0.3, 0.2, 0.0);
  p.driven = false;
  Model model = examples::slider_crank(p);
  const DriveFunction drive = DriveFunction::smooth_step(0.2, 2.6, 0.0, 1.5);
  model.add_absolute_angle_driver("crank angle", model.find_body("crank"), drive);
  for (double t : {0.3, 0.6, 1.05}) {
    const DriveValue A = drive(t);
    auto exact = [&](double s) { return slider_crank_exact(p, drive(s).f); };
    const VecX q = exact(t), qd = path_rate(exact, t);
    const VecX qdd = solve_accelerations(model, q, qd, t);
    const VecX expected = path_acceleration(exact, t);
    CAPTURE(t, A.f, A.fd, A.fdd);
    CHECK_CLOSE_NAMED("your q_ddot", qdd, expected, (Tolerance{1e-5, 1e-5}),
                      acceleration_hint(model, q, qd, t, qdd, expected));
    if (qdd.size() == 9) {
      const auto x = examples::slider_crank_closed_form(p.r, p.l, A.f);
      CHECK_NEAR_NAMED("the slider's x_ddot in your q_ddot", qdd(6), x.d2x_dA2 * A.fd * A.fd + x.dx_dA * A.fdd,
                       (Tolerance{1e-8, 1e-7}),
                       "your slider's acceleration differs from the closed form: " +
                           acceleration_hint(model, q, qd, t, qdd, expected));
      CHECK_NEAR_NAMED("the crank's phi_ddot in your q_ddot", qdd(2), A.fdd, (Tolerance{1e-8, 1e-7}),
                       "your crank's angular acceleration is not the driver's f'': " +
                           acceleration_hint(model, q, qd, t, qdd, expected));
    }
  }
}

GRADED_TEST("solve_accelerations four-bar matches finite differences of the closed form", "[M02][T5][points=1]") {
  const auto p = four_bar_parameters(0.1, 0.3, 0.25, 0.3, 0.5, 1.3);
  const Model model = examples::four_bar(p);
  for (double t : {0.4, 1.9, 3.3}) {
    auto exact = [&](double s) { return four_bar_configuration(p, p.theta0 + p.omega * s); };
    const VecX q = exact(t), qd = path_rate(exact, t);
    const VecX qdd = solve_accelerations(model, q, qd, t);
    const VecX expected = path_acceleration(exact, t);
    CAPTURE(t);
    CHECK_CLOSE_NAMED("your q_ddot", qdd, expected, (Tolerance{1e-5, 1e-5}),
                      acceleration_hint(model, q, qd, t, qdd, expected));
  }
}

// ---- T5: gamma of the whole model ---------------------------------------------------------------

GRADED_TEST("constraint_gamma: every constraint's gamma in its rows, at the markers' velocities", "[M02][T5][points=2]") {
  Random random(251);
  const Model every = every_constraint_model();
  VecX out = VecX::Constant(every.num_constraints(), 7.0);  // an earlier call's numbers
  for (int k = 0; k < 4; ++k) {
    const VecX q = random.vector(every.num_coordinates(), -1.2, 1.2), qd = random.vector(every.num_coordinates(), -2.0, 2.0);
    if (!check_gamma_assembly(every, q, qd, random.uniform(0.0, 3.0), out, "every joint and driver type")) break;
  }
  const auto p = slider_crank_parameters(0.1, 0.3, 0.5, 2.0);
  const Model slider = examples::slider_crank(p);
  VecX out_slider = VecX::Zero(slider.num_constraints());
  for (double t : {0.3, 1.4}) {
    auto exact = [&](double s) { return slider_crank_exact(p, p.A0 + p.omega * s); };
    if (!check_gamma_assembly(slider, exact(t), path_rate(exact, t), t, out_slider, "slider-crank on its motion")) break;
  }
}
