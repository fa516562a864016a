#include "fmbd/projection.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "fmbd/mass_matrix.hpp"

namespace fmbd {

VecX project_positions(const Model& model, const VecX& q, double t, const ProjectionOptions& options) {
  DynamicsData data(model);
  VecX p = q;
  project_positions(model, p, t, options, data);
  return p;
}

VecX project_velocities(const Model& model, const VecX& q, const VecX& qd, double t) {
  DynamicsData data(model);
  VecX v = qd;
  project_velocities(model, q, v, t, data);
  return v;
}

State consistent_initial_conditions(const Model& model, const VecX& q_guess, const VecX& qd_guess, double t,
                                    const ProjectionOptions& options) {
  Model::check_size(q_guess, model.num_coordinates(), "q_guess", "consistent_initial_conditions");
  Model::check_size(qd_guess, model.num_coordinates(), "qd_guess", "consistent_initial_conditions");
  State s;
  s.q = project_positions(model, q_guess, t, options);
  s.qd = project_velocities(model, s.q, qd_guess, t);
  return s;
}

StepProjection::StepProjection(const Model& model, const ProjectionOptions& options, double length)
    : model_(model),
      options_(options),
      length_(length),
      data_(model),
      now_(constraint_storage(model)),
      next_(constraint_storage(model)),
      q_(VecX::Zero(model.num_coordinates())),
      trial_(q_),
      qd_(q_),
      v_(q_),
      dv_(q_),
      M_dv_(q_),
      M_(MatX::Zero(q_.size(), q_.size())) {}

double StepProjection::operator()(VecX& y, double t, double v_ref) {
  const Eigen::Index n = model_.num_coordinates();
  q_ = y.head(n);
  project_positions(model_, q_, t, options_, data_);
  polish(t);
  qd_ = y.segment(n, n);
  v_ = qd_;
  project_velocities(model_, q_, v_, t, data_);
  y.head(n) = q_;
  y.segment(n, n) = v_;
  dv_ = v_ - qd_;
  mass_matrix(model_, q_, M_);
  M_dv_.noalias() = M_ * dv_;
  const double removed = dv_.dot(M_dv_);
  M_dv_.noalias() = M_ * qd_;
  const double before = qd_.dot(M_dv_);
  largest_ = std::max(largest_, before);
  if (!(removed > 1e-16 * v_ref * v_ref)) return 0.0;
  return largest_ > 0 ? removed / largest_ : HUGE_VAL;
}

void StepProjection::polish(double t) {
  evaluate_constraints(model_, q_, t, now_);
  for (int k = 0; k < 2; ++k) {
    const double residual = now_.C.norm();
    if (residual <= 1e-15 * length_ * std::sqrt(static_cast<double>(now_.C.size()))) return;
    mass_matrix(model_, q_, data_.M);
    data_.rhs = -now_.C;
    solve_augmented(model_, data_.M, now_.Cq, data_.zero, data_.rhs, "simulate", data_.solution);
    trial_ = q_ + data_.solution.qdd;
    evaluate_constraints(model_, trial_, t, next_);
    if (!(next_.C.norm() < residual)) return;
    q_.swap(trial_);
    std::swap(now_, next_);  // the next correction starts from the evaluation just made
  }
}

}  // namespace fmbd
