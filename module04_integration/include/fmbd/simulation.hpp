#pragma once
// Forward-dynamics simulation of a model over time (given code, module 4): an integrator from
// integrators.hpp on y = (q, q_dot), forward_dynamics() for q_ddot, a constraint treatment,
// and monitors of energy, constraint drift and step size.

#include <stdexcept>
#include <string>
#include <vector>

#include "fmbd/forward_dynamics.hpp"
#include "fmbd/projection.hpp"

namespace fmbd {

enum class Integrator { euler, rk4, dormand_prince };
enum class Stabilisation { none, baumgarte, projection };

/// Options of simulate().
struct SimulationOptions {
  Integrator integrator = Integrator::rk4;
  double step = 1e-3;        ///< fixed step, or first trial step of dormand_prince [s]
  double rtol = 1e-6;        ///< dormand_prince: relative tolerance
  double atol = 1e-9;        ///< dormand_prince: absolute tolerance
  double min_step = 1e-10;   ///< dormand_prince: smaller steps throw StepSizeError [s]
  double max_step = 0.05;    ///< dormand_prince: largest step [s]
  Stabilisation stabilisation = Stabilisation::none;
  Baumgarte baumgarte{10.0, 10.0};  ///< used with Stabilisation::baumgarte
  /// Used with Stabilisation::projection; its tolerance is relative to the model's length
  /// scale L (see drift_limit).
  ProjectionOptions projection;
  /// Record every step (0), or at the times t0 + k output_interval and t_end [s]. Fixed steps
  /// are taken at t0 + j step (the last one ends at t_end); a grid time inside a step takes the
  /// step's cubic Hermite extension, so the output times do not depend on the steps.
  double output_interval = 0.0;
  /// Largest constraint drift |C| allowed at an output point, relative to the model's length
  /// scale L (the largest |R| of a body at q0 or |s_bar| of a point; 1 m if both are zero).
  /// Beyond drift_limit L simulate() throws DriftError; infinity records any drift.
  double drift_limit = 1e-2;
};

/// The recorded run: one entry per output point.
struct Trajectory {
  std::vector<double> t;
  std::vector<VecX> q, qd;
  std::vector<double> step;            ///< step size that led to this point (0 at the start)
  std::vector<double> energy;          ///< T + V (module 3)
  std::vector<double> work_done;       ///< integral of the driver and non-conservative power so far
  std::vector<double> position_drift;  ///< |C(q, t)|
  std::vector<double> velocity_drift;  ///< |C_q q_dot + C_t|
  int steps = 0;                       ///< accepted steps
  int rejected_steps = 0;              ///< dormand_prince only

  /// Writes t, step, energy, work_done, position_drift, velocity_drift and every q and q_dot
  /// as CSV (header line first). Throws std::runtime_error if the file cannot be written.
  void write_csv(const std::string& path) const;
};

/// The state became NaN or Inf: names the time, the step number and the coordinate.
class IntegrationError : public std::runtime_error {
 public:
  IntegrationError(const std::string& message, double t, int step)
      : std::runtime_error(message), t(t), step(step) {}
  double t;
  int step;
};

/// The adaptive step fell below SimulationOptions::min_step.
class StepSizeError : public IntegrationError {
 public:
  using IntegrationError::IntegrationError;
};

/// The constraint drift |C| exceeded SimulationOptions::drift_limit: names the time, the step
/// and the constraint that drifted most.
class DriftError : public IntegrationError {
 public:
  using IntegrationError::IntegrationError;
};

/// Simulates from consistent (q0, qd0) at t0 to t_end. The work done is integrated with the
/// motion (y = (q, q_dot, W), W' = lambda^T C_t + the non-conservative power), to the
/// integrator's own order. Throws std::invalid_argument for bad options, a non-finite initial
/// state or inconsistent initial conditions (|C| or |C_dot| above 1e-6 L, L the length scale of
/// drift_limit: use consistent_initial_conditions); IntegrationError, StepSizeError and
/// DriftError, and SingularJacobianError (locked or redundant mechanism), with the time at which
/// it happened.
Trajectory simulate(const Model& model, const VecX& q0, const VecX& qd0, double t0, double t_end,
                    const SimulationOptions& options = {});

}  // namespace fmbd
