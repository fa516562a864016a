// Given code of the nodal FFRF (declared in fmbd/ffrf.hpp): the node maps and biases stacked over
// the body, which the exercises M08T3 to M08T5 use, and the full FFRF body for the Model.
#include "fmbd/ffrf.hpp"

#include <stdexcept>
#include <string>

namespace fmbd {

FfrfWorkspace& ffrf_workspace() {
  thread_local FfrfWorkspace w;
  return w;
}

MatX node_acceleration_map(const NodeModes& node, const VecX& q) {
  MatX L_k;
  node_acceleration_map(node, q, L_k);
  return L_k;
}

void stacked_map(const FlexibleBodyData& data, const VecX& q, MatX& L) {
  L.resize(3 * static_cast<Eigen::Index>(data.nodes.size()), q.size());
  MatX& L_k = ffrf_workspace().L_k;
  for (std::size_t k = 0; k < data.nodes.size(); ++k) {
    node_acceleration_map(data.nodes[k], q, L_k);
    L.middleRows<3>(3 * k) = L_k;
  }
}

MatX stacked_map(const FlexibleBodyData& data, const VecX& q) {
  MatX L;
  stacked_map(data, q, L);
  return L;
}

void stacked_bias(const FlexibleBodyData& data, const VecX& q, const VecX& qd, VecX& b) {
  b.resize(3 * static_cast<Eigen::Index>(data.nodes.size()));
  for (std::size_t k = 0; k < data.nodes.size(); ++k) b.segment<3>(3 * k) = node_acceleration_bias(data.nodes[k], q, qd);
}

VecX stacked_bias(const FlexibleBodyData& data, const VecX& q, const VecX& qd) {
  VecX b;
  stacked_bias(data, q, qd, b);
  return b;
}

VecX quadratic_velocity_vector(const FlexibleBodyData& data, const VecX& q, const VecX& qd) {
  Model::check_size(q, 3 + data.num_modes(), "q", "quadratic_velocity_vector");
  Model::check_size(qd, 3 + data.num_modes(), "q_dot", "quadratic_velocity_vector");
  VecX Q = VecX::Zero(q.size());
  add_quadratic_velocity_vector(data, q, qd, 0, Q);
  return Q;
}

MatX ffrf_mass_matrix(const FlexibleBodyData& data, const VecX& q_j) {
  Model::check_size(q_j, 3 + data.num_modes(), "q_j", "ffrf_mass_matrix");
  MatX M = MatX::Zero(q_j.size(), q_j.size());
  add_ffrf_mass(data, q_j, 0, M);
  return M;
}

VecX ffrf_body_forces(const FlexibleBodyData& data, const VecX& q_j, const VecX& qd_j, const Vec2& g) {
  Model::check_size(q_j, 3 + data.num_modes(), "q_j", "ffrf_body_forces");
  VecX Q = VecX::Zero(q_j.size());
  add_ffrf_forces(data, q_j, qd_j, g, 0, Q);
  return Q;
}

FfrfBody::FfrfBody(std::shared_ptr<const FlexibleBodyData> data)
    : IntuitiveBody(data, AnyBasis{}), fe_data_(std::move(data)) {
  const Eigen::Index n = 3 * static_cast<Eigen::Index>(fe_data_->nodes.size());
  if (fe_data_->matrices.M.rows() != n || fe_data_->matrices.M.cols() != n)
    throw std::invalid_argument("FfrfBody: M_FE is " + std::to_string(fe_data_->matrices.M.rows()) + " x " +
                                std::to_string(fe_data_->matrices.M.cols()) + ", expected " + std::to_string(n) +
                                " x " + std::to_string(n) + " for " + std::to_string(fe_data_->nodes.size()) +
                                " nodes");
}

void FfrfBody::add_mass(const VecX& q, int at, MatX& M) const { add_ffrf_mass(*fe_data_, q, at, M); }

void FfrfBody::add_forces(const VecX& q, const VecX& qd, const Vec2& g, int at, VecX& Q_a) const {
  add_ffrf_forces(*fe_data_, q, qd, g, at, Q_a);
}

std::shared_ptr<const DeformableBody> make_ffrf_body(std::shared_ptr<const FlexibleBodyData> data) {
  return std::make_shared<FfrfBody>(std::move(data));
}

}  // namespace fmbd
