// The full FFRF body in its fast form: inertia invariants (given code, module 8).
#include "fmbd/ffrf_invariants.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace fmbd {

namespace {

Mat2 frame_rotation(double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  return (Mat2() << c, -s, s, c).finished();
}

// x^T B y column by column: no temporary vector.
template <typename X, typename Y>
double bilinear(const X& x, const MatX& B, const Y& y) {
  double sum = 0.0;
  for (Eigen::Index j = 0; j < B.cols(); ++j) sum += y(j) * B.col(j).dot(x);
  return sum;
}

MatX symmetric_part(const MatX& B) { return 0.5 * (B + B.transpose()); }

const char* const kDofNames[3] = {"u_x", "u_y", "psi"};

// ModalFfrfBody's per-thread storage for M(q) and the body forces, one per body size.
struct BodyScratch {
  int size = 0;
  MatX M;
  VecX Q;
};

BodyScratch& body_scratch(int size) {
  thread_local std::vector<BodyScratch> kept;
  for (BodyScratch& s : kept)
    if (s.size == size) return s;
  kept.push_back(BodyScratch{size, MatX(size, size), VecX(size)});
  return kept.back();
}

}  // namespace

FfrfInvariants::FfrfInvariants(const FlexibleBodyData& data) : n_f_(data.num_modes()) {
  const MatX M(data.matrices.M);  // dense once: the invariants are built at setup
  const Eigen::Index N = static_cast<Eigen::Index>(data.nodes.size()), n = 3 * N;
  if (M.rows() != n || M.cols() != n)
    throw std::invalid_argument("FfrfInvariants: M_FE is " + std::to_string(M.rows()) + " x " +
                                std::to_string(M.cols()) + ", expected " + std::to_string(n) + " x " +
                                std::to_string(n) + " for " + std::to_string(N) + " nodes");
  // The DOF order of the FE model: node k at rows 3k, 3k + 1, 3k + 2.
  std::vector<NodeDofNumbers> dofs(static_cast<std::size_t>(N));
  for (Eigen::Index k = 0; k < N; ++k) {
    const int r = static_cast<int>(3 * k);
    dofs[static_cast<std::size_t>(k)] = {r, r + 1, r + 2};
  }
  build(M, dofs, data);
}

FfrfInvariants::FfrfInvariants(const SparseMat& M, const std::vector<NodeDofNumbers>& dofs,
                               const ModalBodyData& data)
    : n_f_(data.num_modes()) {
  const Eigen::Index n = M.rows();
  if (M.cols() != n || n == 0)
    throw std::invalid_argument("FfrfInvariants: M_FE is " + std::to_string(M.rows()) + " x " +
                                std::to_string(M.cols()) + ", not a non-empty square matrix");
  if (dofs.size() != data.nodes.size())
    throw std::invalid_argument("FfrfInvariants: " + std::to_string(dofs.size()) + " sets of DOF numbers for " +
                                std::to_string(data.nodes.size()) + " nodes");
  // Every row of M is one DOF of one node.
  std::vector<int> owner(static_cast<std::size_t>(n), -1);
  for (std::size_t k = 0; k < dofs.size(); ++k)
    for (int d = 0; d < 3; ++d) {
      const int r = dofs[k][d];
      if (r < -1 || r >= n)
        throw std::invalid_argument("FfrfInvariants: node " + std::to_string(k) + ": the DOF number " +
                                    std::to_string(r) + " of " + kDofNames[d] + " is outside -1 .. " +
                                    std::to_string(n - 1));
      if (r < 0) continue;
      if (owner[r] >= 0)
        throw std::invalid_argument("FfrfInvariants: row " + std::to_string(r) + " of M_FE is named twice (node " +
                                    std::to_string(owner[r] / 3) + " " + kDofNames[owner[r] % 3] + " and node " +
                                    std::to_string(k) + " " + kDofNames[d] + ")");
      owner[r] = static_cast<int>(3 * k) + d;
    }
  for (Eigen::Index r = 0; r < n; ++r)
    if (owner[r] < 0)
      throw std::invalid_argument("FfrfInvariants: row " + std::to_string(r) +
                                  " of M_FE belongs to no node; every DOF needs its motion with the frame");
  build(M, dofs, data);
}

