#include <Eigen/QR>
#include <sstream>
#include <stdexcept>

#include "fmbd/dof.hpp"
#include "fmbd/inverse_dynamics.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/linear_solve.hpp"

namespace fmbd {

VecX solve_multipliers(const Model& model, const MatX& Cq, const VecX& rhs) {
  Model::check_size(rhs, static_cast<int>(Cq.cols()), "right-hand side", "solve_multipliers");
  if (Cq.rows() != Cq.cols()) {
    std::ostringstream s;
    s << "inverse dynamics needs a kinematically driven model (0 degrees of freedom), but it has m = "
      << Cq.rows() << " constraint equations for n = " << Cq.cols() << " coordinates";
    if (Cq.rows() < Cq.cols())
      s << ": " << Cq.cols() - Cq.rows() << " degree(s) of freedom without a driver; use forward dynamics.";
    else
      s << ": remove the " << Cq.rows() - Cq.cols() << " redundant equation(s).";
    throw std::invalid_argument(s.str());
  }
  Eigen::CompleteOrthogonalDecomposition<MatX> cod(Cq.transpose());
  cod.setThreshold(rank_tolerance);
  if (cod.rank() < Cq.rows()) {
    const std::vector<int> rows = dependent_rows(Cq);
    std::ostringstream s;
    s << "inverse dynamics: the multipliers are not unique because constraint rows are dependent (rank "
      << cod.rank() << " < " << Cq.rows() << "):";
    for (int r : rows) s << " row " << r << ": " << model.describe_row(r) << ";";
    s << " remove redundant constraints, or move the mechanism away from a singular position.";
    throw SingularJacobianError(s.str(), rows);
  }
  return cod.solve(rhs);
}

InverseDynamicsSolution inverse_dynamics(const Model& model, const VecX& q_guess, const std::vector<double>& times) {
  InverseDynamicsSolution out{kinematic_analysis(model, q_guess, times), {}};
  const KinematicSolution& k = out.kinematics;
  for (std::size_t i = 0; i < k.t.size(); ++i)
    out.lambda.push_back(lagrange_multipliers(model, k.q[i], k.qd[i], k.qdd[i], k.t[i]));
  return out;
}

}  // namespace fmbd
