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

/// The projections of one step as simulate() takes them (Stabilisation::projection; given code),
/// and the share of the kinetic energy that the velocity projection removed (the correction is
/// M-orthogonal to the motions C_q allows, so it removes 1/2 dv^T M dv), counted only above the
/// round-off of the model's velocity scale v_ref (the square root of twice a kinetic energy). The
/// share is of the largest kinetic energy met so far, so that a mechanism that comes to rest for
/// an instant is not judged by its small energy. The positions are taken to round-off: after the
/// exercise's project_positions (to its tolerance), at most two more Newton corrections of least
/// M-norm. A residual C left within the tolerance is a neighbouring level set C(q) = c, which near
/// a singular position turns from one branch of the mechanism to another, and the velocity
/// projection would follow it there. Its storage is sized once, for `model`, so that a projection
/// allocates nothing.
class StepProjection {
 public:
  /// `options.tolerance` is absolute (simulate() passes its tolerance times the length scale
  /// `length`, which also sets the round-off of C: 1e-15 length per row).
  StepProjection(const Model& model, const ProjectionOptions& options, double length);
  /// Projects y = (q, q_dot, ...) in place at time t; returns the share of the kinetic energy the
  /// velocity projection removed (0 at round-off).
  double operator()(VecX& y, double t, double v_ref);

 private:
  void polish(double t);  // at most two more Newton corrections of q_, each kept where it lowers |C|

  const Model& model_;
  ProjectionOptions options_;
  double length_;
  DynamicsData data_;
  ConstraintEvaluation now_, next_;
  VecX q_, trial_, qd_, v_, dv_, M_dv_;
  MatX M_;
  double largest_ = 0;  // twice the largest kinetic energy before a projection
};

/// Consistent initial conditions from a partial guess: project_positions, then
/// project_velocities (given code). Coordinates that the guess gets right stay close.
struct State {
  VecX q, qd;
};
State consistent_initial_conditions(const Model& model, const VecX& q_guess, const VecX& qd_guess, double t,
                                    const ProjectionOptions& options = {});

}  // namespace fmbd