template <typename Matrix>
void FfrfInvariants::build(const Matrix& M, const std::vector<NodeDofNumbers>& dofs, const ModalBodyData& data) {
  const Eigen::Index n = M.rows();
  if (data.K_ff.rows() != n_f_ || data.K_ff.cols() != n_f_)
    throw std::invalid_argument("FfrfInvariants: K_ff is not " + std::to_string(n_f_) + " x " + std::to_string(n_f_));

  // The stacked fields of the header, from the rows of every node.
  MatX T = MatX::Zero(n, 2), Phi = MatX::Zero(n, n_f_), X1 = MatX::Zero(n, n_f_), C1 = MatX::Zero(n, n_f_);
  VecX X0 = VecX::Zero(n), c0 = VecX::Zero(n);
  for (std::size_t k = 0; k < data.nodes.size(); ++k) {
    const NodeModes& node = data.nodes[k];
    if (node.Phi_t.rows() != 2 || node.Phi_t.cols() != n_f_ || node.Phi_psi.rows() != 1 || node.Phi_psi.cols() != n_f_)
      throw std::invalid_argument("FfrfInvariants: the rows of node " + std::to_string(k) + " do not have " +
                                  std::to_string(n_f_) + " columns");
    const NodeDofNumbers& rows = dofs[k];
    const bool moves[3] = {node.Phi_t.row(0).any(), node.Phi_t.row(1).any(), node.Phi_psi.any()};
    for (int d = 0; d < 3; ++d)
      if (rows[d] < 0 && moves[d])
        throw std::invalid_argument("FfrfInvariants: node " + std::to_string(k) + " has a non-zero elastic row for " +
                                    kDofNames[d] + ", which is not in M_FE");
    const Vec2 rotated(-node.x_bar.y(), node.x_bar.x());  // I~ x_bar
    for (int d = 0; d < 2; ++d) {
      const int r = rows[d];
      if (r < 0) continue;
      T(r, d) = 1.0;
      Phi.row(r) = node.Phi_t.row(d);
      X1.row(r) = node.Phi_t.row(d);
      if (d == 0)
        C1.row(r) = -node.Phi_t.row(1);
      else
        C1.row(r) = node.Phi_t.row(0);
      X0(r) = node.x_bar(d);
      c0(r) = rotated(d);
    }
    if (rows[2] >= 0) {
      Phi.row(rows[2]) = node.Phi_psi;
      c0(rows[2]) = 1.0;
    }
  }

  // The products with M_FE, once.
  const MatX MT = M * T, MPhi = M * Phi, MC1 = M * C1;
  const VecX Mc0 = M * c0;

  M_tt_ = MT.transpose() * T;
  M_tt_ = (0.5 * (M_tt_ + M_tt_.transpose())).eval();
  S_t0_ = MT.transpose() * c0;
  S_t1_ = MT.transpose() * C1;
  S_f_ = MT.transpose() * Phi;
  U_0_ = MT.transpose() * X0;
  U_1_ = MT.transpose() * X1;

  J_0_ = c0.dot(Mc0);
  j_1_ = C1.transpose() * Mc0;
  J_2_ = symmetric_part(MC1.transpose() * C1);

  p_0_ = Phi.transpose() * Mc0;
  P_1_ = MPhi.transpose() * C1;
  M_ff_ = symmetric_part(MPhi.transpose() * Phi);
  e_0_ = MPhi.transpose() * X0;
  E_1_ = MPhi.transpose() * X1;

  h_0_ = X0.dot(Mc0);
  h_1_ = X1.transpose() * Mc0 + MC1.transpose() * X0;
  H_1_ = MC1.transpose() * X1;
  K_ff_ = data.K_ff;
  mass_ = data.mass;
}

void FfrfInvariants::check(const ConstVec& v, const char* what, const char* where) const {
  if (v.size() != size())
    throw std::invalid_argument(std::string("FfrfInvariants::") + where + ": " + what + " has size " +
                                std::to_string(v.size()) + ", expected " + std::to_string(size()));
}

void FfrfInvariants::mass_matrix(const ConstVec& q, MatX& out) const {
  check(q, "q", "mass_matrix");
  const int s = size();
  if (out.rows() != s || out.cols() != s) out.resize(s, s);
  const Mat2 A = frame_rotation(q(2));
  const auto q_f = q.tail(n_f_);

  const Mat2 M_RR = A * M_tt_ * A.transpose();
  out.topLeftCorner<2, 2>() = M_RR;
  out(0, 1) = out(1, 0) = 0.5 * (M_RR(0, 1) + M_RR(1, 0));

  const Vec2 M_Rtheta = A * (S_t0_ + S_t1_ * q_f);
  out.block<2, 1>(0, 2) = M_Rtheta;
  out.block<1, 2>(2, 0) = M_Rtheta.transpose();

  out.topRightCorner(2, n_f_).noalias() = A * S_f_;
  out.bottomLeftCorner(n_f_, 2) = out.topRightCorner(2, n_f_).transpose();

  out(2, 2) = J_0_ + 2.0 * j_1_.dot(q_f) + bilinear(q_f, J_2_, q_f);
  auto M_ftheta = out.col(2).tail(n_f_);
  M_ftheta = p_0_;
  M_ftheta.noalias() += P_1_ * q_f;
  out.row(2).tail(n_f_) = M_ftheta.transpose();

  out.bottomRightCorner(n_f_, n_f_) = M_ff_;
}

