#pragma once
// Forward-dynamics simulation of a model over time (given code, module 4): an integrator from
// integrators.hpp on y = (q, q_dot), forward_dynamics() for q_ddot, a constraint treatment,
// and monitors of energy, constraint drift and step size.

#include <exception>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "fmbd/forward_dynamics.hpp"
#include "fmbd/projection.hpp"
#include "fmbd/reactions.hpp"

namespace fmbd {

enum class Integrator { euler, rk4, dormand_prince };
enum class Stabilisation { none, baumgarte, projection };

/// Options of simulate().
struct SimulationOptions {
  Integrator integrator = Integrator::rk4;
  double step = 1e-3;        ///< fixed step, or first trial step of dormand_prince [s]
  /// dormand_prince: relative tolerance. A step is accepted when the RMS of its error e_k /
  /// (atol + rtol s_k) is at most 1, with sizes s_k from the model where a coordinate's
  /// magnitude means nothing: a body's x and y relative to the body's size (the largest distance
  /// of a point on it from its centroid; the length scale L for a body without points), not to
  /// their distance from the origin; its angle relative to 1 rad; rates and elastic coordinates
  /// relative to their own magnitude max(|y_k|, |y_new_k|). With projection, e is the error of
  /// the independent coordinates (module 4 README, section 4).
  double rtol = 1e-6;
  double atol = 1e-9;        ///< dormand_prince: absolute tolerance
  double min_step = 1e-10;   ///< dormand_prince: smaller steps throw StepSizeError [s]
  /// dormand_prince: largest step [s]. A bound on the local error does not bound the global
  /// one: at rtol 1e-6 the estimate alone takes steps of 0.06 s on average on the A02 chains,
  /// whose error then grows to 6e-5 m in 10 s. Steps of at most 0.02 s keep them within 2e-7 m
  /// (module 4 README, section 4); at rtol 1e-9 the estimate's own steps are about that long.
  double max_step = 0.02;
  Stabilisation stabilisation = Stabilisation::none;
  Baumgarte baumgarte{10.0, 10.0};  ///< used with Stabilisation::baumgarte
  /// Used with Stabilisation::projection; its tolerance is relative to the model's length
  /// scale L (see drift_limit). After project_positions, at most two more Newton corrections
  /// take |C| to round-off (a residual left within the tolerance is a neighbouring level set of
  /// C, which near a singular position leads to another branch). With euler and rk4, a step whose
  /// velocity projection removes more than 1e-10 of the largest kinetic energy so far, and six
  /// decades more than the run's steps usually do (a coarse step keeps its size), is taken
  /// again in halves (six times); where the last halving did not shrink that share, the step
  /// ends too close to a singular position (or at a jump of the constraints' velocity C_t) and is
  /// kept unprojected (ProjectionError after five such steps in a row).
  ProjectionOptions projection;
  /// Record every step (0), or at the times t0 + k output_interval and t_end [s]. Fixed steps
  /// are taken at t0 + j step (the last one ends at t_end); a grid time inside a step takes the
  /// step's cubic Hermite extension (dormand_prince: its own continuous extension of order 4
  /// from the seven stages), so the output times do not depend on the steps.
  double output_interval = 0.0;
  /// Largest constraint drift |C| allowed at an output point, relative to the model's length
  /// scale L (the largest |R| of a body at q0 or |s_bar| of a point; 1 m if both are zero).
  /// Beyond drift_limit L simulate() throws DriftError; infinity records any drift.
  double drift_limit = 1e-2;
  /// Also record the Lagrange multipliers at every output point (Trajectory::lambda; one more
  /// forward_dynamics() per point), for multipliers() and reactions().
  bool record_multipliers = false;
  /// Integrate the work of the drivers and the non-conservative forces with the motion
  /// (Trajectory::work_done), at the cost of driver_power() and nonconservative_power() at
  /// every evaluation. false: no work monitor, work_done stays empty; the motion is the same.
  bool integrate_work = true;
};

/// A change of the set of dependent rows of C_q that forward dynamics met during a run
/// (Accelerations::dependent_rows): redundant constraints, or a singular position.
struct RankDeficit {
  double t = 0.0;         ///< time of the evaluation (a stage of a step) that first met the new set
  std::vector<int> rows;  ///< the dependent rows from then on; empty: C_q has full rank again
};

/// The recorded run: one entry per output point (but rank_deficits).
struct Trajectory {
  std::vector<double> t;
  std::vector<VecX> q, qd;
  std::vector<double> step;            ///< step size that led to this point (0 at the start)
  std::vector<double> energy;          ///< T + V (module 3)
  std::vector<double> work_done;       ///< integral of the driver and non-conservative power so far
                                       ///< (empty without SimulationOptions::integrate_work)
  std::vector<double> position_drift;  ///< |C(q, t)|
  std::vector<double> velocity_drift;  ///< |C_q q_dot + C_t|
  int steps = 0;                       ///< accepted steps
  /// Steps taken again: dormand_prince's error test, or (Stabilisation::projection, euler and
  /// rk4) a velocity projection that removed more than 1e-10 of the kinetic energy
  int rejected_steps = 0;
  std::vector<VecX> lambda;            ///< multipliers, with SimulationOptions::record_multipliers
                                       ///< (the minimum-norm set where C_q is rank deficient)
  /// Each change of the rank deficit of C_q, in the order the evaluations met it; empty for a
  /// model whose C_q has full rank throughout. A model with redundant constraints has one entry
  /// at t0; a singular position that an evaluation meets, one there and one where the rank returns.
  std::vector<RankDeficit> rank_deficits;
  /// Fixed steps: the instants of a rank loss that a step spanned rather than met
  /// (fmbd/singular_instant.hpp), as the rank margins of the evaluations before them predicted.
  std::vector<double> stepped_over;

