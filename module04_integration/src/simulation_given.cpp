#include "fmbd/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "fmbd/constraints.hpp"
#include "fmbd/energy.hpp"
#include "fmbd/integrators.hpp"
#include "fmbd/kinematic_errors.hpp"

namespace fmbd {

namespace {

std::string at(double t, int step) {
  std::ostringstream s;
  s << "at t = " << t << " s (step " << step << ")";
  return s.str();
}

void check_options(const SimulationOptions& o, double t0, double t_end) {
  auto positive = [](double x, const char* name) {
    if (!(x > 0) || !std::isfinite(x))
      throw std::invalid_argument(std::string("simulate: ") + name + " must be positive, got " + std::to_string(x));
  };
  if (!(t_end > t0)) throw std::invalid_argument("simulate: t_end must be after t0");
  positive(o.step, "step");
  if (o.integrator == Integrator::dormand_prince) {
    positive(o.rtol, "rtol");
    positive(o.atol, "atol");
    positive(o.min_step, "min_step");
    positive(o.max_step, "max_step");
  }
  if (o.stabilisation == Stabilisation::baumgarte && (o.baumgarte.alpha < 0 || o.baumgarte.beta < 0))
    throw std::invalid_argument("simulate: Baumgarte alpha and beta must not be negative");
}

void check_consistent(const Model& model, const VecX& q, const VecX& qd, double t) {
  const ConstraintEvaluation e = evaluate_constraints(model, q, t);
  const VecX C_dot = e.Cq * qd + e.Ct;
  for (const auto& [residual, name] : {std::pair<const VecX*, const char*>{&e.C, "C(q0)"}, {&C_dot, "C_q q_dot0 + C_t"}}) {
    Eigen::Index row = 0;
    if (residual->size() && residual->cwiseAbs().maxCoeff(&row) > 1e-6)
      throw std::invalid_argument("simulate: inconsistent initial conditions: " + std::string(name) + " = " +
                                  std::to_string((*residual)(row)) + " in " +
                                  model.describe_row(static_cast<int>(row)) +
                                  "; use consistent_initial_conditions() first");
  }
}

}  // namespace

Trajectory simulate(const Model& model, const VecX& q0, const VecX& qd0, double t0, double t_end,
                    const SimulationOptions& options) {
  const int n = model.num_coordinates();
  Model::check_size(q0, n, "q0", "simulate");
  Model::check_size(qd0, n, "qd0", "simulate");
  check_options(options, t0, t_end);
  check_consistent(model, q0, qd0, t0);

  const Baumgarte baumgarte = options.stabilisation == Stabilisation::baumgarte ? options.baumgarte : Baumgarte{};
  int step = 0;
  bool started = false;  // the initial state has been evaluated
  auto entry_name = [&](Eigen::Index k) {
    return k < n ? model.describe_coordinate(static_cast<int>(k))
                 : "the rate of " + model.describe_coordinate(static_cast<int>(k - n));
  };
  // "the state has blown up at t = ... (step ...): its largest entry is ..., and <what>; ...".
  auto blown_up = [&](const std::string& what, double t, const VecX& y) {
    Eigen::Index k = 0;
    if (y.size()) y.cwiseAbs().maxCoeff(&k);
    std::ostringstream s;
    s << "the state has blown up " << at(t, step) << ": ";
    if (y.size()) s << "its largest entry is " << entry_name(k) << " = " << y(k) << ", and ";
    s << what << "; the step is too large for this integrator, or the model is unstable";
    return s.str();
  };
  // Runs one evaluation of the model at time t and state y = (q, q_dot) and gives its errors the
  // time and the step: NaN or Inf anywhere becomes an IntegrationError; a singular matrix keeps
  // its type and rows, except that after the start a singular matrix with C_q of full rank means
  // a mass matrix ruined by a state that has blown up (an unstable step): an IntegrationError
  // naming the largest entry of the state.
  auto guarded = [&](double t, const VecX& y, auto&& evaluate) {
    try {
      return evaluate();
    } catch (const SingularJacobianError& e) {
      if (started && e.rows.empty())
        throw IntegrationError(
            blown_up("the augmented matrix [M C_q^T; C_q 0] became singular although C_q has full rank", t, y), t,
            step);
      throw SingularJacobianError(std::string(e.what()) + " (" + at(t, step) + ")", e.rows);
    } catch (const ConvergenceError&) {
      throw;  // projection: its message gives the time, iterations and residual
    } catch (const KinematicsError& e) {
      throw IntegrationError(std::string(e.what()) + " " + at(t, step) +
                                 ": the step is too large for this integrator, or the model is unstable",
                             t, step);
    }
  };
  const OdeRhs f = [&](double t, const VecX& y) {
    if (!y.allFinite()) {
      Eigen::Index k = 0;
      while (k < y.size() && std::isfinite(y(k))) ++k;
      throw IntegrationError("the state became NaN or Inf " + at(t, step) + " in " + entry_name(k) +
                                 "; the step is too large for this integrator, or the model is unstable",
                             t, step);
    }
    return guarded(t, y, [&] {
      const Accelerations a = forward_dynamics(model, y.head(n), y.tail(n), t, baumgarte);
      VecX dy(2 * n);
      dy << y.tail(n), a.qdd;
      return dy;
    });
  };
  // Power of the drivers (lambda^T C_t) and of the non-conservative forces at y = (q, q_dot).
  auto power = [&](double t, const VecX& y) {
    return guarded(t, y, [&] {
      const VecX q = y.head(n), qd = y.tail(n);
      const Accelerations a = forward_dynamics(model, q, qd, t, baumgarte);
      return a.lambda.dot(constraint_time_derivative(model, q, t)) + nonconservative_power(model, q, qd, t);
    });
  };

  Trajectory out;
  double t = t0, work = 0.0, last_output = t0;
  VecX y(2 * n);
  y << q0, qd0;
  double P = power(t, y);
  started = true;
  auto record = [&](double h) {
    const VecX q = y.head(n), qd = y.tail(n);
    const ConstraintEvaluation e = evaluate_constraints(model, q, t);
    const double energy = kinetic_energy(model, q, qd) + potential_energy(model, q);
    const double drift = e.C.norm(), velocity_drift = (e.Cq * qd + e.Ct).norm();
    if (!std::isfinite(energy) || !std::isfinite(drift) || !std::isfinite(velocity_drift) || !std::isfinite(work))
      throw IntegrationError(blown_up("the monitors (energy, work, drift) became NaN or Inf", t, y), t, step);
    out.t.push_back(t);
    out.q.push_back(q);
    out.qd.push_back(qd);
    out.step.push_back(h);
    out.energy.push_back(energy);
    out.work_done.push_back(work);
    out.position_drift.push_back(drift);
    out.velocity_drift.push_back(velocity_drift);
    last_output = t;
  };
  record(0.0);

  double h = options.step;
  const double end_tolerance = 1e-12 * std::max(1.0, std::abs(t_end));
  while (t < t_end - end_tolerance) {
    h = std::min(h, t_end - t);
    VecX y_new;
    double h_next = h;
    switch (options.integrator) {
      case Integrator::euler:
        y_new = euler_step(f, t, y, h);
        break;
      case Integrator::rk4:
        y_new = rk4_step(f, t, y, h);
        break;
      case Integrator::dormand_prince: {
        const EmbeddedStep s = dormand_prince_step(f, t, y, h);
        const double err = error_norm(s.error, y, s.y, options.rtol, options.atol);
        const double factor = std::isfinite(err) && err > 0 ? 0.9 * std::pow(err, -0.2) : 0.2;
        if (!(err <= 1.0)) {  // rejected (also when err is NaN)
          ++out.rejected_steps;
          h *= std::clamp(factor, 0.2, 0.9);
          if (h < options.min_step)
            throw StepSizeError("the adaptive step fell below min_step = " + std::to_string(options.min_step) +
                                    " s " + at(t, step) + ": the problem is too stiff or singular here",
                                t, step);
          continue;
        }
        y_new = s.y;
        h_next = std::min(h * std::clamp(factor, 0.2, 5.0), options.max_step);
        break;
      }
    }
    if (!y_new.allFinite()) f(t + h, y_new);  // throws IntegrationError naming the coordinate
    if (options.stabilisation == Stabilisation::projection) {
      guarded(t + h, y_new, [&] {
        y_new.head(n) = project_positions(model, y_new.head(n), t + h, options.projection);
        y_new.tail(n) = project_velocities(model, y_new.head(n), y_new.tail(n), t + h);
        return 0;
      });
    }
    y = y_new;
    t += h;
    ++step;
    ++out.steps;
    const double P_new = power(t, y);
    work += 0.5 * (P + P_new) * h;
    P = P_new;
    if (t - last_output >= options.output_interval - 1e-12 || t >= t_end - end_tolerance) record(h);
    h = h_next;
  }
  return out;
}

void Trajectory::write_csv(const std::string& path) const {
  std::ofstream csv(path);
  if (!csv) throw std::runtime_error("Trajectory::write_csv: cannot open " + path);
  const Eigen::Index n = q.empty() ? 0 : q.front().size();
  csv << "t,step,energy,work_done,position_drift,velocity_drift";
  for (Eigen::Index k = 0; k < n; ++k) csv << ",q" << k;
  for (Eigen::Index k = 0; k < n; ++k) csv << ",qd" << k;
  csv << '\n';
  csv.precision(15);
  for (std::size_t i = 0; i < t.size(); ++i) {
    csv << t[i] << ',' << step[i] << ',' << energy[i] << ',' << work_done[i] << ',' << position_drift[i] << ','
        << velocity_drift[i];
    for (Eigen::Index k = 0; k < n; ++k) csv << ',' << q[i](k);
    for (Eigen::Index k = 0; k < n; ++k) csv << ',' << qd[i](k);
    csv << '\n';
  }
  if (!csv) throw std::runtime_error("Trajectory::write_csv: writing " + path + " failed");
}

}  // namespace fmbd
