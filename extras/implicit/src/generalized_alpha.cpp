#include "fmbd/generalized_alpha.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "fmbd/applied_forces.hpp"
#include "fmbd/constraints.hpp"
#include "fmbd/energy.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/integrators.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/mass_matrix.hpp"

namespace fmbd {

GeneralizedAlphaCoefficients GeneralizedAlphaCoefficients::from_rho_inf(double rho_inf) {
  if (!(rho_inf >= 0.0 && rho_inf <= 1.0))
    throw std::invalid_argument("generalized_alpha: rho_inf must lie in [0, 1], got " + readable(rho_inf));
  GeneralizedAlphaCoefficients c;
  c.alpha_m = (2 * rho_inf - 1) / (rho_inf + 1);
  c.alpha_f = rho_inf / (rho_inf + 1);
  c.gamma = 0.5 + c.alpha_f - c.alpha_m;
  c.beta = 0.25 * (c.gamma + 0.5) * (c.gamma + 0.5);
  return c;
}

namespace {

std::string at(double t, int step) {
  return "at t = " + readable(t) + " s (step " + std::to_string(step) + ")";
}

std::string unstable(double t, int step) {
  return at(t, step) + ": the model is unstable or the step too large";
}

void check_arguments(const Model& model, const VecX& q0, const VecX& qd0, double t0, double t_end, double step,
                     const GeneralizedAlphaOptions& o, double output_interval) {
  auto positive = [](double x, const char* name) {
    if (!(x > 0) || !std::isfinite(x))
      throw std::invalid_argument(std::string("generalized_alpha: ") + name + " must be positive, got " + readable(x));
  };
  if (!std::isfinite(t0) || !std::isfinite(t_end) || !(t_end > t0))
    throw std::invalid_argument("generalized_alpha: t_end must be after t0");
  positive(step, "step");
  positive(o.rtol, "rtol");
  positive(o.atol, "atol");
  if (o.max_iterations < 1)
    throw std::invalid_argument("generalized_alpha: max_iterations must be at least 1, got " +
                                std::to_string(o.max_iterations));
  GeneralizedAlphaCoefficients::from_rho_inf(o.rho_inf);  // range check
  if (!(output_interval >= 0) || !std::isfinite(output_interval))
    throw std::invalid_argument("generalized_alpha: output_interval must be zero (every step) or positive");

  check_initial_state(model, q0, qd0, t0, "generalized_alpha");
}

// Runs `evaluate` and gives its errors the time and the step: a singular matrix keeps its type
// and rows, NaN or Inf becomes an IntegrationError.
template <typename F>
auto guarded(double t, int step, F&& evaluate) {
  try {
    return evaluate();
  } catch (const SingularJacobianError& e) {
    throw SingularJacobianError(std::string(e.what()) + " (" + at(t, step) + ")", e.rows);
  } catch (const ConvergenceError&) {
    throw;
  } catch (const KinematicsError& e) {
    throw IntegrationError(std::string(e.what()) + " " + unstable(t, step),
                           t, step);
  }
}

// The variables the method carries from step to step.
struct MethodState {
  VecX q, v, qdd, a, lambda;
};

// The residuals of a step at one iterate: r = M q_ddot + C_q^T lambda - Q_a and C, with C_q.
struct Residual {
  VecX r, C;
  MatX Cq;
};

class GeneralizedAlpha {
 public:
  GeneralizedAlpha(const Model& model, const GeneralizedAlphaOptions& options)
      : model_(model), options_(options), c_(GeneralizedAlphaCoefficients::from_rho_inf(options.rho_inf)),
        n_(model.num_coordinates()) {}

