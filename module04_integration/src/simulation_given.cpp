#include "fmbd/simulation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <sstream>
#include <utility>

#include "fmbd/constraints.hpp"
#include "fmbd/energy.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/integrators.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/mass_matrix.hpp"
#include "fmbd/singular_instant.hpp"

namespace fmbd {

namespace {

std::string at(double t, int step) { return "at t = " + readable(t) + " s (step " + std::to_string(step) + ")"; }

void check_options(const SimulationOptions& o, double t0, double t_end) {
  auto fail = [](const std::string& what) { throw std::invalid_argument("simulate: " + what); };
  auto positive = [&](double x, const char* name) {
    if (!(x > 0) || !std::isfinite(x)) fail(std::string(name) + " must be positive, got " + readable(x));
  };
  if (!std::isfinite(t0) || !std::isfinite(t_end)) fail("t0 and t_end must be finite");
  if (!(t_end > t0)) fail("t_end must be after t0");
  positive(o.step, "step");
  if (o.integrator == Integrator::dormand_prince) {
    positive(o.rtol, "rtol");
    positive(o.atol, "atol");
    positive(o.min_step, "min_step");
    positive(o.max_step, "max_step");
    if (o.min_step > o.max_step) fail("min_step = " + readable(o.min_step) + " s exceeds max_step = " + readable(o.max_step) + " s");
  }
  if (o.stabilisation == Stabilisation::baumgarte &&
      (!(o.baumgarte.alpha >= 0) || !(o.baumgarte.beta >= 0) || !std::isfinite(o.baumgarte.alpha + o.baumgarte.beta)))
    fail("Baumgarte alpha and beta must not be negative");
  if (o.stabilisation == Stabilisation::projection) {
    positive(o.projection.tolerance, "projection.tolerance");
    if (o.projection.max_iterations < 1)
      fail("projection.max_iterations must be at least 1, got " + std::to_string(o.projection.max_iterations));
  }
  if (!(o.output_interval >= 0) || !std::isfinite(o.output_interval))
    fail("output_interval must be zero (every step) or positive, got " + readable(o.output_interval));
  if (!(o.drift_limit > 0)) fail("drift_limit must be positive (infinity: no limit), got " + readable(o.drift_limit));
}

// A velocity projection that removes more than this share of the kinetic energy is not the drift
// of an accurate step.
constexpr double kProjectionShare = 1e-10;

// Fixed steps whose projection removes too much: taken again in halves (at most kMaxHalvings
// times), or kept unprojected where halving does not help (at most kMaxDeferred in a row).
constexpr int kMaxHalvings = 6, kMaxDeferred = 4;
constexpr double kJump = 6;

}  // namespace

double length_scale(const Model& model, const VecX& q) {
  double L = 0.0;
  for (int b = 0; b < model.num_bodies(); ++b) L = std::max(L, model.body_coordinates(q, BodyId{b}).head<2>().norm());
  for (const Point& p : model.points()) L = std::max(L, p.s_bar.norm());
  return L > 0 ? L : 1.0;
}

void check_initial_state(const Model& model, const VecX& q0, const VecX& qd0, double t0, const char* who) {
  const int n = model.num_coordinates();
  Model::check_size(q0, n, "q0", who);
  Model::check_size(qd0, n, "qd0", who);
  for (const auto& [v, name] : {std::pair<const VecX*, const char*>{&q0, "q0"}, {&qd0, "qd0"}})
    for (Eigen::Index k = 0; k < n; ++k)
      if (!std::isfinite((*v)(k)))
        throw std::invalid_argument(std::string(who) + ": the initial state is not finite: " + name + " of " +
                                    model.describe_coordinate(static_cast<int>(k)) + " = " + readable((*v)(k)));
  const ConstraintEvaluation e = evaluate_constraints(model, q0, t0);
  const VecX C_dot = e.Cq * qd0 + e.Ct;
  const double tolerance = 1e-6 * length_scale(model, q0);  // velocities: per unit time, on the same scale
  for (const auto& [residual, name] : {std::pair<const VecX*, const char*>{&e.C, "C(q0)"}, {&C_dot, "C_q q_dot0 + C_t"}}) {
    Eigen::Index row = 0;
    if (residual->size() && residual->cwiseAbs().maxCoeff(&row) > tolerance)
      throw std::invalid_argument(std::string(who) + ": inconsistent initial conditions: " + name + " = " +
                                  readable((*residual)(row)) + " in " + model.describe_row(static_cast<int>(row)) +
                                  "; use consistent_initial_conditions() first");
  }
}

namespace {

// The blow-up bound's mask: every entry of (q, q_dot) but the angles (which grow without bound as
// a body turns).
VecX watched_entries(const Model& model) {
  const int n = model.num_coordinates();
  VecX watched = VecX::Ones(2 * n);
  for (int b = 0; b < model.num_bodies(); ++b) watched(model.offset(BodyId{b}) + 2) = 0.0;
  return watched;
}

// The model's velocity scale below which a projection's removal is round-off: L / span for
// translations, 1 / span for angles, in the M-norm at q0, or the initial q_dot.
double velocity_scale(const Model& model, const VecX& q0, const VecX& qd0, const VecX& watched, double length,
                      double span) {
  const Eigen::Index n = q0.size();
  const MatX M0 = mass_matrix(model, q0);
  const VecX unit_rates = (watched.head(n) * length + (VecX::Ones(n) - watched.head(n))) / span;
  return std::sqrt(std::max(unit_rates.dot(M0 * unit_rates), qd0.dot(M0 * qd0)));
}

// The size that Dormand-Prince's relative tolerance takes each entry of (q, q_dot) relative to, or
// 0 where it is the entry's own magnitude max(|y_k|, |y_new_k|). A body's x and y: the body's own
// size (the largest distance of a point on it from its centroid; the model's length scale L for
// a body without points), not the distance from the origin, which a move of the ground frame
// changes (40 m at the far end of the 40-window A02 chain, 0 where a coordinate crosses an axis);
// its angle: one radian (an angle error dphi moves the body's points by size dphi, the same
// share of its size), not the angle, which grows by 2 pi a turn. Elastic coordinates and every
// rate: their own magnitude (they do not depend on the origin).
VecX error_sizes(const Model& model, double length) {
  const int n = model.num_coordinates();
  VecX sizes = VecX::Zero(2 * n);
  std::vector<double> extent(model.bodies().size(), 0.0);
  for (const Point& p : model.points())
    if (!p.body.is_ground()) extent[p.body.index] = std::max(extent[p.body.index], p.s_bar.norm());
  for (int b = 0; b < model.num_bodies(); ++b) {
    const int k = model.offset(BodyId{b});
    sizes(k) = sizes(k + 1) = extent[b] > 0 ? extent[b] : length;
    sizes(k + 2) = 1.0;
  }
  return sizes;
}

// One run of simulate(): the model's evaluations with the time and step in their errors, the
// fixed steps (projected, halved where a projection removes too much), the adaptive steps, and
// the recorder. The integrated state is y = (q, q_dot, W): W, the work of the drivers and the
// non-conservative forces, is integrated with the motion, to the integrator's own order.
// Without the work monitor, y = (q, q_dot).
class Simulation {
 public:
  Simulation(const Model& model, const VecX& q0, const VecX& qd0, double t0, double t_end,
             const SimulationOptions& options)
      : model_(model),
        options_(options),
        n_(model.num_coordinates()),
        t0_(t0),
        t_end_(t_end),
        length_(length_scale(model, q0)),
        projection_(scaled(options.projection, length_)),
        baumgarte_(options.stabilisation == Stabilisation::baumgarte ? options.baumgarte : Baumgarte{}),
        work_(options.integrate_work),
        size_(2 * n_ + (work_ ? 1 : 0)),
        watched_(watched_entries(model)),
        // 1e8 times the initial state's largest watched entry or the length scale.
        blow_up_(1e8 * std::max({length_, watched_.head(n_).cwiseProduct(q0).cwiseAbs().maxCoeff(),
                                 qd0.cwiseAbs().maxCoeff()})),
        recorder_(model, t0, t_end, options.output_interval, options.drift_limit, length_, "simulate", work_),
        project_step_(model, projection_, length_),
        v_ref_(velocity_scale(model, q0, qd0, watched_, length_, t_end - t0)),
        sizes_(error_sizes(model, length_)),
        f_([this](double t, const VecX& y, VecX& dy) { rhs(t, y, dy); }),
        data_(model),
        q_(VecX::Zero(n_)),
        qd_(VecX::Zero(n_)),
        y_(VecX::Zero(size_)),
        y_new_(y_),
        unprojected_(y_),
        singular_(t0, options.step) {
    y_.head(n_) = q0;
    y_.segment(n_, n_) = qd0;
  }