  // ---- named access, one entry per output point; each throws std::invalid_argument for an
  // unknown name (the message lists the known ones) ----

  /// Coordinates (x, y, phi) of body `name` (of a flexible body: its floating frame).
  std::vector<Vec3> body(const Model& model, const std::string& name) const;
  /// Multipliers of constraint `name` (its rows of lambda). Throws std::logic_error when the
  /// multipliers were not recorded (SimulationOptions::record_multipliers).
  std::vector<VecX> multipliers(const Model& model, const std::string& name) const;
  /// Reactions of joint `name` on its two bodies (joint_reaction(), module 3); for a driver use
  /// driver_effort() with multipliers(). Throws std::logic_error as multipliers().
  std::vector<JointReaction> reactions(const Model& model, const std::string& name) const;

  /// Writes t, step, energy, work_done (when recorded), position_drift, velocity_drift and
  /// every q and q_dot as CSV (header line first). Throws std::runtime_error if the file
  /// cannot be written.
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

/// Stabilisation::projection with euler or rk4: velocity projections removed more than 1e-10 of
/// the kinetic energy in five steps in a row, and halving those steps did not shrink it. Where C_q
/// has lost rank, the motion stays at a singular position, where it can switch to another branch
/// of the mechanism (the message names a dependent row); where C_q has full rank, the velocity the
/// constraints ask for jumps (a drive function whose rate is not continuous; the message names the
/// row the unprojected velocity misses most). Names the time and the step.
class ProjectionError : public IntegrationError {
 public:
  using IntegrationError::IntegrationError;
};

/// The constraint drift |C| exceeded SimulationOptions::drift_limit: names the time, the step
/// and the constraint that drifted most.
class DriftError : public IntegrationError {
 public:
  using IntegrationError::IntegrationError;
};

// ---- What every integrator shares (simulate, and generalized_alpha of extras/implicit) ----

/// The model's length scale L: the largest distance of a body's position in q or of a point's
/// body-frame offset from the origin; 1 m for a model that has neither.
double length_scale(const Model& model, const VecX& q);

/// Checks the initial state of an integration: sizes, finite entries (std::invalid_argument
/// naming the coordinate) and consistency, |C| and |C_q q_dot + C_t| at most 1e-6 L
/// (std::invalid_argument naming the constraint row). `who` names the caller in messages.
void check_initial_state(const Model& model, const VecX& q0, const VecX& qd0, double t0, const char* who);

/// One state of an integration: q, q_dot, the work done since the start, and the multipliers
/// (empty when they are not recorded).
struct Sample {
  VecX q, qd;
  double work = 0.0;
  VecX lambda;
};

/// The output side of an integrator: the output grid t0 + k output_interval (every step when it
/// is 0) ending at t_end, the monitors of every recorded point (energy, work, drift), and the
/// drift limit (DriftError beyond drift_limit L). The integrator calls start() once and then
/// after_step() after every accepted step. Without record_work, Sample::work is ignored and
/// Trajectory::work_done stays empty.
class Recorder {
 public:
  Recorder(const Model& model, double t0, double t_end, double output_interval, double drift_limit, double length,
           const char* who, bool record_work = true);
  /// Records the initial point.
  void start(const Sample& s);
  /// After a step from t to t_new of size h (`step` steps done): records every output time in
  /// (t, t_new], taking the state there from state(t_out); state(t_new) is the step's own end.
  void after_step(double t, double t_new, double h, int step, const std::function<Sample(double)>& state);
  /// Whether after_step(..., t_new, ...) records a point: an output time lies in (t, t_new].
  bool records_in(double t_new) const;
  Trajectory& trajectory() { return out_; }