  // Advances s from t by h; `step` is the number of steps done (for messages).
  void advance(MethodState& s, double t, double h, int step) const {
    const double am = c_.alpha_m, af = c_.alpha_f, beta = c_.beta, gamma = c_.gamma;
    const double t1 = t + h, bh2 = beta * h * h;
    const double gamma_p = gamma / (beta * h), beta_p = (1 - am) / ((1 - af) * bh2);

    // Predictor: the last acceleration and multipliers.
    VecX qdd = s.qdd;
    VecX a = ((1 - af) * qdd + af * s.qdd - am * s.a) / (1 - am);
    VecX v = s.v + h * ((1 - gamma) * s.a + gamma * a);
    VecX q = s.q + h * s.v + h * h * ((0.5 - beta) * s.a + beta * a);
    VecX lambda = s.lambda;

    MatX S;
    double residual_norm = std::numeric_limits<double>::quiet_NaN(), correction = residual_norm;
    for (int iteration = 1; iteration <= options_.max_iterations; ++iteration) {
      const Residual R = residual(q, v, qdd, lambda, t1, t, step);
      residual_norm = std::sqrt((bh2 * R.r).squaredNorm() + R.C.squaredNorm());
      if (iteration == 1 || options_.jacobian_update == JacobianUpdate::every_iteration)
        S = tangent(q, v, qdd, lambda, t1, R.r, gamma_p, beta_p, t, step);
      const Accelerations d = solve(bh2 * S, R.Cq, -bh2 * R.r, -R.C, t, step);
      const VecX q_old = q;
      q += d.qdd;  // the position correction dq
      v += gamma_p * d.qdd;
      qdd += beta_p * d.qdd;
      lambda += d.lambda / bh2;
      check_finite(q, v, qdd, lambda, t, step);
      correction = error_norm(d.qdd, q_old, q, options_.rtol, options_.atol);
      if (correction <= 1.0) {
        s.a = ((1 - af) * qdd + af * s.qdd - am * s.a) / (1 - am);
        s.q = q;
        s.v = v;
        s.qdd = qdd;
        s.lambda = lambda;
        if (options_.project_velocities) s.v = guarded(t, step, [&] { return project_velocities(model_, q, v, t1); });
        return;
      }
    }
    std::ostringstream msg;
    msg << "generalized_alpha: the Newton iteration did not converge in " << options_.max_iterations
        << (options_.max_iterations == 1 ? " iteration " : " iterations ") << at(t, step) << ", advancing to t = "
        << t1 << " s: residual norm |(beta h^2 r, C)| = " << residual_norm << " before the last correction, which was "
        << correction << " times the tolerance; use a smaller step, more iterations or looser rtol/atol";
    throw NewtonIterationError(msg.str(), t, step, options_.max_iterations, residual_norm);
  }

 private:
  VecX force_residual(const VecX& q, const VecX& v, const VecX& qdd, const VecX& lambda, double t1,
                      const MatX& Cq) const {
    return mass_matrix(model_, q) * qdd + Cq.transpose() * lambda - applied_forces(model_, q, v, t1);
  }

  Residual residual(const VecX& q, const VecX& v, const VecX& qdd, const VecX& lambda, double t1, double t,
                    int step) const {
    Residual R;
    guarded(t, step, [&] {
      ConstraintEvaluation e = evaluate_constraints(model_, q, t1);
      R.r = force_residual(q, v, qdd, lambda, t1, e.Cq);
      R.C = std::move(e.C);
      R.Cq = std::move(e.Cq);
      return 0;
    });
    for (Eigen::Index k = 0; k < R.r.size(); ++k)
      if (!std::isfinite(R.r(k)))
        throw IntegrationError("generalized_alpha: the residual of the equation of motion of " +
                                   model_.describe_coordinate(static_cast<int>(k)) + " became NaN or Inf " +
                                   unstable(t, step),
                               t, step);
    for (Eigen::Index k = 0; k < R.C.size(); ++k)
      if (!std::isfinite(R.C(k)) || !R.Cq.row(k).allFinite())
        throw IntegrationError("generalized_alpha: " + model_.describe_row(static_cast<int>(k)) +
                                   " became NaN or Inf " + unstable(t, step),
                               t, step);
    return R;
  }

  // dr/dq_{n+1} by forward differences, moving q_dot and q_ddot with q as the method does.
  MatX tangent(VecX q, VecX v, VecX qdd, const VecX& lambda, double t1, const VecX& r0, double gamma_p, double beta_p,
               double t, int step) const {
    const double root_eps = std::sqrt(std::numeric_limits<double>::epsilon());
    MatX S(n_, n_);
    guarded(t, step, [&] {
      for (int j = 0; j < n_; ++j) {
        const double qj = q(j), vj = v(j), qddj = qdd(j);
        const double eps = root_eps * std::max(1.0, std::abs(qj));
        q(j) = qj + eps;
        v(j) = vj + gamma_p * eps;
        qdd(j) = qddj + beta_p * eps;
        const MatX Cq = constraint_jacobian(model_, q, t1);
        S.col(j) = (force_residual(q, v, qdd, lambda, t1, Cq) - r0) / eps;
        q(j) = qj;
        v(j) = vj;
        qdd(j) = qddj;
      }
      return 0;
    });
    return S;
  }

