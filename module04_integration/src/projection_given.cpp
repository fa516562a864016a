#include "fmbd/projection.hpp"

namespace fmbd {

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
