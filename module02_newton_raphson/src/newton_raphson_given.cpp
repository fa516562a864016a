#include <Eigen/Cholesky>
#include <cmath>
#include <sstream>

#include "fmbd/constraints.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/newton_raphson.hpp"

namespace fmbd {

namespace {

// Row of C with the largest |C_r|, described.
std::string worst_row(const Model& model, const VecX& C) {
  if (C.size() == 0) return "none";
  Eigen::Index r = 0;
  C.cwiseAbs().maxCoeff(&r);
  std::ostringstream s;
  s << model.describe_row(static_cast<int>(r)) << " with |C| = " << std::abs(C(r));
  return s.str();
}

// Levenberg-Marquardt on 1/2 |C|^2 from q0: the smallest residual reachable near q0.
VecX least_squares(const Model& model, VecX q, double t) {
  double mu = 1e-3;
  VecX C = constraints(model, q, t);
  for (int k = 0; k < 200 && C.norm() > 1e-12; ++k) {
    const MatX Cq = constraint_jacobian(model, q, t);
    const VecX g = Cq.transpose() * C;
    if (g.norm() < 1e-14) break;  // stationary point of |C|^2
    MatX H = Cq.transpose() * Cq;
    H.diagonal().array() += mu * (1.0 + H.diagonal().array());
    const VecX q_try = q - H.ldlt().solve(g);
    const VecX C_try = constraints(model, q_try, t);
    if (C_try.allFinite() && C_try.norm() < C.norm()) {
      q = q_try;
      C = C_try;
      mu = std::max(mu / 3, 1e-12);
    } else {
      mu *= 4;
      if (mu > 1e12) break;
    }
  }
  return q;
}

}  // namespace

void throw_not_converged(const Model& model, const VecX& q_last, double t, const NewtonResult& progress) {
  const double residual = progress.residuals.empty() ? NAN : progress.residuals.back();
  // The diagnosis first, the long residual history last: one-line summaries keep the start.
  std::ostringstream s;
  s << "Newton-Raphson did not converge at t = " << t << " after " << progress.iterations
    << " iterations: |C| = " << residual << ". ";
  if (!std::isfinite(residual))
    s << "The iterates became NaN or Inf.";
  else {
    const std::vector<double>& r = progress.residuals;
    const bool diverging = r.size() >= 3 && r[r.size() - 1] > r[r.size() - 2] && r[r.size() - 2] > r[r.size() - 3];
    s << (diverging ? "The residual grew at each of the last steps: the iteration diverges, from a poor guess "
                      "or because the update has the wrong sign (it must solve C_q dq = -C)."
                    : "Try a better initial guess.")
      << " Largest residual in " << worst_row(model, constraints(model, q_last, t)) << ".";
  }
  s << " History of |C|:";
  for (double r : progress.residuals) s << ' ' << r;
  throw ConvergenceError(s.str(), progress.iterations, residual);
}

NewtonResult solve_positions(const Model& model, const VecX& q_guess, double t, const NewtonOptions& options) {
  try {
    return newton_raphson(model, q_guess, t, options);
  } catch (const KinematicsError&) {
    if (!q_guess.allFinite()) throw;
    const VecX q_best = least_squares(model, q_guess, t);
    const VecX C = constraints(model, q_best, t);
    const double scale = 1.0 + (q_guess.size() ? q_guess.cwiseAbs().maxCoeff() : 0.0);
    if (C.allFinite() && C.norm() > 1e3 * options.tolerance * scale) {
      std::ostringstream s;
      s << "unreachable configuration at t = " << t
        << ": the constraints cannot be satisfied near the guess; the closest configuration "
           "found leaves |C| = "
        << C.norm() << ", largest in " << worst_row(model, C)
        << ". The mechanism cannot close: check link lengths, driver values and the guess.";
      throw UnreachableConfigurationError(s.str(), C.norm());
    }
    throw;  // reachable: the original error (redundant rows, or a poor guess) stands
  }
}

}  // namespace fmbd