  Trajectory run();
  Trajectory recorded();  // the points recorded so far, with the rank deficits met

 private:
  static ProjectionOptions scaled(ProjectionOptions o, double length) {
    o.tolerance *= length;
    return o;
  }
  std::string entry_name(Eigen::Index k) const;
  std::string blown_up(const std::string& what, double t, const VecX& y) const;
  // Runs one evaluation of the model at time t and state y and gives its errors the time and
  // the step: NaN or Inf anywhere becomes an IntegrationError; a singular matrix keeps its type
  // and rows, except that after the start a singular matrix with C_q of full rank means a mass
  // matrix ruined by a state that has blown up (an unstable step): an IntegrationError naming
  // the largest entry of the state.
  template <class Evaluate>
  auto guarded(double t, const VecX& y, Evaluate&& evaluate) const {
    try {
      return evaluate();
    } catch (const SingularJacobianError& e) {
      if (started_ && e.rows.empty())
        throw IntegrationError(
            blown_up("the augmented matrix [M C_q^T; C_q 0] became singular although C_q has full rank", t, y), t,
            step_);
      throw SingularJacobianError(std::string(e.what()) + " (" + at(t, step_) + ")", e.rows);
    } catch (const ConvergenceError&) {
      throw;  // projection: its message gives the time, iterations and residual
    } catch (const KinematicsError& e) {
      throw IntegrationError(std::string(e.what()) + " " + at(t, step_) +
                                 ": the step is too large for this integrator, or the model is unstable",
                             t, step_);
    }
  }
  void rhs(double t, const VecX& y, VecX& dy);
  VecX rhs(double t, const VecX& y);
  Sample sample(double t, const VecX& y) const;
  double project(VecX& y_new, double t_new);
  ProjectionError projection_error(double t_new, int halvings, const VecX& y_new) const;
  void advance(double t, const VecX& y, double t_new, int halvings, double parent, VecX& y_new);
  void independent_error(double t_new, const VecX& y_new, const VecX& error);
  double weighted_error(const VecX& error, const VecX& y_new) const;
  bool adaptive_step(double t, double& h, double t_new, VecX& y_new, double& h_next);
  bool dense_output(double h, const VecX& y_new);
  VecX dense(double theta) const;
  void record_step(double t, double t_new, double h, const VecX& y_new);

