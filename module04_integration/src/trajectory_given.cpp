// The recorded run (given code, module 4): the Recorder that every integrator fills, the cubic
// Hermite extension of a step, and Trajectory's named access and CSV file.
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>

#include "fmbd/constraints.hpp"
#include "fmbd/energy.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/simulation.hpp"

namespace fmbd {

namespace {

std::string at(double t, int step) { return "at t = " + readable(t) + " s (step " + std::to_string(step) + ")"; }

int find_constraint(const Model& model, const std::string& name, const char* where) {
  std::string known;
  for (std::size_t c = 0; c < model.constraints().size(); ++c) {
    if (model.constraints()[c].name == name) return static_cast<int>(c);
    known += (c ? ", '" : "'") + model.constraints()[c].name + "'";
  }
  throw std::invalid_argument(std::string(where) + ": no constraint '" + name + "' (the model has " + known + ")");
}

void check_recorded(const Trajectory& tr, const char* where) {
  if (tr.lambda.size() != tr.t.size())
    throw std::logic_error(std::string(where) +
                           ": the multipliers were not recorded; set SimulationOptions::record_multipliers");
}

}  // namespace

VecX hermite(const VecX& y0, const VecX& f0, const VecX& y1, const VecX& f1, double h, double theta) {
  const double h00 = (1 + 2 * theta) * (1 - theta) * (1 - theta), h10 = theta * (1 - theta) * (1 - theta);
  const double h01 = theta * theta * (3 - 2 * theta), h11 = theta * theta * (theta - 1);
  return h00 * y0 + h10 * h * f0 + h01 * y1 + h11 * h * f1;
}

Recorder::Recorder(const Model& model, double t0, double t_end, double output_interval, double drift_limit,
                   double length, const char* who, bool record_work)
    : model_(model),
      t0_(t0),
      t_end_(t_end),
      dt_(output_interval),
      drift_limit_(drift_limit),
      length_(length),
      tiny_(1e-12 * std::max(std::abs(t0), std::abs(t_end)) + 1e-14 * (t_end - t0)),
      who_(who),
      record_work_(record_work) {}

void Recorder::start(const Sample& s) { record(t0_, s, 0.0, 0); }

void Recorder::after_step(double t, double t_new, double h, int step, const std::function<Sample(double)>& state) {
  if (dt_ == 0.0) {
    record(t_new, state(t_new), h, step);
    return;
  }
  for (double t_out = std::min(t0_ + static_cast<double>(next_) * dt_, t_end_); t_out <= t_new + tiny_;
       t_out = std::min(t0_ + static_cast<double>(++next_) * dt_, t_end_)) {
    const double t_record = t_out >= t_new - tiny_ ? t_new : std::max(t, t_out);
    record(t_record, state(t_record), h, step);
    if (t_out >= t_end_) break;
  }
}

bool Recorder::records_in(double t_new) const {
  return dt_ == 0.0 || std::min(t0_ + static_cast<double>(next_) * dt_, t_end_) <= t_new + tiny_;
}

void Recorder::record(double t, const Sample& s, double h, int step) {
  const ConstraintEvaluation e = evaluate_constraints(model_, s.q, t);
  const double energy = kinetic_energy(model_, s.q, s.qd) + potential_energy(model_, s.q);
  const double drift = e.C.norm(), velocity_drift = (e.Cq * s.qd + e.Ct).norm();
  if (!std::isfinite(energy) || !std::isfinite(drift) || !std::isfinite(velocity_drift) || !std::isfinite(s.work)) {
    // Name the largest entry of the state (a NaN counts as the largest).
    const int n = static_cast<int>(s.q.size());
    int worst = 0;
    double size = -1;
    for (int k = 0; k < 2 * n; ++k) {
      const double x = k < n ? s.q(k) : s.qd(k - n), a = std::isnan(x) ? HUGE_VAL : std::abs(x);
      if (a > size) size = a, worst = k;
    }
    std::string entry = worst < n ? model_.describe_coordinate(worst) : "the rate of " + model_.describe_coordinate(worst - n);
    throw IntegrationError(std::string(who_) + ": the state has blown up " + at(t, step) + ": its largest entry is " +
                               entry + " = " + readable(worst < n ? s.q(worst) : s.qd(worst - n)) +
                               ", and the monitors (energy, work, drift) became NaN or Inf; the step is too large " +
                               "for this integrator, or the model is unstable",
                           t, step);
  }
  if (drift > drift_limit_ * length_) {
    Eigen::Index row = 0;
    e.C.cwiseAbs().maxCoeff(&row);
    throw DriftError(std::string(who_) + ": the constraints have drifted " + at(t, step) + ": |C| = " + readable(drift) +
                         " exceeds drift_limit " + readable(drift_limit_) + " x the model's length " + readable(length_) +
                         " m; worst in " + model_.describe_row(static_cast<int>(row)) +
                         ". Use a smaller step or Stabilisation::projection (drift_limit = infinity records it anyway)",
                     t, step);
  }
  out_.t.push_back(t);
  out_.q.push_back(s.q);
  out_.qd.push_back(s.qd);
  out_.step.push_back(h);
  out_.energy.push_back(energy);
  if (record_work_) out_.work_done.push_back(s.work);
  out_.position_drift.push_back(drift);
  out_.velocity_drift.push_back(velocity_drift);
  if (s.lambda.size()) out_.lambda.push_back(s.lambda);
}

std::vector<Vec3> Trajectory::body(const Model& model, const std::string& name) const {
  std::string known;
  for (int b = 0; b < model.num_bodies(); ++b) known += (b ? ", '" : "'") + model.bodies()[b].name + "'";
  BodyId id;
  try {
    id = model.find_body(name);
  } catch (const std::exception&) {
    throw std::invalid_argument("Trajectory::body: no body '" + name + "' (the model has " + known + ")");
  }
  std::vector<Vec3> out;
  for (const VecX& x : q) out.push_back(model.body_coordinates(x, id));
  return out;
}

std::vector<VecX> Trajectory::multipliers(const Model& model, const std::string& name) const {
  const Constraint& c = model.constraints()[find_constraint(model, name, "Trajectory::multipliers")];
  check_recorded(*this, "Trajectory::multipliers");
  std::vector<VecX> out;
  for (const VecX& l : lambda) out.push_back(l.segment(c.first_row, c.rows));
  return out;
}

std::vector<JointReaction> Trajectory::reactions(const Model& model, const std::string& name) const {
  const int c = find_constraint(model, name, "Trajectory::reactions");
  check_recorded(*this, "Trajectory::reactions");
  std::vector<JointReaction> out;
  for (std::size_t i = 0; i < t.size(); ++i) out.push_back(joint_reaction(model, c, q[i], lambda[i]));
  return out;
}

void Trajectory::write_csv(const std::string& path) const {
  std::ofstream csv(path);
  if (!csv) throw std::runtime_error("Trajectory::write_csv: cannot open " + path);
  const Eigen::Index n = q.empty() ? 0 : q.front().size();
  const bool work = !t.empty() && work_done.size() == t.size();
  csv << "t,step,energy," << (work ? "work_done," : "") << "position_drift,velocity_drift";
  for (Eigen::Index k = 0; k < n; ++k) csv << ",q" << k;
  for (Eigen::Index k = 0; k < n; ++k) csv << ",qd" << k;
  csv << '\n';
  csv.precision(15);
  for (std::size_t i = 0; i < t.size(); ++i) {
    csv << t[i] << ',' << step[i] << ',' << energy[i] << ',';
    if (work) csv << work_done[i] << ',';
    csv << position_drift[i] << ',' << velocity_drift[i];
    for (Eigen::Index k = 0; k < n; ++k) csv << ',' << q[i](k);
    for (Eigen::Index k = 0; k < n; ++k) csv << ',' << qd[i](k);
    csv << '\n';
  }
  if (!csv) throw std::runtime_error("Trajectory::write_csv: writing " + path + " failed");
}

}  // namespace fmbd
