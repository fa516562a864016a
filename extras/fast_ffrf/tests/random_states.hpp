#pragma once
// Random states of one flexible body for the project's tests of module 8's body forms.
#include <algorithm>

#include "fmbd/flexible_body.hpp"
#include "oracles.hpp"

namespace fmbd::testing {

/// Size of the body: the largest node distance from the centroid.
inline double reach(const ModalBodyData& d) {
  double r = 0;
  for (const NodeModes& node : d.nodes) r = std::max(r, node.x_bar.norm());
  return r;
}

/// Largest nodal translation of Phi_f v.
inline double largest_translation(const ModalBodyData& d, const VecX& v) {
  double worst = 0;
  for (const NodeModes& node : d.nodes) worst = std::max(worst, (node.Phi_t * v).norm());
  return worst;
}

/// A random state (q, q_dot) of the body: deflections of about 5 % of its size, nodal rates of
/// about 2 m/s, frame angle within +-3 rad and angular rate within +-15 rad/s.
inline void random_state(const ModalBodyData& d, Random& rnd, VecX& q, VecX& qd) {
  const int n_f = d.num_modes();
  q.resize(3 + n_f);
  qd.resize(3 + n_f);
  q.head<2>() = rnd.vec2(-2.0, 2.0);
  q(2) = rnd.uniform(-3.0, 3.0);
  VecX f = rnd.vector(n_f, -1.0, 1.0);
  q.tail(n_f) = f * (0.05 * reach(d) / largest_translation(d, f));
  qd.head<2>() = rnd.vec2(-2.0, 2.0);
  qd(2) = rnd.uniform(-15.0, 15.0);
  f = rnd.vector(n_f, -1.0, 1.0);
  qd.tail(n_f) = f * (2.0 / largest_translation(d, f));
}

}  // namespace fmbd::testing
