#include "fmbd/linear_solve.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <sstream>

#include "fmbd/dof.hpp"
#include "fmbd/kinematic_errors.hpp"

namespace fmbd {

namespace {

std::string list_rows(const Model& model, const std::vector<int>& rows) {
  std::ostringstream s;
  for (std::size_t k = 0; k < rows.size(); ++k)
    s << (k ? "; " : "") << "row " << rows[k] << ": " << model.describe_row(rows[k]);
  return s.str();
}

void check_finite(const Model& model, const MatX& Cq, const VecX& rhs, const std::string& what) {
  for (Eigen::Index r = 0; r < Cq.rows(); ++r) {
    if (!Cq.row(r).allFinite() || !std::isfinite(rhs(r)))
      throw KinematicsError(what + ": C_q or the right-hand side is not finite (NaN or Inf) in row " +
                            std::to_string(r) + ": " + model.describe_row(static_cast<int>(r)));
  }
}

VecX solve(const Model& model, const MatX& Cq, const VecX& rhs, const std::string& what) {
  Model::check_size(rhs, static_cast<int>(Cq.rows()), "right-hand side", what.c_str());
  check_finite(model, Cq, rhs, what);
  Eigen::CompleteOrthogonalDecomposition<MatX> cod(Cq);
  cod.setThreshold(rank_tolerance);
  if (cod.rank() < Cq.rows()) {
    const std::vector<int> rows = dependent_rows(Cq);
    std::ostringstream s;
    s << what << ": the constraint Jacobian C_q (" << Cq.rows() << "x" << Cq.cols()
      << ") is singular, rank " << cod.rank() << " < " << Cq.rows()
      << " rows. Dependent rows: " << list_rows(model, rows)
      << ". Either constraints are redundant, or the mechanism is at a singular (dead-point) position.";
    throw SingularJacobianError(s.str(), rows);
  }
  return cod.solve(rhs);
}

}  // namespace

std::vector<int> dependent_rows(const MatX& Cq) {
  std::vector<int> rows;
  if (Cq.rows() == 0) return rows;
  Eigen::JacobiSVD<MatX> svd(Cq, Eigen::ComputeFullU);
  const VecX& sigma = svd.singularValues();
  const double cut = rank_tolerance * (sigma.size() ? sigma(0) : 0.0);
  Eigen::Index rank = 0;
  while (rank < sigma.size() && sigma(rank) > cut) ++rank;
  if (rank == Cq.rows()) return rows;
  const MatX left_null = svd.matrixU().rightCols(Cq.rows() - rank);  // y with y^T C_q = 0
  for (Eigen::Index r = 0; r < Cq.rows(); ++r)
    if (left_null.row(r).norm() > 1e-8) rows.push_back(static_cast<int>(r));
  return rows;
}

VecX solve_square(const Model& model, const MatX& Cq, const VecX& rhs, const std::string& what) {
  if (Cq.rows() < Cq.cols()) {
    std::ostringstream s;
    s << what << ": needs a kinematically driven model (0 degrees of freedom), but it has m = " << Cq.rows()
      << " constraint equations for n = " << Cq.cols() << " coordinates: " << Cq.cols() - Cq.rows()
      << " degree(s) of freedom have no driver. Add drivers, or use forward dynamics (module 4).";
    throw std::invalid_argument(s.str());
  }
  return solve(model, Cq, rhs, what);  // m > n: rank < m, so the dependent rows are reported
}

VecX solve_min_norm(const Model& model, const MatX& Cq, const VecX& rhs, const std::string& what) {
  return solve(model, Cq, rhs, what);
}

}  // namespace fmbd