void FfrfInvariants::quadratic_velocity_vector(const ConstVec& q, const ConstVec& qd, VecX& out) const {
  check(q, "q", "quadratic_velocity_vector");
  check(qd, "q_dot", "quadratic_velocity_vector");
  if (out.size() != size()) out.resize(size());
  const Mat2 A = frame_rotation(q(2));
  const double w = qd(2), w2 = w * w;
  const auto q_f = q.tail(n_f_);
  const auto qd_f = qd.tail(n_f_);

  // Q_v = -L^T M g, row block by row block.
  const Vec2 in_frame = -w2 * (U_0_ + U_1_ * q_f) + 2.0 * w * (S_t1_ * qd_f);
  out.head<2>() = -(A * in_frame);

  const double centripetal = h_0_ + h_1_.dot(q_f) + bilinear(q_f, H_1_, q_f);
  const double coriolis = j_1_.dot(qd_f) + bilinear(q_f, J_2_, qd_f);
  out(2) = w2 * centripetal - 2.0 * w * coriolis;

  auto f = out.tail(n_f_);
  f = w2 * e_0_;
  f.noalias() += (w2 * E_1_) * q_f;
  f.noalias() -= ((2.0 * w) * P_1_) * qd_f;
}

void FfrfInvariants::body_forces(const ConstVec& q, const ConstVec& qd, const Vec2& g, VecX& out) const {
  quadratic_velocity_vector(q, qd, out);
  const Mat2 A = frame_rotation(q(2));
  const Vec2 gamma = A.transpose() * g;
  const auto q_f = q.tail(n_f_);

  // Gravity as module 7's flexible_gravity_force: minus the gradient of -g^T (m R + A S_f q_f).
  const Vec2 first_moment = S_f_ * q_f;
  out.head<2>() += mass_ * g;
  out(2) += gamma.y() * first_moment.x() - gamma.x() * first_moment.y();  // gamma^T I~ S_f q_f
  auto f = out.tail(n_f_);
  f.noalias() += S_f_.transpose() * gamma;
  f.noalias() -= K_ff_ * q_f;
}

double FfrfInvariants::kinetic_energy(const ConstVec& q, const ConstVec& qd) const {
  check(q, "q", "kinetic_energy");
  check(qd, "q_dot", "kinetic_energy");
  const Mat2 A = frame_rotation(q(2));
  const Vec2 v = A.transpose() * qd.head<2>();
  const double w = qd(2);
  const auto q_f = q.tail(n_f_);
  const auto qd_f = qd.tail(n_f_);

  const double M_thth = J_0_ + 2.0 * j_1_.dot(q_f) + bilinear(q_f, J_2_, q_f);
  const double twice = v.dot(M_tt_ * v) + 2.0 * w * v.dot(S_t0_ + S_t1_ * q_f) + 2.0 * v.dot(S_f_ * qd_f) +
                       w * w * M_thth + 2.0 * w * (p_0_.dot(qd_f) + bilinear(qd_f, P_1_, q_f)) +
                       bilinear(qd_f, M_ff_, qd_f);
  return 0.5 * twice;
}

MatX FfrfInvariants::mass_matrix(const ConstVec& q) const {
  MatX out(size(), size());
  mass_matrix(q, out);
  return out;
}

VecX FfrfInvariants::quadratic_velocity_vector(const ConstVec& q, const ConstVec& qd) const {
  VecX out(size());
  quadratic_velocity_vector(q, qd, out);
  return out;
}

VecX FfrfInvariants::body_forces(const ConstVec& q, const ConstVec& qd, const Vec2& g) const {
  VecX out(size());
  body_forces(q, qd, g, out);
  return out;
}

ModalFfrfBody::ModalFfrfBody(std::shared_ptr<const FlexibleBodyData> data)
    : IntuitiveBody(data, AnyBasis{}), invariants_(*data) {}

void ModalFfrfBody::add_mass(const VecX& q, int at, MatX& M) const {
  check_body_block(*data_, q, at, M.rows(), "ModalFfrfBody::add_mass");
  const int n = 3 + num_modes();
  MatX& M_j = body_scratch(n).M;
  invariants_.mass_matrix(q.segment(at, n), M_j);
  M.block(at, at, n, n) += M_j;
}

void ModalFfrfBody::add_forces(const VecX& q, const VecX& qd, const Vec2& g, int at, VecX& Q_a) const {
  check_body_block(*data_, q, at, Q_a.size(), "ModalFfrfBody::add_forces");
  check_body_block(*data_, qd, at, Q_a.size(), "ModalFfrfBody::add_forces");
  const int n = 3 + num_modes();
  VecX& Q_j = body_scratch(n).Q;
  invariants_.body_forces(q.segment(at, n), qd.segment(at, n), g, Q_j);
  Q_a.segment(at, n) += Q_j;
}

double ModalFfrfBody::kinetic_energy(const VecX& q, const VecX& qd) const {
  check_state(q, "q", "kinetic_energy");
  check_state(qd, "q_dot", "kinetic_energy");
  return invariants_.kinetic_energy(q, qd);
}

ModalFfrfBody::ModalFfrfBody(std::shared_ptr<const ModalBodyData> data, const SparseMat& M,
                             const std::vector<NodeDofNumbers>& dofs)
    : IntuitiveBody(std::move(data), AnyBasis{}), invariants_(M, dofs, *data_) {}

std::shared_ptr<const DeformableBody> make_modal_ffrf_body(std::shared_ptr<const FlexibleBodyData> data) {
  return std::make_shared<ModalFfrfBody>(std::move(data));
}

}  // namespace fmbd
