// Static solution with a diagnosis of missing supports (given code, module 5).
#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>
#include <sstream>

#include "fmbd/modal.hpp"

namespace fmbd {

namespace {

// Rigid motions of the plane, as (a, b, w): node k moves by (a - w y_k, b + w x_k) and turns by w.
// A rigid motion is allowed by the supports if it moves no fixed DOF. Returns a basis of the
// allowed ones (3 x d).
MatX free_rigid_motions(const FeModel& fe, const DofMap& map) {
  std::vector<bool> is_free(map.num_dofs, false);
  for (int i : map.free) is_free[i] = true;
  std::vector<Eigen::RowVector3d> rows;
  for (int k = 0; k < fe.num_nodes(); ++k) {
    const Vec2& x = fe.nodes()[k];
    if (!is_free[3 * k + 0]) rows.push_back(Eigen::RowVector3d(1.0, 0.0, -x.y()));
    if (!is_free[3 * k + 1]) rows.push_back(Eigen::RowVector3d(0.0, 1.0, x.x()));
    if (!is_free[3 * k + 2]) rows.push_back(Eigen::RowVector3d(0.0, 0.0, 1.0));
  }
  if (rows.empty()) return Eigen::Matrix3d::Identity();
  MatX C(rows.size(), 3);
  for (std::size_t r = 0; r < rows.size(); ++r) C.row(r) = rows[r];
  Eigen::FullPivLU<MatX> lu(C);
  lu.setThreshold(1e-10);
  if (lu.rank() == 3) return MatX(3, 0);
  return lu.kernel();
}

std::string describe_motion(const Eigen::Vector3d& m, double size) {
  std::ostringstream s;
  s.precision(4);
  if (std::abs(m.z()) * size < 1e-9 * m.head<2>().norm()) {
    const Vec2 d = m.head<2>().normalized();
    if (std::abs(d.y()) < 1e-12) return "translation x";
    if (std::abs(d.x()) < 1e-12) return "translation y";
    s << "translation along (" << d.x() << ", " << d.y() << ")";
  } else {
    // The centre c does not move: a - w c_y = 0, b + w c_x = 0.
    s << "rotation about (" << -m.y() / m.z() << ", " << m.x() / m.z() << ")";
  }
  return s.str();
}

}  // namespace

VecX static_solve(const FeModel& fe, const FeMatrices& matrices, const DofMap& map, const VecX& F_full) {
  if (F_full.size() != fe.num_dofs() || matrices.K.rows() != fe.num_dofs() || matrices.K.cols() != fe.num_dofs() ||
      map.num_dofs != fe.num_dofs()) {
    std::ostringstream s;
    s << "static_solve: the model has " << fe.num_dofs() << " DOFs, but F has " << F_full.size() << ", K has "
      << matrices.K.rows() << " rows and the DofMap " << map.num_dofs;
    throw std::invalid_argument(s.str());
  }
  if (!F_full.allFinite()) throw std::invalid_argument("static_solve: the load vector F is not finite");
  for (int r = 0; r < map.num_free(); ++r)
    if (map.free[r] < 0 || map.free[r] >= map.num_dofs || (r > 0 && map.free[r] <= map.free[r - 1]))
      throw std::invalid_argument("static_solve: DofMap::free must list DOFs 0 .. " + std::to_string(map.num_dofs - 1) +
                                  " in increasing order; entry " + std::to_string(r) + " is " +
                                  std::to_string(map.free[r]));

  const MatX motions = free_rigid_motions(fe, map);
  if (motions.cols() > 0) {
    double size = 0.0;
    for (const Vec2& x : fe.nodes()) size = std::max(size, x.norm());
    std::ostringstream s;
    s << "static_solve: K is singular: the supports leave " << motions.cols() << " rigid-body motion"
      << (motions.cols() > 1 ? "s" : "") << " free (";
    if (motions.cols() == 3) {
      s << "translation x, translation y, rotation";
    } else {
      for (Eigen::Index c = 0; c < motions.cols(); ++c)
        s << (c ? ", " : "") << describe_motion(motions.col(c), std::max(size, 1.0));
    }
    s << "); clamp or hinge more nodes";
    throw SingularStiffness(s.str());
  }

  const MatX K_ff = reduce(matrices.K, map);
  const VecX F_f = reduce(F_full, map);
  Eigen::LLT<MatX> llt(K_ff);
  if (llt.info() != Eigen::Success)
    throw SingularStiffness(
        "static_solve: K_ff is not positive definite although the supports fix every rigid motion; "
        "is the frame in one connected piece?");
  return expand(VecX(llt.solve(F_f)), map);
}

}  // namespace fmbd