 private:
  void record(double t, const Sample& s, double h, int step);
  const Model& model_;
  double t0_, t_end_, dt_, drift_limit_, length_, tiny_;
  const char* who_;
  bool record_work_;
  long next_ = 1;  // index k of the next output time t0 + k dt
  Trajectory out_;
};

/// Cubic Hermite interpolation on [t, t + h] from the values y0, y1 and slopes f0, f1 at both
/// ends, at t + theta h (0 <= theta <= 1).
VecX hermite(const VecX& y0, const VecX& f0, const VecX& y1, const VecX& f1, double h, double theta);

/// Simulates from consistent (q0, qd0) at t0 to t_end. The work done is integrated with the
/// motion (y = (q, q_dot, W), W' = lambda^T C_t + the non-conservative power), to the
/// integrator's own order, unless SimulationOptions::integrate_work is false (y = (q, q_dot)).
/// Throws std::invalid_argument for bad options, a non-finite initial state or inconsistent
/// initial conditions (|C| or |C_dot| above 1e-6 L, L the length scale of
/// drift_limit: use consistent_initial_conditions); IntegrationError, StepSizeError,
/// ProjectionError and DriftError, and SingularJacobianError (a locked mechanism: constraint equations without a
/// solution), with the time at which it happened. Redundant constraints do not stop it: their
/// rows are reported in Trajectory::rank_deficits.
Trajectory simulate(const Model& model, const VecX& q0, const VecX& qd0, double t0, double t_end,
                    const SimulationOptions& options = {});

/// What simulate_keeping() returns: the run up to t_end, or up to the failure that stopped it.
struct SimulationOutcome {
  /// Every output point recorded before the failure, with the steps, rejected steps and rank
  /// deficits met so far; the whole run when it reached t_end.
  Trajectory trajectory;
  /// The exception simulate() would have thrown once the run had started (IntegrationError and
  /// its kinds, SingularJacobianError, ConvergenceError of the projection, ...), to inspect with
  /// std::rethrow_exception; null when the run reached t_end.
  std::exception_ptr error;
  bool completed() const { return !error; }
};

/// simulate(), keeping the trajectory when a step fails: a failure after the checks of the
/// arguments is returned in SimulationOutcome::error with the points recorded before it, instead
/// of thrown. Throws what simulate() throws before the run starts: std::invalid_argument for bad
/// options, sizes, a non-finite or an inconsistent initial state.
SimulationOutcome simulate_keeping(const Model& model, const VecX& q0, const VecX& qd0, double t0, double t_end,
                                   const SimulationOptions& options = {});

}  // namespace fmbd
