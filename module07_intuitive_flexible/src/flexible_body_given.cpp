// Flexible bodies: data, and the intuitive body for the Model (given code, module 7).
#include "fmbd/flexible_body.hpp"

#include <stdexcept>
#include <string>

#include "fmbd/craig_bampton.hpp"
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

IntuitiveBody::IntuitiveBody(std::shared_ptr<const ModalBodyData> data) : data_(std::move(data)) {
  if (!data_) throw std::invalid_argument("IntuitiveBody: no data");
  mass_bar_ = data_->basis.M_bar;
}

IntuitiveBody::IntuitiveBody(std::shared_ptr<const ModalBodyData> data, MatX mass_bar)
    : data_(std::move(data)), mass_bar_(std::move(mass_bar)) {
  if (!data_) throw std::invalid_argument("IntuitiveBody: no data");
  const Eigen::Index n = 3 + data_->num_modes();
  if (mass_bar_.rows() != n || mass_bar_.cols() != n)
    throw std::invalid_argument("IntuitiveBody: M_bar is " + std::to_string(mass_bar_.rows()) + " x " +
                                std::to_string(mass_bar_.cols()) + ", expected " + std::to_string(n) + " x " +
                                std::to_string(n) + " for " + std::to_string(data_->num_modes()) + " modes");
}

void IntuitiveBody::check_state(const VecX& q, const char* what, const char* where) const {
  Model::check_size(q, 3 + num_modes(), what, where);
}

NodeMarker IntuitiveBody::node_marker(int node, const VecX& q, const VecX& qd) const {
  check_state(q, "q", "node_marker");
  check_state(qd, "q_dot", "node_marker");
  const NodeModes& modes = data_->nodes.at(node);
  NodeMarker m;
  m.pose = node_pose(modes, q);
  m.G = node_jacobian(modes, q);
  m.velocity = m.G * qd;
  m.convective = node_convective_acceleration(modes, q, qd);
  return m;
}

MatX IntuitiveBody::mass_matrix(const VecX& q) const {
  check_state(q, "q", "mass_matrix");
  return mass_bar_;
}

VecX IntuitiveBody::body_forces(const VecX& q, const VecX& qd, const Vec2& g) const {
  check_state(q, "q", "body_forces");
  check_state(qd, "q_dot", "body_forces");
  return intuitive_body_forces(*data_, q, g);
}

double IntuitiveBody::kinetic_energy(const VecX& q, const VecX& qd) const {
  check_state(q, "q", "kinetic_energy");
  return 0.5 * qd.dot(mass_bar_ * qd);
}

double IntuitiveBody::potential_energy(const VecX& q, const Vec2& g) const {
  check_state(q, "q", "potential_energy");
  const VecX q_f = q.tail(num_modes());
  const Vec2 first_moment = data_->mass * q.head<2>() + rotation(q(2)) * (data_->S_f * q_f);
  return -g.dot(first_moment) + 0.5 * q_f.dot(data_->K_ff * q_f);
}

std::shared_ptr<const DeformableBody> make_intuitive_body(std::shared_ptr<const FlexibleBodyData> data) {
  if (!data) throw std::invalid_argument("make_intuitive_body: no data");
  MatX M_bar = intuitive_matrices(data->basis.Phi, data->matrices.M, data->matrices.K).M_bar;
  return std::make_shared<IntuitiveBody>(std::move(data), std::move(M_bar));
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
