#include "fmbd/workspace_rk4.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>

#include "fmbd/constraints.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/forward_dynamics.hpp"
#include "fmbd/gamma.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/simulation.hpp"

namespace fmbd::bench {

WorkspaceRk4::WorkspaceRk4(const Model& model)
    : model_(model), n_(model.num_coordinates()), m_(model.num_constraints()) {
  if (!model.forces().empty())
    throw std::invalid_argument("WorkspaceRk4: force element '" + model.forces().front().name +
                                "': force elements are not supported (gravity and flexible bodies are)");
  const int bodies = model.num_bodies();
  flexible_.assign(bodies, nullptr);
  body_mass_.resize(bodies);
  body_forces_.resize(bodies);
  for (int k = 0; k < bodies; ++k) {
    const Body& body = model.bodies()[k];
    if (!body.is_flexible()) continue;
    flexible_[k] = dynamic_cast<const ModalFfrfBody*>(body.deformable.get());
    if (flexible_[k] == nullptr)
      throw std::invalid_argument("WorkspaceRk4: flexible body '" + body.name +
                                  "' is not a ModalFfrfBody (make it with make_modal_ffrf_body)");
    const int nb = body.num_coordinates();
    if (nb > kMaxBodyCoordinates)
      throw std::invalid_argument("WorkspaceRk4: flexible body '" + body.name + "' has " + std::to_string(nb) +
                                  " coordinates, more than kMaxBodyCoordinates = " +
                                  std::to_string(kMaxBodyCoordinates));
    body_mass_[k].resize(nb, nb);
    body_forces_[k].resize(nb);
  }
  const int N = n_ + m_;
  A_.resize(N, N);
  b_.resize(N);
  x_.resize(N);
  r_.resize(N);
  den_.resize(N);
  lu_ = Eigen::PartialPivLU<MatX>(N);
  for (VecX* v : {&k1_, &k2_, &k3_, &k4_, &stage_}) v->resize(2 * n_);
}

void WorkspaceRk4::set_profiling(bool on) {
  profiling_ = on;
  profile_ = StepProfile{};
}

template <class Part>
void WorkspaceRk4::timed(double& seconds, Part&& part) {
  if (!profiling_) {
    part();
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  part();
  seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void WorkspaceRk4::body_site(BodyId body, const ConstVec& q, const ConstVec& qd, Marker& marker,
                             GStorage& G) const {
  marker.body = body;
  marker.s_bar.setZero();
  marker.convective.setZero();
  if (body.is_ground()) {
    marker.q.setZero();
    marker.qd.setZero();
    G.resize(3, 0);
    return;
  }
  const int at = model_.offset(body), nb = model_.body(body).num_coordinates();
  marker.offset = at;
  marker.q = q.segment<3>(at);
  marker.qd = qd.segment<3>(at);
  G.setZero(3, nb);
  G.leftCols<3>().setIdentity();
}

// A rigid body's point, or an FE node: p_k = (R + A s, theta + psi), s = x_bar + Phi_t q_f,
// G_k = [I2, A I~ s, A Phi_t; 0 0 1, Phi_psi], c_k = (-theta_dot^2 A s + 2 theta_dot A I~ u_dot, 0).
void WorkspaceRk4::point_site(PointId id, const ConstVec& q, const ConstVec& qd, Marker& marker,
                              GStorage& G) const {
  const Point& point = model_.point(id);
  body_site(point.body, q, qd, marker, G);
  if (point.node < 0) {
    marker.s_bar = point.s_bar;
    return;
  }
  const int at = model_.offset(point.body), nf = G.cols() - 3;
  const NodeModes& node = flexible_[point.body.index]->data().nodes[point.node];
  const auto q_f = q.segment(at + 3, nf), qd_f = qd.segment(at + 3, nf);
  const double theta = q(at + 2), w = qd(at + 2);
  const Mat2 A = rotation(theta), AI = A * I_tilde();
  Vec2 u, u_dot;
  u.noalias() = node.Phi_t * q_f;
  u_dot.noalias() = node.Phi_t * qd_f;
  const Vec2 s = node.x_bar + u;
  marker.q.head<2>() = q.segment<2>(at) + A * s;
  marker.q(2) = theta + node.Phi_psi.row(0).dot(q_f);
  marker.qd.head<2>() = qd.segment<2>(at) + AI * s * w + A * u_dot;
  marker.qd(2) = w + node.Phi_psi.row(0).dot(qd_f);
  marker.convective.head<2>() = -w * w * (A * s) + 2 * w * (AI * u_dot);
  G.block<2, 1>(0, 2) = AI * s;
  G.block(0, 3, 2, nf).noalias() = A * node.Phi_t;
  G.block(2, 3, 1, nf) = node.Phi_psi;
}

void WorkspaceRk4::constraint_sites(const Constraint& c, const ConstVec& q, const ConstVec& qd) {
  std::visit(
      [&](const auto& k) {
        using T = std::decay_t<decltype(k)>;
        if constexpr (std::is_same_v<T, AbsoluteAngleDriver>) {
          body_site(k.body, q, qd, markers_.i, G_i_);
          body_site(ground, q, qd, markers_.j, G_j_);
        } else if constexpr (std::is_same_v<T, RelativeAngleDriver>) {
          body_site(k.body_i, q, qd, markers_.i, G_i_);
          body_site(k.body_j, q, qd, markers_.j, G_j_);
        } else if constexpr (std::is_same_v<T, PointCoordinateDriver>) {
          point_site(k.P, q, qd, markers_.i, G_i_);
          body_site(ground, q, qd, markers_.j, G_j_);
        } else {
          point_site(k.P_i, q, qd, markers_.i, G_i_);
          point_site(k.P_j, q, qd, markers_.j, G_j_);
        }
      },
      c.type);
}

void WorkspaceRk4::add_columns(int row, const Marker& marker, const GStorage& G, const RowBlock& block) {
  if (marker.body.is_ground()) return;
  A_.block(row, marker.offset, block.rows(), G.cols()).noalias() += block * G;
}

// [M C_q^T; C_q 0] into A_ and (Q, gamma) into b_.
void WorkspaceRk4::assemble(double t, const ConstVec& q, const ConstVec& qd) {
  A_.setZero();
  b_.setZero();
  const Vec2 g = model_.gravity();
  for (int k = 0; k < model_.num_bodies(); ++k) {
    const Body& body = model_.bodies()[k];
    const int at = model_.offset(BodyId{k});
    if (flexible_[k] == nullptr) {
      A_.diagonal().segment<3>(at) << body.mass, body.mass, body.inertia;
      b_.segment<2>(at) = body.mass * g;
      continue;
    }
    const int nb = body.num_coordinates();
    const FfrfInvariants& invariants = flexible_[k]->invariants();
    timed(profile_.mass_matrix, [&] { invariants.mass_matrix(q.segment(at, nb), body_mass_[k]); });
    timed(profile_.body_forces,
          [&] { invariants.body_forces(q.segment(at, nb), qd.segment(at, nb), g, body_forces_[k]); });
    A_.block(at, at, nb, nb) = body_mass_[k];
    b_.segment(at, nb) = body_forces_[k];
  }

  timed(profile_.constraints, [&] { assemble_constraints(t, q, qd); });
}

// The rows of C_q G and gamma below the bodies' block, and C_q^T beside it.
void WorkspaceRk4::assemble_constraints(double t, const ConstVec& q, const ConstVec& qd) {
  for (const Constraint& c : model_.constraints()) {
    constraint_sites(c, q, qd);
    const ConstraintBlock blk = evaluate_constraint(c, markers_, t);
    RowVector gamma = kernel_gamma(c, markers_, t);
    if (blk.Cq_i.rows() != c.rows || blk.Cq_j.rows() != c.rows || gamma.size() != c.rows)
      throw std::logic_error(std::string(c.type_name()) + " '" + c.name + "': a kernel returned the wrong number of rows");
    const int row = n_ + c.first_row;
    add_columns(row, markers_.i, G_i_, blk.Cq_i);
    add_columns(row, markers_.j, G_j_, blk.Cq_j);
    // B G q_ddot = gamma - B c for a marker with a convective acceleration c (an FE node).
    gamma -= blk.Cq_i * markers_.i.convective + blk.Cq_j * markers_.j.convective;
    b_.segment(row, c.rows) = gamma;
  }
  A_.topRightCorner(n_, m_) = A_.bottomLeftCorner(m_, n_).transpose();
}

void WorkspaceRk4::derivative(double t, const VecX& y, VecX& out) {
  if (!y.allFinite())
    throw IntegrationError("WorkspaceRk4: the state became NaN or Inf at t = " + readable(t) + ", step " +
                               std::to_string(steps_) + "; the step is too large, or the model is unstable",
                           t, steps_);
  const auto q = y.head(n_), qd = y.tail(n_);
  assemble(t, q, qd);
  if (!A_.allFinite() || !b_.allFinite())
    throw IntegrationError("WorkspaceRk4: the augmented system is not finite at t = " + readable(t), t, steps_);
  double error = 0;
  timed(profile_.solve, [&] {
    lu_.compute(A_);
    x_ = lu_.solve(b_);
    error = backward_error();
    if (error > augmented_round_off(n_ + m_) && std::isfinite(error)) {  // one step of refinement
      x_ += lu_.solve(r_);
      error = backward_error();
    }
  });
  if (!x_.allFinite() || !(error <= augmented_round_off(n_ + m_))) {
    // Redundant constraints, an instant at a singular position, or a system the LU cannot solve
    // to round-off: module 4's solve_augmented decides (its general and rank-revealing paths),
    // allocating on this path only, and names what has no motion.
    timed(profile_.solve, [&] {
      x_.head(n_) = solve_augmented(model_, A_.topLeftCorner(n_, n_), A_.bottomLeftCorner(m_, n_), b_.head(n_),
                                    b_.tail(m_), "WorkspaceRk4")
                        .qdd;
    });
  }
  out.head(n_) = qd;
  out.tail(n_) = x_.head(n_);
}

double WorkspaceRk4::backward_error() {
  r_ = b_;
  r_.noalias() -= A_ * x_;
  den_ = b_.cwiseAbs();
  for (Eigen::Index j = 0; j < A_.cols(); ++j) den_ += A_.col(j).cwiseAbs() * std::abs(x_(j));
  double worst = 0;
  for (Eigen::Index i = 0; i < r_.size(); ++i)
    if (r_(i) != 0) worst = std::max(worst, den_(i) > 0 ? std::abs(r_(i)) / den_(i) : HUGE_VAL);
  return worst;
}

void WorkspaceRk4::step(double t, VecX& y, double h) {
  derivative(t, y, k1_);
  stage_ = y + h / 2 * k1_;
  derivative(t + h / 2, stage_, k2_);
  stage_ = y + h / 2 * k2_;
  derivative(t + h / 2, stage_, k3_);
  stage_ = y + h * k3_;
  derivative(t + h, stage_, k4_);
  y += h / 6 * (k1_ + 2 * k2_ + 2 * k3_ + k4_);
  ++steps_;
}

}  // namespace fmbd::bench
