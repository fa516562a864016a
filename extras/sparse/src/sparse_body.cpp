// A flexible body from an imported FE model (given code, module 8, extra).
#include "fmbd/sparse_body.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "fmbd/errors.hpp"

namespace fmbd {

namespace {

const char* const kDofNames[3] = {"u_x", "u_y", "psi"};

Mat2 turn(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return (Mat2() << c, -s, s, c).finished();
}

// The checks of the header on M, K and the node table; `where` starts each message.
void check_model(const SparseFeModel& model, const std::string& where) {
  const Eigen::Index n = model.K.rows();
  if (model.K.cols() != n || model.M.rows() != n || model.M.cols() != n || n == 0)
    throw std::invalid_argument(where + ": M is " + std::to_string(model.M.rows()) + " x " +
                                std::to_string(model.M.cols()) + " and K is " + std::to_string(model.K.rows()) +
                                " x " + std::to_string(model.K.cols()) + "; both must be n x n with n > 0");
  const NodeTable& table = model.table;
  if (table.nodes.size() != table.dofs.size())
    throw std::invalid_argument(where + ": the node table has " + std::to_string(table.nodes.size()) +
                                " coordinates but " + std::to_string(table.dofs.size()) + " sets of DOF numbers");
  if (table.nodes.empty()) throw std::invalid_argument(where + ": the node table has no nodes");
  std::vector<int> owner(static_cast<std::size_t>(n), -1);
  for (std::size_t k = 0; k < table.nodes.size(); ++k) {
    if (!table.nodes[k].allFinite())
      throw std::invalid_argument(where + ": node " + std::to_string(k) + " has coordinates that are not finite");
    for (int d = 0; d < 3; ++d) {
      const int r = table.dofs[k][d];
      if (r < -1 || r >= n)
        throw std::invalid_argument(where + ": node " + std::to_string(k) + ": the DOF number " + std::to_string(r) +
                                    " of " + kDofNames[d] + " is outside -1 .. " + std::to_string(n - 1));
      if (r < 0) continue;
      if (owner[r] >= 0)
        throw std::invalid_argument(where + ": row " + std::to_string(r) + " is named twice in the node table (node " +
                                    std::to_string(owner[r] / 3) + " " + kDofNames[owner[r] % 3] + " and node " +
                                    std::to_string(k) + " " + kDofNames[d] + ")");
      owner[r] = static_cast<int>(3 * k) + d;
    }
  }
  for (Eigen::Index r = 0; r < n; ++r)
    if (owner[r] < 0)
      throw std::invalid_argument(where + ": row " + std::to_string(r) +
                                  " of M and K belongs to no node of the table; the FFRF needs the motion of every "
                                  "DOF with the frame (internal DOFs are not supported)");
}

void check_ffrf_basis(const SparseFeModel& model, const ReducedBasis& basis, const std::string& where) {
  if (basis.num_rigid != 3 || basis.Phi.cols() < 3 || basis.Phi.rows() != model.num_dofs())
    throw std::invalid_argument(where + ": the basis must have num_rigid = 3 (sparse_ffrf_basis of a "
                                "sparse_craig_bampton basis) and " + std::to_string(model.num_dofs()) +
                                " rows (the DOFs of the model), got num_rigid = " + std::to_string(basis.num_rigid) +
                                ", " + std::to_string(basis.Phi.rows()) + " rows and " +
                                std::to_string(basis.Phi.cols()) + " columns");
}

// Rigid-body modes about the centroid for nodes at `x` (M06T1 with the table's DOF numbers).
RigidBodyModes rigid_modes(const std::vector<Vec2>& x, const SparseFeModel& model, const std::string& where) {
  const Eigen::Index n = model.num_dofs();
  const std::vector<NodeDofNumbers>& dofs = model.table.dofs;
  RigidBodyModes rigid;
  MatX& Phi = rigid.Phi_r;
  Phi = MatX::Zero(n, 3);
  VecX r_o = VecX::Zero(n);
  for (std::size_t k = 0; k < x.size(); ++k) {
    const NodeDofNumbers& d = dofs[k];
    if (d[0] >= 0) {
      Phi(d[0], 0) = 1.0;
      r_o(d[0]) = -x[k].y();
    }
    if (d[1] >= 0) {
      Phi(d[1], 1) = 1.0;
      r_o(d[1]) = x[k].x();
    }
    if (d[2] >= 0) r_o(d[2]) = 1.0;
  }
  const MatX M_t = model.M * Phi.leftCols(2);
  rigid.mass = Phi.col(0).dot(M_t.col(0));
  const double m_y = Phi.col(1).dot(M_t.col(1)), m_xy = Phi.col(0).dot(M_t.col(1));
  if (!(rigid.mass > 0.0))
    throw std::invalid_argument(where + ": the model has no translational mass (t_x^T M t_x = " +
                                readable(rigid.mass) + ")");
  if (std::abs(m_y - rigid.mass) > 1e-10 * rigid.mass || std::abs(m_xy) > 1e-10 * rigid.mass)
    throw std::invalid_argument(where + ": the translational masses differ (t_x^T M t_x = " +
                                readable(rigid.mass) + ", t_y^T M t_y = " + readable(m_y) +
                                ", t_x^T M t_y = " + readable(m_xy) +
                                "); is a node in the matrices with only one of u_x, u_y?");
  const VecX M_ro = model.M * r_o;
  rigid.centroid = Vec2(Phi.col(1).dot(M_ro), -Phi.col(0).dot(M_ro)) / rigid.mass;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const NodeDofNumbers& d = dofs[k];
    const Vec2 s = x[k] - rigid.centroid;
    if (d[0] >= 0) Phi(d[0], 2) = -s.y();
    if (d[1] >= 0) Phi(d[1], 2) = s.x();
    if (d[2] >= 0) Phi(d[2], 2) = 1.0;
  }
  rigid.inertia = Phi.col(2).dot(model.M * Phi.col(2));
  return rigid;
}

std::vector<Vec2> shifted(const std::vector<Vec2>& x, const Vec2& shift) {
  std::vector<Vec2> out;
  out.reserve(x.size());
  for (const Vec2& p : x) out.push_back(p + shift);
  return out;
}

// Phi^T M Phi must be positive definite: no column without M-norm, none a combination of others.
void check_independent(const MatX& M_bar, const std::string& where) {
  const VecX d = M_bar.diagonal();
  for (Eigen::Index c = 0; c < d.size(); ++c)
    if (!(d(c) > 0.0))
      throw std::invalid_argument(where + ": column " + std::to_string(c) +
                                  " of the basis has no M-norm (Phi^T M Phi is singular)");
  const VecX s = d.cwiseSqrt().cwiseInverse();
  const MatX scaled = s.asDiagonal() * (0.5 * (M_bar + M_bar.transpose())) * s.asDiagonal();
  const double lowest = Eigen::SelfAdjointEigenSolver<MatX>(scaled, Eigen::EigenvaluesOnly).eigenvalues()(0);
  if (!(lowest > 1e-12))
    throw std::invalid_argument(where + ": the columns of the basis are linearly dependent in the M-norm "
                                "(Phi^T M Phi is singular: smallest eigenvalue " + readable(lowest) +
                                " of its scaled form); make the basis with sparse_ffrf_basis");
}

}  // namespace

