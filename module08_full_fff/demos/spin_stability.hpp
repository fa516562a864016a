#pragma once
// Stability of the spin-up beam in steady spin (demo spin_up_beam, `--threshold on`).
//
// After the spin-up the hub turns at a constant rate Omega. The beam's elastic coordinates q_f
// are then the model's only degrees of freedom (the frame follows from the clamp), and its
// equations do not depend on the hub's angle: the state y = (q_f, q_f_dot) obeys an autonomous
// first-order system y_dot = f(y). Its value is found from the model itself: the example built
// with a spin-up time of zero (theta = Omega t, theta_dot = Omega from t = 0) and the initial
// elastic state y, whose frame coordinates and velocities the builder makes consistent, and then
// forward dynamics at t = 0.
//
// Steady spin is the equilibrium f(q_f*, 0) = 0 (Newton on q_f). The Jacobian of f there, by
// central differences, has eigenvalues in +/- pairs (a gyroscopic system); steady spin is stable
// while every real part is zero and loses stability where a pair becomes real (divergence). The
// threshold is the lowest spin rate with a real part above `growth_tolerance`, bracketed by a
// scan and bisected.
//
// The time simulation checks the linearisation: steady spin at a given rate, started with the
// tip moved by `kick` along the softest eigenvector, stays near steady spin below the threshold
// and leaves it exponentially above, at the rate of the largest real part.

#include <Eigen/Dense>
#include <vector>

#include "fmbd/flexible_examples.hpp"
#include "fmbd/simulation.hpp"

namespace fmbd::spin {

/// The tip's position across the hub's radial line, in the hub frame [m]; points "beam tip" and
/// body "hub" of spin_up_beam().
double tip_deflection(const FlexibleExample& ex, const VecX& q);

/// Every run of the demo: Dormand-Prince (rtol 1e-8, atol 1e-10, steps up to 0.01 s) with
/// projection on the constraints.
SimulationOptions run_options();

/// Real parts below this count as zero (round-off and the differencing step) [1/s].
constexpr double growth_tolerance = 1e-3;

/// The linearisation about steady spin at p.spin_rate.
struct SteadySpin {
  VecX q_f;                        ///< elastic coordinates of steady spin
  MatX jacobian;                   ///< d f / d y at (q_f, 0), 2 n_f x 2 n_f
  Eigen::VectorXcd eigenvalues;    ///< of the Jacobian [1/s]
  Eigen::MatrixXcd eigenvectors;   ///< columns, in the order of the eigenvalues
  double growth = 0.0;             ///< largest real part [1/s]
};

/// Steady spin of the beam of `p` (its spin rate; spin-up time and initial state are ignored)
/// with the body of `make`, linearised. Throws std::runtime_error if Newton does not converge.
SteadySpin steady_spin(SpinUpBeamParameters p, const BodyFactory& make);

/// The lowest spin rate in (0, upper] at which steady spin loses stability, to `tolerance`
/// [rad/s]: a scan in steps of `step`, then bisection. Returns NaN if it is stable up to `upper`.
double stability_threshold(const SpinUpBeamParameters& p, const BodyFactory& make, double upper, double step = 0.25,
                           double tolerance = 1e-4);

/// A run from steady spin with a kicked tip.
struct KickedRun {
  std::vector<double> t;          ///< [s]
  std::vector<double> deviation;  ///< tip deflection in the hub frame minus steady spin's [m]
  double peak = 0.0;              ///< largest |deviation| [m]
  double growth = 0.0;            ///< fitted growth rate of |deviation| from 10 to 100 kicks [1/s]; 0 if it stays below
};

/// Steady spin at p.spin_rate for `t_end` seconds after a kick of the tip by `kick` metres along
/// the softest eigenvector (the one of the eigenvalue nearest zero). The run stops once the tip
/// has left steady spin by `limit` metres.
KickedRun kicked_run(SpinUpBeamParameters p, const BodyFactory& make, double kick, double t_end, double limit);

}  // namespace fmbd::spin
