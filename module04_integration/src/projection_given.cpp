#include "fmbd/projection.hpp"

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

}  // namespace fmbd
