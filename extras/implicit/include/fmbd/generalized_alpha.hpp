#pragma once
// Implicit time integration by the generalised-alpha method (extra: extras/implicit), for stiff
// models such as flexible bodies with many modes, where the step of an explicit integrator is
// bounded by the highest eigenfrequency (RK4: h < 2 sqrt(2) / omega_max for undamped modes) rather
// than by accuracy.
//
// The equations of motion are integrated as the index-3 DAE
//
//   M(q) q_ddot + C_q(q, t)^T lambda = Q_a(q, q_dot, t),     C(q, t) = 0,
//
// without differentiating the constraints: C = 0 holds at position level at every step.
//
// ---- The method (Chung & Hulbert 1993, in the form of Arnold & Bruls 2007) ------------------
//
// Besides q_n, v_n = q_dot_n and the true accelerations q_ddot_n, the method carries an
// acceleration-like variable a_n, defined by
//
//   (1 - alpha_m) a_{n+1} + alpha_m a_n = (1 - alpha_f) q_ddot_{n+1} + alpha_f q_ddot_n,
//
// and advances positions and velocities with Newmark's formulas on a:
//
//   q_{n+1} = q_n + h v_n + h^2 (1/2 - beta) a_n + h^2 beta a_{n+1},
//   v_{n+1} = v_n + h (1 - gamma) a_n + h gamma a_{n+1}.
//
// The equations of motion and the constraints are imposed at t_{n+1} on (q_{n+1}, v_{n+1},
// q_ddot_{n+1}, lambda_{n+1}). The start is a_0 = q_ddot_0, lambda_0 from the augmented system
// of forward_dynamics() at the (consistent) initial state.
//
// ---- Parameters ------------------------------------------------------------------------------
//
// One parameter, the spectral radius rho_inf in [0, 1] of the amplification matrix for
// omega h -> infinity, sets all four (second-order accuracy and optimal high-frequency damping):
//
//   alpha_m = (2 rho_inf - 1) / (rho_inf + 1),     alpha_f = rho_inf / (rho_inf + 1),
//   gamma   = 1/2 + alpha_f - alpha_m,             beta    = (gamma + 1/2)^2 / 4.
//
// rho_inf = 1 is the trapezoidal rule (alpha_m = alpha_f = gamma = 1/2, beta = 1/4): no numerical
// dissipation, the energy of a linear undamped system is conserved exactly. rho_inf < 1 damps
// the modes with omega h >> 1 by about a factor rho_inf per step while the low modes (omega h
// << 1) keep their amplitude to O((omega h)^3) per step; rho_inf = 0 annihilates the highest
// modes in one step. The default 0.8 is the usual compromise for flexible multibody models.
// The method is second-order accurate in q and q_dot for every rho_inf.
//
// ---- Newton iteration ------------------------------------------------------------------------
//
// The unknowns of a step are (q_{n+1}, lambda_{n+1}); v_{n+1}, a_{n+1} and q_ddot_{n+1} follow
// from q_{n+1} through the formulas above, so that a correction dq of the positions changes
//
//   v_{n+1} by gamma' dq,   q_ddot_{n+1} by beta' dq,
//   gamma' = gamma / (beta h),   beta' = (1 - alpha_m) / ((1 - alpha_f) beta h^2).
//
// The predictor keeps the acceleration and the multipliers of the last step (q_ddot_{n+1} =
// q_ddot_n, lambda_{n+1} = lambda_n). With the residual r = M q_ddot + C_q^T lambda - Q_a, each
// iteration solves
//
//   [ beta h^2 S_t   C_q^T ] [ dq ]     [ beta h^2 r ]
//   [ C_q            0     ] [ mu ] = - [ C          ],     lambda += mu / (beta h^2),
//
// i.e. the Newton system on (q, lambda) with the equation-of-motion rows multiplied by beta h^2
// (equivalently, the constraint rows scaled by 1/(beta h^2) relative to them) and the unknown
// mu = beta h^2 dlambda (the scaling of Bottasso, Bauchau and Cardona), so that every block is of
// order one: without it the condition number grows like 1/h^4.
//
// The iteration matrix S_t = dr/dq_{n+1} = M beta' + D_t gamma' + K_t (D_t = -dQ_a/dq_dot,
// K_t = d(M q_ddot + C_q^T lambda - Q_a)/dq) is computed by FINITE DIFFERENCES: column j is the
// forward difference of r when q_j moves by eps_j and, consistently, (q_dot)_j by gamma' eps_j and
// (q_ddot)_j by beta' eps_j, with eps_j = sqrt(machine epsilon) max(1, |q_j|). It thus contains
// every term of the tangent (dM/dq q_ddot, the geometric stiffness of the constraints,
// d(C_q^T lambda)/dq, the quadratic velocity forces) at the cost of n evaluations of r per
// iteration, and needs no derivative of the force elements or of the flexible bodies. C_q is
// analytic (evaluate_constraints). The matrix is rebuilt at every iteration (full Newton) or,
// with jacobian_update = once_per_step, only at the first iteration of a step (modified Newton:
// cheaper per iteration, linear convergence).
//
// The iteration has converged when the weighted RMS norm of the position correction,
// sqrt(mean((dq_k / (atol + rtol |q_k|))^2)) (error_norm() of integrators.hpp), is <= 1. A step
// that does not converge within max_iterations throws NewtonIterationError with the time, the
// step and the residual norm |(beta h^2 r, C)|.
//
// ---- Drift ------------------------------------------------------------------------------------
//
// C(q, t) = 0 is part of every Newton solve, so positions stay on the constraint manifold to the
// Newton tolerance, without Baumgarte terms or position projection. The velocity constraint
// C_q q_dot + C_t = 0 is satisfied only to O(h^2) (it is not imposed); with project_velocities
// each accepted step moves q_dot onto it by the mass-weighted projection of module 4
// (project_velocities()). That keeps the velocity drift at round-off for the monitors and the
// energy balance but changes v_{n+1} after the fact (not a_{n+1}); the order of accuracy stays 2.
//
// ---- Errors -----------------------------------------------------------------------------------
//
// The state or the residual becoming NaN or Inf throws IntegrationError naming the time, the
// step and the coordinate (or the equation); non-convergence throws NewtonIterationError. A
// singular iteration matrix throws SingularJacobianError with the dependent rows and the time
// when C_q is rank-deficient (a locked or redundant mechanism), and IntegrationError when C_q has
// full rank (the step is too large for the stiffness, or the iteration diverged). The integrator
// never returns NaN output.