  // The scaled Newton system; Accelerations carries (dq, mu). Singular although C_q has full rank,
  // beta h^2 S_t is singular on the admissible motions (the null space of C_q): the step is too
  // large for the stiffness or the iterates have diverged, so this is an IntegrationError.
  Accelerations solve(const MatX& A, const MatX& Cq, const VecX& top, const VecX& bottom, double t, int step) const {
    try {
      return guarded(t, step, [&] { return solve_augmented(model_, A, Cq, top, bottom, "generalized_alpha"); });
    } catch (const SingularJacobianError& e) {
      if (!e.rows.empty()) throw;
      throw IntegrationError("generalized_alpha: the iteration matrix [beta h^2 S_t C_q^T; C_q 0] is singular " +
                                 at(t, step) + " although C_q has full rank: the step is too large for the stiffness " +
                                 "of the model, or the Newton iteration diverged",
                             t, step);
    }
  }

  void check_finite(const VecX& q, const VecX& v, const VecX& qdd, const VecX& lambda, double t, int step) const {
    for (const auto& [x, what] : {std::pair<const VecX*, const char*>{&q, ""}, {&v, "the rate of "},
                                  {&qdd, "the acceleration of "}}) {
      for (Eigen::Index k = 0; k < x->size(); ++k)
        if (!std::isfinite((*x)(k)))
          throw IntegrationError("generalized_alpha: the state became NaN or Inf " + at(t, step) + " in " + what +
                                     model_.describe_coordinate(static_cast<int>(k)) +
                                     ": the model is unstable or the step too large",
                                 t, step);
    }
    for (Eigen::Index k = 0; k < lambda.size(); ++k)
      if (!std::isfinite(lambda(k)))
        throw IntegrationError("generalized_alpha: the multiplier of " + model_.describe_row(static_cast<int>(k)) +
                                   " became NaN or Inf " + unstable(t, step),
                               t, step);
  }

  const Model& model_;
  GeneralizedAlphaOptions options_;
  GeneralizedAlphaCoefficients c_;
  int n_;
};

}  // namespace

Trajectory generalized_alpha(const Model& model, const VecX& q0, const VecX& qd0, double t0, double t_end,
                             double step, const GeneralizedAlphaOptions& options, double output_interval) {
  check_arguments(model, q0, qd0, t0, t_end, step, options, output_interval);
  const GeneralizedAlpha method(model, options);

  int steps = 0;
  double t = t0;
  MethodState s;
  s.q = q0;
  s.v = qd0;
  const Accelerations start = guarded(t0, 0, [&] { return forward_dynamics(model, q0, qd0, t0); });
  s.qdd = start.qdd;
  s.a = start.qdd;
  s.lambda = start.lambda;

  // Power of the drivers (lambda^T C_t) and of the non-conservative forces, integrated by the
  // trapezoidal rule (second order, as the method); 0 without the work monitor.
  auto power = [&] {
    if (!options.integrate_work) return 0.0;
    return driver_power(model, s.q, s.lambda, t) + nonconservative_power(model, s.q, s.v, t);
  };
  // C = 0 is imposed at every step: no drift limit.
  Recorder recorder(model, t0, t_end, output_interval, std::numeric_limits<double>::infinity(),
                    length_scale(model, q0), "generalized_alpha", options.integrate_work);
  double work = 0.0, P = power();
  recorder.start(Sample{s.q, s.v, work, s.lambda});

  // Steps at t0 + j step, the last one ending at t_end; the time is never accumulated.
  const long total = std::max(1L, static_cast<long>(std::ceil((t_end - t0) / step * (1 - 1e-10))));
  while (steps < total) {
    const double t_new = steps + 1 == total ? t_end : t0 + static_cast<double>(steps + 1) * step, h = t_new - t;
    const MethodState old = s;
    const double work_old = work;
    method.advance(s, t, h, steps);
    ++steps;
    ++recorder.trajectory().steps;
    t = t_new;
    const double P_new = power();
    work += 0.5 * (P + P_new) * h;
    P = P_new;
    // Between the steps: cubic Hermite in (q, q_dot) with slopes (q_dot, q_ddot); linear work
    // and multipliers (the method's own lambda: always recorded).
    recorder.after_step(t_new - h, t_new, h, steps, [&](double t_out) {
      if (t_out == t_new) return Sample{s.q, s.v, work, s.lambda};
      const double theta = (t_out - (t_new - h)) / h;
      return Sample{hermite(old.q, old.v, s.q, s.v, h, theta), hermite(old.v, old.qdd, s.v, s.qdd, h, theta),
                    work_old + theta * (work - work_old), old.lambda + theta * (s.lambda - old.lambda)};
    });
  }
  return std::move(recorder.trajectory());
}

}  // namespace fmbd
