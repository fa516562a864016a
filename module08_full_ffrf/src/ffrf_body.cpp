// The full FFRF body for the Model (given code, module 8).
#include "fmbd/ffrf.hpp"

namespace fmbd {

MatX FfrfBody::mass_matrix(const VecX& q) const {
  check_state(q, "q", "mass_matrix");
  return ffrf_mass_matrix(*data_, q);
}

VecX FfrfBody::body_forces(const VecX& q, const VecX& qd, const Vec2& g) const {
  check_state(q, "q", "body_forces");
  check_state(qd, "q_dot", "body_forces");
  return ffrf_body_forces(*data_, q, qd, g);
}

double FfrfBody::kinetic_energy(const VecX& q, const VecX& qd) const {
  check_state(q, "q", "kinetic_energy");
  check_state(qd, "q_dot", "kinetic_energy");
  return 0.5 * qd.dot(ffrf_mass_matrix(*data_, q) * qd);
}

std::shared_ptr<const DeformableBody> make_ffrf_body(std::shared_ptr<const FlexibleBodyData> data) {
  return std::make_shared<FfrfBody>(std::move(data));
}

}  // namespace fmbd