RigidBodyModes sparse_rigid_body_modes(const SparseFeModel& model) {
  check_model(model, "sparse_rigid_body_modes");
  return rigid_modes(model.table.nodes, model, "sparse_rigid_body_modes");
}

ReducedBasis sparse_ffrf_basis(const SparseFeModel& model, const ReducedBasis& basis) {
  const std::string where = "sparse_ffrf_basis";
  check_model(model, where);
  if (basis.Phi.rows() != model.num_dofs())
    throw std::invalid_argument(where + ": the basis has " + std::to_string(basis.Phi.rows()) +
                                " rows, the model has " + std::to_string(model.num_dofs()) + " DOFs");
  const SparseMat& M = model.M;
  const SparseMat& K = model.K;

  // 1. Remove the rigid content of every column.
  const MatX Phi_r = rigid_modes(model.table.nodes, model, where).Phi_r;
  const MatX MPhi_r = M * Phi_r;
  const Eigen::Matrix3d M_rr = Phi_r.transpose() * MPhi_r;
  const MatX T = basis.Phi - Phi_r * M_rr.ldlt().solve(MPhi_r.transpose() * basis.Phi);

  // 2. Unit M-norm; drop the columns that were rigid motions.
  const MatX MPhi = M * basis.Phi, MT = M * T;
  std::vector<Eigen::Index> kept;
  for (Eigen::Index c = 0; c < T.cols(); ++c) {
    const double before = std::sqrt(basis.Phi.col(c).dot(MPhi.col(c)));
    const double after = std::sqrt(T.col(c).dot(MT.col(c)));
    if (after > 1e-8 * before) kept.push_back(c);
  }
  const Eigen::Index n = T.rows(), k = static_cast<Eigen::Index>(kept.size());
  MatX T_e(n, k), MT_e(n, k);
  for (Eigen::Index c = 0; c < k; ++c) {
    const double norm = std::sqrt(T.col(kept[c]).dot(MT.col(kept[c])));
    T_e.col(c) = T.col(kept[c]) / norm;
    MT_e.col(c) = MT.col(kept[c]) / norm;
  }

  // 3. An M-orthonormal basis of their span.
  const Eigen::SelfAdjointEigenSolver<MatX> gram(T_e.transpose() * MT_e);
  const VecX& g = gram.eigenvalues();
  const double g_max = g.size() > 0 ? g.maxCoeff() : 0.0;
  std::vector<Eigen::Index> independent;
  for (Eigen::Index c = 0; c < g.size(); ++c)
    if (g(c) > 1e-10 * g_max) independent.push_back(c);
  MatX V(k, static_cast<Eigen::Index>(independent.size()));
  for (std::size_t c = 0; c < independent.size(); ++c)
    V.col(static_cast<Eigen::Index>(c)) = gram.eigenvectors().col(independent[c]) / std::sqrt(g(independent[c]));
  const MatX S = T_e * V;

  // 4. Diagonalise the stiffness on that span.
  const Eigen::SelfAdjointEigenSolver<MatX> stiffness(S.transpose() * (K * S));
  ReducedBasis out;
  out.Phi.resize(n, 3 + S.cols());
  out.Phi << Phi_r, S * stiffness.eigenvectors();
  out.M_bar = out.Phi.transpose() * (M * out.Phi);
  out.K_bar = out.Phi.transpose() * (K * out.Phi);
  out.num_rigid = 3;
  return out;
}

