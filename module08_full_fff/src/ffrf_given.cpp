// Given code of the nodal FFRF (declared in fmbd/ffrf.hpp): the node maps and biases stacked over
// the body, which the exercises M08T3 to M08T5 use.
#include "fmbd/ffrf.hpp"

namespace fmbd {

MatX stacked_map(const FlexibleBodyData& data, const VecX& q) {
  MatX L(3 * data.nodes.size(), q.size());
  for (std::size_t k = 0; k < data.nodes.size(); ++k) L.middleRows<3>(3 * k) = node_acceleration_map(data.nodes[k], q);
  return L;
}

VecX stacked_bias(const FlexibleBodyData& data, const VecX& q, const VecX& qd) {
  VecX g(3 * data.nodes.size());
  for (std::size_t k = 0; k < data.nodes.size(); ++k) g.segment<3>(3 * k) = node_acceleration_bias(data.nodes[k], q, qd);
  return g;
}

}  // namespace fmbd