#include "fmbd/simulation.hpp"

namespace fmbd {

/// How often the generalised-alpha iteration matrix is rebuilt (generalized_alpha.hpp).
enum class JacobianUpdate { every_iteration, once_per_step };

/// Options of the generalised-alpha method (generalized_alpha.hpp explains each one).
struct GeneralizedAlphaOptions {
  double rho_inf = 0.8;     ///< spectral radius at infinity, in [0, 1]; 1: no numerical damping
  double rtol = 1e-8;       ///< Newton: relative tolerance on the position correction
  double atol = 1e-10;      ///< Newton: absolute tolerance on the position correction
  int max_iterations = 10;  ///< Newton iterations per step before NewtonIterationError
  JacobianUpdate jacobian_update = JacobianUpdate::every_iteration;
  bool project_velocities = false;  ///< move q_dot onto C_q q_dot + C_t = 0 after each step
  /// Integrate the work of the drivers and the non-conservative forces (Trajectory::work_done);
  /// false: work_done stays empty, and the motion is the same (as SimulationOptions).
  bool integrate_work = true;
};

/// The Newton iteration of an implicit step (generalized_alpha) did not converge within
/// GeneralizedAlphaOptions::max_iterations: the message names the time, the step and the
/// residual norm.
class NewtonIterationError : public IntegrationError {
 public:
  NewtonIterationError(const std::string& message, double t, int step, int iterations, double residual)
      : IntegrationError(message, t, step), iterations(iterations), residual(residual) {}
  int iterations;   ///< iterations done
  double residual;  ///< |(beta h^2 r, C)| at the last iterate
};

/// The four parameters of the generalised-alpha method.
struct GeneralizedAlphaCoefficients {
  double alpha_m = 0.0;
  double alpha_f = 0.0;
  double gamma = 0.0;
  double beta = 0.0;

  /// The coefficients above for a spectral radius at infinity rho_inf in [0, 1]; throws
  /// std::invalid_argument outside that range.
  static GeneralizedAlphaCoefficients from_rho_inf(double rho_inf);
};

/// Integrates the model from the consistent state (q0, qd0) at t0 to t_end with the fixed step
/// `step` (steps at t0 + j step, the last one ending exactly at t_end) by the generalised-alpha
/// method with `options`. Records through simulate()'s Recorder, so the output is the same: at
/// every step with output_interval = 0, else on the grid t0 + k output_interval and at t_end
/// (between steps by cubic Hermite interpolation of q and q_dot), with q, q_dot, the step, T + V,
/// the work of the drivers (lambda^T C_t with the method's lambda_{n+1}) and non-conservative
/// forces (trapezoidal rule), |C| and |C_q q_dot + C_t|. Trajectory::steps counts the steps;
/// rejected_steps stays 0.
///
/// Throws std::invalid_argument for a non-positive step, t_end <= t0, rho_inf outside [0, 1],
/// non-positive tolerances, max_iterations < 1, a negative output_interval, wrong sizes, a
/// non-finite initial state or inconsistent initial conditions (check_initial_state());
/// IntegrationError, NewtonIterationError and SingularJacobianError as described above.
Trajectory generalized_alpha(const Model& model, const VecX& q0, const VecX& qd0, double t0, double t_end,
                             double step, const GeneralizedAlphaOptions& options = {},
                             double output_interval = 0.0);

}  // namespace fmbd
