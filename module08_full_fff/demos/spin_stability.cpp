// Stability of the spin-up beam in steady spin: see spin_stability.hpp.
#include "spin_stability.hpp"

#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

#include "fmbd/forward_dynamics.hpp"
#include "fmbd/marker.hpp"

namespace fmbd::spin {

namespace {

constexpr double kStep = 1e-5;  // differencing step in q_f and q_f_dot

// The beam in steady spin from t = 0 at the elastic state (q_f, q_f_dot).
FlexibleExample steady_example(SpinUpBeamParameters p, const BodyFactory& make, const VecX& q_f, const VecX& qf_dot) {
  p.spin_up_time = 0.0;
  p.initial = {q_f, qf_dot};
  return spin_up_beam(p, make);
}

int elastic_size(const SpinUpBeamParameters& p, const BodyFactory& make) {
  SpinUpBeamParameters q = p;
  q.initial = {};
  return spin_up_beam(q, make).data->num_modes();
}

// The second half of f(y): q_f_ddot.
VecX elastic_accelerations(const SpinUpBeamParameters& p, const BodyFactory& make, const VecX& q_f,
                           const VecX& qf_dot) {
  const FlexibleExample ex = steady_example(p, make, q_f, qf_dot);
  const int at = ex.model.offset(ex.flexible) + 3;
  return forward_dynamics(ex.model, ex.q0, ex.qd0, 0.0).qdd.segment(at, q_f.size());
}

// d f / d y at (q_f, 0) by central differences; `columns` = n_f gives the q_f columns only.
MatX state_jacobian(const SpinUpBeamParameters& p, const BodyFactory& make, const VecX& q_f, int columns) {
  const int n = static_cast<int>(q_f.size());
  MatX J = MatX::Zero(2 * n, 2 * n);
  J.topRightCorner(n, n).setIdentity();
  for (int j = 0; j < columns; ++j) {
    VecX dq = VecX::Zero(n), dv = VecX::Zero(n);
    (j < n ? dq(j) : dv(j - n)) = kStep;
    J.block(n, j, n, 1) =
        (elastic_accelerations(p, make, q_f + dq, dv) - elastic_accelerations(p, make, q_f - dq, -dv)) / (2 * kStep);
  }
  return J;
}

}  // namespace

double tip_deflection(const FlexibleExample& ex, const VecX& q) {
  const Model& m = ex.model;
  const Vec2 tip = point_position(m, m.find_point("beam tip"), q);
  return (rotation(m.body_coordinates(q, m.find_body("hub"))(2)).transpose() * tip).y();
}

SimulationOptions run_options() {
  SimulationOptions o;
  o.integrator = Integrator::dormand_prince;
  o.rtol = 1e-8;
  o.atol = 1e-10;
  o.max_step = 0.01;
  o.stabilisation = Stabilisation::projection;
  return o;
}

SteadySpin steady_spin(SpinUpBeamParameters p, const BodyFactory& make) {
  const int n = elastic_size(p, make);
  SteadySpin s;
  s.q_f = VecX::Zero(n);
  for (int iteration = 0;; ++iteration) {
    if (iteration == 20)
      throw std::runtime_error("steady_spin: no steady state at " + std::to_string(p.spin_rate) + " rad/s");
    const MatX J = state_jacobian(p, make, s.q_f, n);
    const VecX dq = J.bottomLeftCorner(n, n).lu().solve(-elastic_accelerations(p, make, s.q_f, VecX::Zero(n)));
    s.q_f += dq;
    if (dq.norm() <= 1e-12 * (1.0 + s.q_f.norm())) break;
  }
  s.jacobian = state_jacobian(p, make, s.q_f, 2 * n);
  const Eigen::EigenSolver<MatX> eig(s.jacobian);
  s.eigenvalues = eig.eigenvalues();
  s.eigenvectors = eig.eigenvectors();
  s.growth = s.eigenvalues.real().maxCoeff();
  return s;
}

double stability_threshold(const SpinUpBeamParameters& p, const BodyFactory& make, double upper, double step,
                           double tolerance) {
  const auto unstable = [&](double rate) {
    SpinUpBeamParameters q = p;
    q.spin_rate = rate;
    return steady_spin(q, make).growth > growth_tolerance;
  };
  double lo = 0.0, hi = step;
  while (!unstable(hi)) {
    if (hi >= upper) return std::nan("");
    lo = hi;
    hi = std::min(upper, hi + step);
  }
  while (hi - lo > tolerance) {
    const double mid = 0.5 * (lo + hi);
    (unstable(mid) ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

namespace {

// The q_f part of the eigenvector whose eigenvalue is nearest zero, turned real.
VecX softest_shape(const SteadySpin& s) {
  const int n = static_cast<int>(s.q_f.size());
  Eigen::Index k = 0;
  s.eigenvalues.cwiseAbs().minCoeff(&k);
  Eigen::VectorXcd v = s.eigenvectors.col(k).head(n);
  Eigen::Index big = 0;
  v.cwiseAbs().maxCoeff(&big);
  v *= std::conj(v(big)) / std::abs(v(big));
  return v.real();
}

// The first time |d| reaches `level`, linearly between samples; NaN if never.
double time_at(const std::vector<double>& t, const std::vector<double>& d, double level) {
  for (std::size_t i = 1; i < d.size(); ++i)
    if (std::abs(d[i]) >= level) {
      const double a = std::abs(d[i - 1]), b = std::abs(d[i]);
      return t[i - 1] + (t[i] - t[i - 1]) * (level - a) / (b - a);
    }
  return std::nan("");
}

}  // namespace

KickedRun kicked_run(SpinUpBeamParameters p, const BodyFactory& make, double kick, double t_end, double limit) {
  const SteadySpin s = steady_spin(p, make);
  const VecX zero = VecX::Zero(s.q_f.size());
  const FlexibleExample rest = steady_example(p, make, s.q_f, zero);
  const double steady_tip = tip_deflection(rest, rest.q0);
  const VecX shape = softest_shape(s) * 1e-3;
  const FlexibleExample probe = steady_example(p, make, s.q_f + shape, zero);
  const double per_shape = tip_deflection(probe, probe.q0) - steady_tip;
  if (std::abs(per_shape) < 1e-9) throw std::runtime_error("kicked_run: the softest shape does not move the tip");
  const FlexibleExample ex = steady_example(p, make, s.q_f + shape * (kick / per_shape), zero);

  KickedRun run;
  VecX q = ex.q0, qd = ex.qd0;
  const double dt = 0.05;
  const SimulationOptions o = run_options();
  run.t.push_back(0.0);
  run.deviation.push_back(tip_deflection(ex, q) - steady_tip);
  for (int i = 1; i * dt <= t_end + 1e-12 && std::abs(run.deviation.back()) <= limit; ++i) {
    const Trajectory step = simulate(ex.model, q, qd, (i - 1) * dt, i * dt, o);
    q = step.q.back();
    qd = step.qd.back();
    run.t.push_back(i * dt);
    run.deviation.push_back(tip_deflection(ex, q) - steady_tip);
  }
  for (double d : run.deviation) run.peak = std::max(run.peak, std::abs(d));
  const double t10 = time_at(run.t, run.deviation, 10 * kick), t100 = time_at(run.t, run.deviation, 100 * kick);
  if (std::isfinite(t10) && std::isfinite(t100)) run.growth = std::log(10.0) / (t100 - t10);
  return run;
}

}  // namespace fmbd::spin