ImportedBodyData imported_body_data(const SparseFeModel& model, const ReducedBasis& basis) {
  const std::string where = "imported_body_data";
  check_model(model, where);
  check_ffrf_basis(model, basis, where);
  // The centroid frame: nodes moved by -c, rigid-body modes about its origin (the same motions).
  const Vec2 c = rigid_modes(model.table.nodes, model, where).centroid;
  const std::vector<Vec2> centred = shifted(model.table.nodes, -c);
  const RigidBodyModes rigid = rigid_modes(centred, model, where);

  ImportedBodyData d;
  d.dofs = model.table.dofs;
  d.basis = basis;
  d.basis.Phi.leftCols(3) = rigid.Phi_r;
  const MatX MPhi = model.M * d.basis.Phi, KPhi = model.K * d.basis.Phi;
  d.basis.M_bar = d.basis.Phi.transpose() * MPhi;
  d.basis.K_bar = d.basis.Phi.transpose() * KPhi;
  check_independent(d.basis.M_bar, where);

  const int n_f = d.basis.num_elastic();
  d.Phi_f = d.basis.Phi.rightCols(n_f);
  d.M_ff = d.Phi_f.transpose() * MPhi.rightCols(n_f);
  d.K_ff = d.Phi_f.transpose() * KPhi.rightCols(n_f);
  d.S_f = rigid.Phi_r.leftCols(2).transpose() * MPhi.rightCols(n_f);
  d.mass = rigid.mass;
  d.inertia = rigid.inertia;
  for (std::size_t k = 0; k < centred.size(); ++k) {
    const NodeDofNumbers& dofs = model.table.dofs[k];
    NodeModes node;
    node.x_bar = centred[k];
    node.Phi_t = MatX::Zero(2, n_f);
    node.Phi_psi = MatX::Zero(1, n_f);
    for (int a = 0; a < 2; ++a)
      if (dofs[a] >= 0) node.Phi_t.row(a) = d.Phi_f.row(dofs[a]);
    if (dofs[2] >= 0) node.Phi_psi.row(0) = d.Phi_f.row(dofs[2]);
    d.nodes.push_back(std::move(node));
  }
  return d;
}

std::shared_ptr<const ModalFfrfBody> make_sparse_modal_ffrf_body(const SparseFeModel& model,
                                                                 const ReducedBasis& basis) {
  auto data = std::make_shared<const ImportedBodyData>(imported_body_data(model, basis));
  return std::make_shared<const ModalFfrfBody>(data, model.M, data->dofs);
}

Vec3 frame_for_placement(const SparseFeModel& model, const Vec2& origin, double angle) {
  const Vec2 c = sparse_rigid_body_modes(model).centroid;
  const Vec2 R = origin + turn(angle) * c;
  return Vec3(R.x(), R.y(), angle);
}

}  // namespace fmbd
