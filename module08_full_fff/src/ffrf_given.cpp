// Given code of the nodal FFRF (declared in fmbd/ffrf.hpp): the node maps and biases stacked over
// the body, which the exercises M08T3 to M08T5 use, and the full FFRF body for the Model.
#include "fmbd/ffrf.hpp"

#include <stdexcept>
#include <string>

namespace fmbd {

MatX stacked_map(const FlexibleBodyData& data, const VecX& q) {
  MatX L(3 * data.nodes.size(), q.size());
  for (std::size_t k = 0; k < data.nodes.size(); ++k) L.middleRows<3>(3 * k) = node_acceleration_map(data.nodes[k], q);
  return L;
}

VecX stacked_bias(const FlexibleBodyData& data, const VecX& q, const VecX& qd) {
  VecX b(3 * data.nodes.size());
  for (std::size_t k = 0; k < data.nodes.size(); ++k) b.segment<3>(3 * k) = node_acceleration_bias(data.nodes[k], q, qd);
  return b;
}

FfrfBody::FfrfBody(std::shared_ptr<const FlexibleBodyData> data) : IntuitiveBody(data), fe_data_(std::move(data)) {
  const Eigen::Index n = 3 * static_cast<Eigen::Index>(fe_data_->nodes.size());
  if (fe_data_->matrices.M.rows() != n || fe_data_->matrices.M.cols() != n)
    throw std::invalid_argument("FfrfBody: M_FE is " + std::to_string(fe_data_->matrices.M.rows()) + " x " +
                                std::to_string(fe_data_->matrices.M.cols()) + ", expected " + std::to_string(n) +
                                " x " + std::to_string(n) + " for " + std::to_string(fe_data_->nodes.size()) +
                                " nodes");
}

MatX FfrfBody::mass_matrix(const VecX& q) const {
  check_state(q, "q", "mass_matrix");
  return ffrf_mass_matrix(*fe_data_, q);
}

VecX FfrfBody::body_forces(const VecX& q, const VecX& qd, const Vec2& g) const {
  check_state(q, "q", "body_forces");
  check_state(qd, "q_dot", "body_forces");
  return ffrf_body_forces(*fe_data_, q, qd, g);
}

double FfrfBody::kinetic_energy(const VecX& q, const VecX& qd) const {
  check_state(q, "q", "kinetic_energy");
  check_state(qd, "q_dot", "kinetic_energy");
  return 0.5 * qd.dot(ffrf_mass_matrix(*fe_data_, q) * qd);
}

std::shared_ptr<const DeformableBody> make_ffrf_body(std::shared_ptr<const FlexibleBodyData> data) {
  return std::make_shared<FfrfBody>(std::move(data));
}

}  // namespace fmbd