  const Model& model_;
  const SimulationOptions& options_;
  const int n_;
  const double t0_, t_end_, length_;
  const ProjectionOptions projection_;  // tolerance times the length scale
  const Baumgarte baumgarte_;
  const bool work_;
  const Eigen::Index size_;
  const VecX watched_;
  const double blow_up_;
  Recorder recorder_;
  StepProjection project_step_;  // projection.hpp
  const double v_ref_;
  const VecX sizes_;  // Dormand-Prince's sizes of (q, q_dot) (error_sizes)
  const OdeRhsInto f_;
  // The storage of a step, sized once: a step that records no output point allocates nothing.
  DynamicsData data_;
  Stages stages_;
  EmbeddedStep embedded_;
  VecX q_, qd_, y_, y_new_, unprojected_, independent_;
  std::array<VecX, 6> dense_;  // Dormand-Prince's continuous extension of the last step
  int step_ = 0;
  bool started_ = false;            // the initial state has been evaluated
  std::vector<int> dependent_;      // the dependent rows of C_q at the last evaluation
  std::vector<RankDeficit> deficits_;
  SingularInstant singular_;        // fixed steps across a rank loss
  int deferred_ = 0;                // steps kept unprojected in a row
  double typical_ = -HUGE_VAL;      // log10 of the share a step of this run usually removes
};

std::string Simulation::entry_name(Eigen::Index k) const {
  if (k == 2 * n_) return std::string("the work done");
  return k < n_ ? model_.describe_coordinate(static_cast<int>(k))
                : "the rate of " + model_.describe_coordinate(static_cast<int>(k - n_));
}

// "the state has blown up at t = ... (step ...): its largest entry is ..., and <what>; ...".
std::string Simulation::blown_up(const std::string& what, double t, const VecX& y) const {
  Eigen::Index k = 0;
  if (y.size()) y.cwiseAbs().maxCoeff(&k);
  std::ostringstream s;
  s << "the state has blown up " << at(t, step_) << ": ";
  if (y.size()) s << "its largest entry is " << entry_name(k) << " = " << readable(y(k)) << ", and ";
  s << what << "; the step is too large for this integrator, or the model is unstable";
  return s.str();
}

void Simulation::rhs(double t, const VecX& y, VecX& dy) {
  if (!y.allFinite()) {
    Eigen::Index k = 0;
    while (k < y.size() && std::isfinite(y(k))) ++k;
    throw IntegrationError("the state became NaN or Inf " + at(t, step_) + " in " + entry_name(k) +
                               "; the step is too large for this integrator, or the model is unstable",
                           t, step_);
  }
  // A state far beyond its start has blown up, even where every matrix stays regular (the
  // unit-free solve does not turn huge entries into a singular matrix).
  if (y.head(2 * n_).cwiseProduct(watched_).cwiseAbs().maxCoeff() > blow_up_)
    throw IntegrationError(
        blown_up("the state exceeds 1e8 times its initial size", t, y.head(2 * n_).cwiseProduct(watched_)), t, step_);
  guarded(t, y, [&] {
    q_ = y.head(n_);
    qd_ = y.segment(n_, n_);
    forward_dynamics(model_, q_, qd_, t, baumgarte_, data_);
    const Accelerations& a = data_.solution;
    if (a.dependent_rows != dependent_) deficits_.push_back({t, dependent_ = a.dependent_rows});
    singular_.observe(t, a.rank_margin);
    dy.resize(size_);
    dy.head(n_) = qd_;
    dy.segment(n_, n_) = a.qdd;
    if (work_) dy(2 * n_) = driver_power(model_, q_, a.lambda, t) + nonconservative_power(model_, q_, qd_, t);
  });
}

VecX Simulation::rhs(double t, const VecX& y) {
  VecX dy(size_);
  rhs(t, y, dy);
  return dy;
}

Sample Simulation::sample(double t, const VecX& y) const {
  Sample s{y.head(n_), y.segment(n_, n_), work_ ? y(2 * n_) : 0.0, VecX()};
  if (options_.record_multipliers)
    s.lambda = guarded(t, y, [&] { return forward_dynamics(model_, s.q, s.qd, t, baumgarte_).lambda; });
  return s;
}

// Stabilisation::projection: the projections of a step and the share of the kinetic energy they
// remove.
double Simulation::project(VecX& y_new, double t_new) {
  if (!y_new.allFinite()) rhs(t_new, y_new);  // throws IntegrationError naming the coordinate
  return guarded(t_new, y_new, [&] { return project_step_(y_new, t_new, v_ref_); });
}

// Five steps in a row whose velocity projection halving did not shrink: at a singular position
// (C_q lost rank at the last evaluation), the motion can switch branch; with C_q of full rank,
// the velocity the constraints ask for jumps (C_t is not continuous), and the row that the
// unprojected state y_new misses most is named.
ProjectionError Simulation::projection_error(double t_new, int halvings, const VecX& y_new) const {
  std::string why;
  if (!dependent_.empty()) {
    why = "the motion stays at a singular position of the constraints (C_q loses rank in " +
          model_.describe_row(dependent_.front()) + (dependent_.size() > 1 ? " and others" : "") +
          "), where it can switch to another branch of the mechanism. Check the model for a flat or folded "
          "linkage at this time, or simulate without projection";
  } else {
    const ConstraintEvaluation e = evaluate_constraints(model_, y_new.head(n_), t_new);
    const VecX miss = e.Cq * y_new.segment(n_, n_) + e.Ct;
    Eigen::Index row = 0;
    if (miss.size()) miss.cwiseAbs().maxCoeff(&row);
    why = "C_q has full rank, so the velocity the constraints ask for jumps here, most in " +
          model_.describe_row(static_cast<int>(row)) + " (C_q q_dot + C_t = " +
          readable(miss.size() ? miss(row) : 0.0) +
          " before the projection): a drive function whose rate f' jumps, or whose f'' is not the derivative "
          "of f', does this. Make it smooth (e.g. DriveFunction::smooth_step) or check its derivatives";
  }
  return ProjectionError("simulate: the velocity projection " + at(t_new, step_) + " removed more than " +
                             readable(kProjectionShare) + " of the kinetic energy in " +
                             std::to_string(kMaxDeferred + 1) + " steps in a row, and halving a step " +
                             std::to_string(halvings) + " times did not shrink it: " + why,
                         t_new, step_);
}

// A fixed step (euler, rk4) from (t, y) to t_new, projected. A step whose velocity projection
// removes more than kProjectionShare of the kinetic energy, and kJump decades more than the steps
// of this run usually do (so that a coarse step, whose every projection removes much, keeps its
// size), is taken again as two halves, at most kMaxHalvings times. If the last halving still
// shrank that share (by 4 at least: the drift of an inaccurate step falls as a power of the
// step), the step is kept. If it did not, the step ends too close to a singular position, where a
// residual of C at round-off already leads to another branch: it is kept unprojected (its drift is
// the integrator's own), and the next step projects again, at most kMaxDeferred times in a row.
void Simulation::advance(double t, const VecX& y, double t_new, int halvings, double parent, VecX& y_new) {
  const double h = t_new - t;
  if (options_.integrator == Integrator::euler)
    euler_step(f_, t, y, h, stages_, y_new);
  else
    rk4_step(f_, t, y, h, stages_, y_new);
  if (options_.stabilisation != Stabilisation::projection) {
    if (!y_new.allFinite()) rhs(t_new, y_new);
    return;
  }
  unprojected_ = y_new;
  const double share = project(y_new, t_new);
  // log10 of the share a step of this run usually removes (its own drift), from the whole steps
  // that were kept and removed more than round-off (the first such step sets it); a share kJump
  // decades above it is an anomaly.
  const double decades = std::log10(share + 1e-300);
  const bool usual =
      share <= kProjectionShare || (halvings == 0 && (!std::isfinite(typical_) || decades <= typical_ + kJump));
  if (usual) {
    if (halvings == 0 && share > 0) typical_ = std::isfinite(typical_) ? 0.9 * typical_ + 0.1 * decades : decades;
    deferred_ = 0;
    return;
  }
  if (halvings == kMaxHalvings) {
    if (share < parent / 4) {  // still shrinking: the drift of a coarse step
      deferred_ = 0;
      return;
    }
    if (++deferred_ > kMaxDeferred) throw projection_error(t_new, halvings, unprojected_);
    y_new = unprojected_;
    return;
  }
  ++recorder_.trajectory().rejected_steps;
  const double middle = t + 0.5 * h;
  VecX half;  // a step taken again in halves: rare, and allowed its own storage
  advance(t, y, middle, halvings + 1, share, half);
  advance(middle, half, t_new, halvings + 1, share, y_new);
}

// With projection, the error of the independent coordinates: the q and q_dot parts of a step's
// error each projected M-orthogonally onto the null space of C_q at its end (the projection
// removes the rest). Near a singular position the stages' drift, amplified across the branch,
// would dominate the estimate and shrink the step without end (module 4 README, section 4).
// The result in independent_.
void Simulation::independent_error(double t_new, const VecX& y_new, const VecX& error) {
  guarded(t_new, y_new, [&] {
    DynamicsData& d = data_;
    q_ = y_new.head(n_);
    mass_matrix(model_, q_, d.M);
    evaluate_constraints(model_, q_, t_new, d.constraints);
    d.rhs.setZero();
    independent_.resize(2 * n_);
    for (int part : {0, 1}) {
      d.Q_a.noalias() = d.M * error.segment(part * n_, n_);
      solve_augmented(model_, d.M, d.constraints.Cq, d.Q_a, d.rhs, "simulate", d.solution);
      independent_.segment(part * n_, n_) = d.solution.qdd;
    }
  });
}

// The weighted RMS norm of the q and q_dot parts of a step's error (error_norm of integrators.hpp),
// with atol + rtol size_k as the weight of the entries that error_sizes gives a size.
double Simulation::weighted_error(const VecX& error, const VecX& y_new) const {
  double sum = 0.0;
  for (Eigen::Index k = 0; k < 2 * n_; ++k) {
    const double size = sizes_(k) > 0 ? sizes_(k) : std::max(std::abs(y_(k)), std::abs(y_new(k)));
    const double e = error(k) / (options_.atol + options_.rtol * size);
    sum += e * e;
  }
  return std::sqrt(sum / static_cast<double>(2 * n_));
}

// A Dormand-Prince step of size h from (t, y_) to t_new: false (h shrunk) if its error is too
// large, else y_new (projected) and the next step's size. With projection, a stage at the instant
// of a rank loss without an acceleration rejects the step; it is thrown below min_step only.
bool Simulation::adaptive_step(double t, double& h, double t_new, VecX& y_new, double& h_next) {
  const bool projected = options_.stabilisation == Stabilisation::projection;
  EmbeddedStep& s = embedded_;
  double err = HUGE_VAL;
  try {
    dormand_prince_step(f_, t, y_, h, stages_, s);
    if (projected) independent_error(t_new, s.y, s.error);
    err = weighted_error(projected ? independent_ : s.error, s.y);
  } catch (const SingularJacobianError&) {
    if (!projected || h * 0.2 < options_.min_step) throw;
  }
  const double factor = std::isfinite(err) && err > 0 ? 0.9 * std::pow(err, -0.2) : 0.2;
  if (!(err <= 1.0)) {  // rejected (also when err is NaN)
    ++recorder_.trajectory().rejected_steps;
    h *= std::clamp(factor, 0.2, 0.9);
    if (h < options_.min_step)
      throw StepSizeError("the adaptive step fell below min_step = " + readable(options_.min_step) + " s " +
                              at(t, step_) + ": the problem is too stiff or singular here" +
                              (dependent_.empty() ? "" : " (C_q loses rank in " + model_.describe_row(dependent_.front()) + ")"),
                          t, step_);
    return false;
  }
  y_new = s.y;
  if (projected) project(y_new, t_new);
  h_next = std::min(h * std::clamp(factor, 0.2, 5.0), options_.max_step);
  return true;
}

// Dormand-Prince's own continuous extension of the step just taken from (t, y_) (Hairer, Norsett
// and Wanner, Solving Ordinary Differential Equations I, section II.6; dopri5's CONTD5): order 4
// inside the step from its seven stages, with no more evaluations, where the cubic Hermite
// extension from the two ends is order 3 (its error, h^4 |y''''| / 384, was 3.6e-5 m on the
// 4-window A02 chain at rtol 1e-6, ten times the error at the ends of the steps). It is set up
// only where the stages in stages_.k are the step's: y5 - y and y5 - y4 rebuilt from them agree
// with the step's own (M04T3 writes them; else the Hermite extension is used). The
// projection's correction of the end, y_new - y5, is spread linearly over the step, so that the
// extension meets the recorded end.
bool Simulation::dense_output(double h, const VecX& y_new) {
  using DP = DormandPrince;
  static constexpr double d[7] = {-12715105075.0 / 11282082432.0, 0.0, 87487479700.0 / 32700410799.0,
                                  -10690763975.0 / 1880347072.0,  701980252875.0 / 199316789632.0,
                                  -1453857185.0 / 822651844.0,    69997945.0 / 29380423.0};
  const auto& k = stages_.k;
  const EmbeddedStep& s = embedded_;
  for (const VecX& slope : k)
    if (slope.size() != y_.size()) return false;
  if (s.y.size() != y_.size() || s.error.size() != y_.size()) return false;
  VecX& ydiff = dense_[0];
  VecX& error = dense_[1];
  ydiff.setZero(y_.size());
  error.setZero(y_.size());
  dense_[4].setZero(y_.size());
  for (int i = 0; i < DP::stages; ++i) {
    ydiff += h * DP::b[i] * k[i];
    error += h * (DP::b[i] - DP::b_hat[i]) * k[i];
    dense_[4] += h * d[i] * k[i];
  }
  const double tolerance = 1e-10 * (ydiff.cwiseAbs().maxCoeff() + (s.y - y_).cwiseAbs().maxCoeff()) +
                           1e-13 * y_.cwiseAbs().maxCoeff() + 1e-300;  // sums taken in another order
  if (!((s.y - y_ - ydiff).cwiseAbs().maxCoeff() <= tolerance) ||
      !((s.error - error).cwiseAbs().maxCoeff() <= 1e-8 * error.cwiseAbs().maxCoeff() + tolerance))
    return false;
  ydiff = s.y - y_;
  dense_[2] = h * k[0] - ydiff;               // bspl
  dense_[3] = ydiff - h * k[6] - dense_[2];   // k[6] = f(t + h, y5)
  dense_[5] = y_new - s.y;                    // the projection's correction of the end
  return true;
}

VecX Simulation::dense(double theta) const {
  const double rest = 1.0 - theta;
  return y_ + theta * (dense_[0] + rest * (dense_[2] + theta * (dense_[3] + rest * dense_[4])) + dense_[5]);
}

// Output times inside the step take Dormand-Prince's continuous extension (dense_output), or
// else the step's cubic Hermite extension, from y and y' at both ends (two more evaluations,
// only for a step that holds one).
void Simulation::record_step(double t, double t_new, double h, const VecX& y_new) {
  if (!recorder_.records_in(t_new)) return;
  const bool dense = options_.integrator == Integrator::dormand_prince && dense_output(h, y_new);
  VecX f_old, f_new;
  recorder_.after_step(t, t_new, h, step_, [&](double t_out) {
    if (t_out == t_new) return sample(t_new, y_new);
    if (dense) return sample(t_out, this->dense((t_out - t) / h));
    if (!f_new.size()) {
      f_old = rhs(t, y_);
      f_new = rhs(t_new, y_new);
    }
    return sample(t_out, hermite(y_, f_old, y_new, f_new, h, (t_out - t) / h));
  });
}

// A fixed-step run takes its steps at t0 + j h (the last one shortened to end at t_end), except
// next to a rank loss (SingularInstant); the time is never accumulated.
Trajectory Simulation::run() {
  rhs(t0_, y_);  // checks the initial state: a locked mechanism throws here, with its rows
  started_ = true;
  recorder_.start(sample(t0_, y_));
  const double span = t_end_ - t0_;
  const double tiny = 1e-12 * std::max(std::abs(t0_), std::abs(t_end_)) + 1e-14 * span;
  const bool adaptive = options_.integrator == Integrator::dormand_prince;
  // the end of the next fixed step: a grid point, or t_end for the last one (a remainder of 1e-10
  // of the span is not a step of its own)
  auto grid_step = [&](double t) {
    const double t_grid = singular_.next_grid_point(t);
    SingularInstant::Step s = singular_.step_from(t, t_grid >= t_end_ - 1e-10 * span ? t_end_ : t_grid);
    if (s.end >= t_end_ - 1e-10 * span) s = {t_end_};
    if (s.spans) recorder_.trajectory().stepped_over.push_back(s.instant);
    return s;
  };
  double t = t0_, h = options_.step;
  while (t < t_end_ - tiny) {
    double t_new = 0, h_next = h;
    VecX& y_new = y_new_;
    if (adaptive) {
      h = std::min(h, t_end_ - t);
      t_new = t_end_ - t - h <= tiny ? t_end_ : t + h;
      if (!adaptive_step(t, h, t_new, y_new, h_next)) continue;
    } else {
      const SingularInstant::Step s = grid_step(t);
      t_new = s.end;
      h = h_next = t_new - t;
      // a step that spans a rank loss is not halved: a half would end at the instant
      advance(t, y_, t_new, s.spans ? kMaxHalvings : 0, HUGE_VAL, y_new);
    }
    ++step_;
    ++recorder_.trajectory().steps;
    record_step(t, t_new, h, y_new);
    y_.swap(y_new);
    t = t_new;
    h = h_next;
  }
  return recorded();
}

Trajectory Simulation::recorded() {
  Trajectory& out = recorder_.trajectory();
  out.rank_deficits = std::move(deficits_);
  return std::move(out);
}

}  // namespace

SimulationOutcome simulate_keeping(const Model& model, const VecX& q0, const VecX& qd0, double t0, double t_end,
                                   const SimulationOptions& options) {
  const int n = model.num_coordinates();
  Model::check_size(q0, n, "q0", "simulate");
  Model::check_size(qd0, n, "qd0", "simulate");
  check_options(options, t0, t_end);
  check_initial_state(model, q0, qd0, t0, "simulate");
  Simulation simulation(model, q0, qd0, t0, t_end, options);
  SimulationOutcome out;
  try {
    out.trajectory = simulation.run();
  } catch (...) {  // any failure once the run has started: kept with the points before it
    out.error = std::current_exception();
    out.trajectory = simulation.recorded();
  }
  return out;
}

Trajectory simulate(const Model& model, const VecX& q0, const VecX& qd0, double t0, double t_end,
                    const SimulationOptions& options) {
  SimulationOutcome out = simulate_keeping(model, q0, qd0, t0, t_end, options);
  if (out.error) std::rethrow_exception(out.error);
  return std::move(out.trajectory);
}

}  // namespace fmbd
