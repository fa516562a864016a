// Flexible bodies: data, and the intuitive body for the Model (given code, module 7).
#include "fmbd/flexible_body.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "fmbd/craig_bampton.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/intuitive_flexible.hpp"

namespace fmbd {

namespace {

FeModel moved(const FeModel& fe, const Vec2& shift) {
  FeModel out;
  for (const Vec2& x : fe.nodes()) out.add_node(x + shift);
  for (const BeamElement& e : fe.elements()) out.add_element(e.node_a, e.node_b, e.section);
  return out;
}

// Everything but the basis, from the centroid-frame model, its matrices and an FFRF basis.
FlexibleBodyData finish(FeModel fe, FeMatrices matrices, ReducedBasis basis, const RigidBodyModes& rigid) {
  FlexibleBodyData d;
  const int n_f = basis.num_elastic();
  d.Phi_f = basis.Phi.rightCols(n_f);
  d.M_ff = d.Phi_f.transpose() * matrices.M * d.Phi_f;
  d.K_ff = d.Phi_f.transpose() * matrices.K * d.Phi_f;
  d.S_f = rigid.Phi_r.leftCols(2).transpose() * matrices.M * d.Phi_f;
  d.mass = rigid.mass;
  d.inertia = rigid.inertia;
  for (int k = 0; k < fe.num_nodes(); ++k) {
    NodeModes node;
    node.x_bar = fe.nodes()[k];
    node.Phi_t = d.Phi_f.middleRows(3 * k, 2);
    node.Phi_psi = d.Phi_f.middleRows(3 * k + 2, 1);
    d.nodes.push_back(std::move(node));
  }
  d.fe = std::move(fe);
  d.matrices = to_sparse(matrices);
  d.basis = std::move(basis);
  return d;
}

}  // namespace

FlexibleBodyData flexible_body_data(const FeModel& fe, MassMatrixType mass_type, int num_modes) {
  FeMatrices matrices = assemble(fe, mass_type);
  const Vec2 c = rigid_body_modes(fe, matrices.M).centroid;
  FeModel centred = moved(fe, -c);
  const RigidBodyModes rigid = rigid_body_modes(centred, matrices.M);
  ReducedBasis basis = modal_truncation(centred, matrices, num_modes);
  return finish(std::move(centred), std::move(matrices), std::move(basis), rigid);
}

FlexibleBodyData flexible_body_data(const FeModel& fe, MassMatrixType mass_type, const ReducedBasis& basis) {
  if (basis.num_rigid != 3 || basis.Phi.cols() < 3 || basis.Phi.rows() != fe.num_dofs())
    throw std::invalid_argument("flexible_body_data: the basis must have num_rigid = 3 (ffrf_basis or "
                                "modal_truncation) and " + std::to_string(fe.num_dofs()) +
                                " rows, got num_rigid = " + std::to_string(basis.num_rigid) + " and " +
                                std::to_string(basis.Phi.rows()) + " rows");
  FeMatrices matrices = assemble(fe, mass_type);
  const Vec2 c = rigid_body_modes(fe, matrices.M).centroid;
  FeModel centred = moved(fe, -c);
  const RigidBodyModes rigid = rigid_body_modes(centred, matrices.M);
  // The rigid columns are re-made about the centroid frame's origin (the same motions).
  ReducedBasis centred_basis = basis;
  centred_basis.Phi.leftCols(3) = rigid.Phi_r;
  centred_basis.M_bar = centred_basis.Phi.transpose() * matrices.M * centred_basis.Phi;
  centred_basis.K_bar = centred_basis.Phi.transpose() * matrices.K * centred_basis.Phi;
  return finish(std::move(centred), std::move(matrices), std::move(centred_basis), rigid);
}

FlexibleBodyData clamped_frame_body_data(const FeModel& fe, MassMatrixType mass_type, int node, int num_modes) {
  if (node < 0 || node >= fe.num_nodes())
    throw std::invalid_argument("clamped_frame_body_data: node " + std::to_string(node) + " is not a node of the model (0 .. " +
                                std::to_string(fe.num_nodes() - 1) + ")");
  const FeMatrices matrices = assemble(fe, mass_type);
  // With one node as interface the three constraint modes are the rigid motions about it; the
  // fixed-interface modes are the cantilever modes.
  const ReducedBasis cb = craig_bampton(matrices.K, matrices.M, node_dofs({node}), num_modes);
  return flexible_body_data(fe, mass_type, with_matrices(cb.Phi, matrices.K, matrices.M, 3));
}

namespace {

// The largest entry of S_f, each divided by its bound sqrt(m (M_ff)_ii) (Cauchy-Schwarz in the
// M inner product): the cosine of the M-angle between an elastic shape and a translation.
double first_moment_cosine(const ModalBodyData& d) {
  double worst = 0.0;
  for (int i = 0; i < d.num_modes(); ++i) {
    const double bound = std::sqrt(d.mass * d.M_ff(i, i));
    if (bound > 0.0) worst = std::max(worst, d.S_f.col(i).cwiseAbs().maxCoeff() / bound);
  }
  return worst;
}

}  // namespace

IntuitiveBody::IntuitiveBody(std::shared_ptr<const ModalBodyData> data, AnyBasis) : data_(std::move(data)) {
  if (!data_) throw std::invalid_argument("IntuitiveBody: no data");
}

IntuitiveBody::IntuitiveBody(std::shared_ptr<const ModalBodyData> data) : IntuitiveBody(std::move(data), AnyBasis{}) {
  const double cosine = first_moment_cosine(*data_);
  if (cosine > kIntuitiveBasisTolerance)
    throw IntuitiveBasisError(
        "IntuitiveBody: the intuitive form (module 7) needs elastic shapes M-orthogonal to the rigid motions "
        "(free-free modes, first moment S_f = 0), but this basis has S_f with a cosine of " + readable(cosine) +
        " to the translations (at most " + readable(kIntuitiveBasisTolerance) +
        "): its elastic coordinates move the centre of mass, and the constant M_bar would couple them to the frame "
        "as if theta stayed 0. Use flexible_body_data(fe, mass_type, num_modes) (free-free modes) or an ffrf_basis "
        "(module 6); a frame clamped at a node needs module 8's make_ffrf_body, whose M(q) turns with the body");
}

void IntuitiveBody::check_state(const VecX& q, const char* what, const char* where) const {
  Model::check_size(q, 3 + num_modes(), what, where);
}

NodeMarker IntuitiveBody::node_marker(int node, const VecX& q, const VecX& qd) const {
  NodeMarker m;
  write_node_marker(node, q, qd, m);
  return m;
}

void IntuitiveBody::write_node_marker(int node, const VecX& q, const VecX& qd, NodeMarker& m) const {
  check_state(q, "q", "node_marker");
  check_state(qd, "q_dot", "node_marker");
  const NodeModes& modes = data_->nodes.at(node);
  m.pose = node_pose(modes, q);
  node_jacobian(modes, q, m.G);
  m.velocity.noalias() = m.G * qd;
  m.convective = node_convective_acceleration(modes, q, qd);
}

void IntuitiveBody::add_node_columns(const NodeMarker& node, const RowBlock& B, int first_row, int at,
                                     MatX& Cq) const {
  add_node_block_columns(node, B, first_row, at, Cq);
}

RowVector IntuitiveBody::node_gamma_term(const NodeMarker& node, const RowBlock& B) const {
  return node_gamma_correction(node, B);
}

void IntuitiveBody::add_node_force(const NodeMarker& node, const Vec3& Q, int at, VecX& Q_a) const {
  add_node_force_rows(node, Q, at, Q_a);
}

void IntuitiveBody::add_mass(const VecX& q, int at, MatX& M) const { add_intuitive_mass(*data_, q, at, M); }

void IntuitiveBody::add_forces(const VecX& q, const VecX& qd, const Vec2& g, int at, VecX& Q_a) const {
  add_intuitive_forces(*data_, q, qd, g, at, Q_a);
}

double IntuitiveBody::kinetic_energy(const VecX& q, const VecX& qd) const {
  check_state(q, "q", "kinetic_energy");
  check_state(qd, "q_dot", "kinetic_energy");
  return 0.5 * qd.dot(mass_matrix(q) * qd);
}

double IntuitiveBody::potential_energy(const VecX& q, const Vec2& g) const {
  check_state(q, "q", "potential_energy");
  const VecX q_f = q.tail(num_modes());
  const Vec2 first_moment = data_->mass * q.head<2>() + rotation(q(2)) * (data_->S_f * q_f);
  return -g.dot(first_moment) + 0.5 * q_f.dot(data_->K_ff * q_f);
}

std::shared_ptr<const DeformableBody> make_intuitive_body(std::shared_ptr<const FlexibleBodyData> data) {
  if (!data) throw std::invalid_argument("make_intuitive_body: no data");
  return std::make_shared<IntuitiveBody>(std::move(data));
}

MatX node_jacobian(const NodeModes& node, const VecX& q) {
  MatX G;
  node_jacobian(node, q, G);
  return G;
}

VecX flexible_gravity_force(const ModalBodyData& data, const VecX& q_j, const Vec2& g) {
  Model::check_size(q_j, 3 + data.num_modes(), "q_j", "flexible_gravity_force");
  VecX Q = VecX::Zero(q_j.size());
  add_flexible_gravity_force(data, q_j, g, 0, Q);
  return Q;
}

void check_body_block(const ModalBodyData& data, const VecX& q, int at, Eigen::Index size, const char* where) {
  const Eigen::Index n = 3 + data.num_modes();
  if (at < 0 || at + n > q.size() || q.size() != size)
    throw std::invalid_argument(std::string(where) + ": the body's " + std::to_string(n) + " coordinates from " +
                                std::to_string(at) + " do not fit a system of " + std::to_string(q.size()) +
                                " coordinates (M or Q_a of size " + std::to_string(size) + ")");
}

Vec2 undeformed_node_position(const ModalBodyData& data, int node, const Vec3& frame) {
  return frame.head<2>() + rotation(frame(2)) * data.nodes.at(node).x_bar;
}

Vec3 frame_for_placement(const FeModel& fe, MassMatrixType mass_type, const Vec2& origin, double angle) {
  const Vec2 c = rigid_body_modes(fe, assemble(fe, mass_type).M).centroid;
  const Vec2 R = origin + rotation(angle) * c;
  return Vec3(R.x(), R.y(), angle);
}

}  // namespace fmbd
