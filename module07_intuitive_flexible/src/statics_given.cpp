// Static equilibrium by Newton's method (given code, module 7).
#include "fmbd/statics.hpp"

#include <Eigen/LU>
#include <cmath>
#include <string>

#include "fmbd/applied_forces.hpp"
#include "fmbd/constraints.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/linear_solve.hpp"

namespace fmbd {

StaticSolution static_equilibrium(const Model& model, const VecX& q_guess, double t, const StaticOptions& options) {
  const int n = model.num_coordinates(), m = model.num_constraints();
  Model::check_size(q_guess, n, "q_guess", "static_equilibrium");
  const VecX zero = VecX::Zero(n);
  StaticSolution s{q_guess, VecX::Zero(m), 0};
  auto residual = [&](const VecX& q, const VecX& lambda, ConstraintEvaluation& e) {
    e = evaluate_constraints(model, q, t);
    VecX r(n + m);
    r << applied_forces(model, q, zero, t) - e.Cq.transpose() * lambda, e.C;
    return r;
  };
  ConstraintEvaluation e;
  VecX r = residual(s.q, s.lambda, e);
  const double scale = std::max(1.0, applied_forces(model, s.q, zero, t).norm());
  for (; s.iterations < options.max_iterations; ++s.iterations) {
    if (!r.allFinite())
      throw ConvergenceError("static_equilibrium: the residual is not finite after " + std::to_string(s.iterations) +
                                 " iterations",
                             s.iterations, r.norm());
    if (r.norm() <= options.tolerance * scale) return s;
    // Tangent: [dQ/dq - d(C_q^T lambda)/dq, -C_q^T; C_q, 0], the q-derivatives by central differences.
    MatX J = MatX::Zero(n + m, n + m);
    for (int k = 0; k < n; ++k) {
      const double h = 1e-7 * std::max(1.0, std::abs(s.q(k)));
      VecX qp = s.q, qm = s.q;
      qp(k) += h;
      qm(k) -= h;
      ConstraintEvaluation ep, em;
      J.block(0, k, n, 1) = (residual(qp, s.lambda, ep).head(n) - residual(qm, s.lambda, em).head(n)) / (2 * h);
    }
    J.block(0, n, n, m) = -e.Cq.transpose();
    J.block(n, 0, m, n) = e.Cq;
    Eigen::FullPivLU<MatX> lu(J);
    if (!lu.isInvertible()) {
      const std::vector<int> rows = dependent_rows(e.Cq);
      throw SingularJacobianError("static_equilibrium: the tangent is singular (a motion without stiffness?)", rows);
    }
    const VecX dx = lu.solve(-r);
    s.q += dx.head(n);
    s.lambda += dx.tail(m);
    r = residual(s.q, s.lambda, e);
  }
  if (r.allFinite() && r.norm() <= options.tolerance * scale) return s;  // converged on the last step
  throw ConvergenceError("static_equilibrium did not converge in " + std::to_string(options.max_iterations) +
                             " iterations (residual " + std::to_string(r.norm()) + ")",
                         options.max_iterations, r.norm());
}

}  // namespace fmbd
