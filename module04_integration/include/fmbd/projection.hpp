#pragma once
// Coordinate projection (module 4, task T4): after a step, move q and q_dot back onto the
// constraint manifold by the smallest correction in the mass-weighted norm.
//
//   positions:  minimise 1/2 dq^T M dq  subject to  C(q + dq, t) = 0   (Newton iterations of
//               [M C_q^T; C_q 0] (dq; mu) = (0; -C))
//   velocities: minimise 1/2 dv^T M dv  subject to  C_q (q_dot + dv) + C_t = 0   (one solve)

#include "fmbd/forward_dynamics.hpp"
#include "fmbd/model.hpp"

namespace fmbd {

struct ProjectionOptions {
  double tolerance = 1e-10;  ///< on |C|
  int max_iterations = 20;
};

/// M04T4. Projects q in place; throws ConvergenceError (with iterations and |C|) if the
/// tolerance is not reached. `data` (sized for the model) holds M, C and C_q afterwards.
void project_positions(const Model& model, VecX& q, double t, const ProjectionOptions& options, DynamicsData& data);

/// M04T4. Projects qd in place, at consistent positions q. `data` as for project_positions.
void project_velocities(const Model& model, const VecX& q, VecX& qd, double t, DynamicsData& data);

/// The same two with storage of their own (given code), returning the projected coordinates.
VecX project_positions(const Model& model, const VecX& q, double t, const ProjectionOptions& options = {});
VecX project_velocities(const Model& model, const VecX& q, const VecX& qd, double t);

/// Consistent initial conditions from a partial guess: project_positions, then
/// project_velocities (given code). Coordinates that the guess gets right stay close.
struct State {
  VecX q, qd;
};
State consistent_initial_conditions(const Model& model, const VecX& q_guess, const VecX& qd_guess, double t,
                                    const ProjectionOptions& options = {});

}  // namespace fmbd
