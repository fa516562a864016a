#include <cmath>
#include <stdexcept>
#include <type_traits>

#include "fmbd/applied_forces.hpp"
#include "fmbd/marker.hpp"

namespace fmbd {

ElementForces element_forces(const Model& model, const Force& force, const VecX& q, const VecX& qd, double t) {
  return std::visit(
      [&](const auto& e) -> ElementForces {
        using T = std::decay_t<decltype(e)>;
        if constexpr (std::is_same_v<T, PointForce>) {
          const Marker m = point_marker(model, e.P, q, qd);
          return {m, Marker{}, point_force(m.q, m.s_bar, e.F, e.frame), Vec3::Zero()};
        } else if constexpr (std::is_same_v<T, Torque>) {
          return {body_marker(model, e.body, q, qd), Marker{}, Vec3(0.0, 0.0, e.T(t).f), Vec3::Zero()};
        } else if constexpr (std::is_same_v<T, Tsda>) {
          const Marker mi = point_marker(model, e.P_i, q, qd), mj = point_marker(model, e.P_j, q, qd);
          const Vec2 d = point_position(mj.q, mj.s_bar) - point_position(mi.q, mi.s_bar);
          if (!(d.norm() > 1e-12))
            throw std::domain_error("spring-damper '" + force.name + "': its points '" + model.point(e.P_i).name +
                                    "' and '" + model.point(e.P_j).name +
                                    "' coincide, so the force direction is undefined");
          const PairForces f = tsda_force(mi.q, mi.qd, mi.s_bar, mj.q, mj.qd, mj.s_bar, e.k, e.L0, e.c, e.actuator(t).f);
          return {mi, mj, f.Q_i, f.Q_j};
        } else {
          static_assert(std::is_same_v<T, Rsda>);
          const Marker mi = body_marker(model, e.body_i, q, qd), mj = body_marker(model, e.body_j, q, qd);
          const PairForces f = rsda_force(mi.q, mi.qd, mj.q, mj.qd, e.k, e.theta0, e.c, e.actuator(t).f);
          return {mi, mj, f.Q_i, f.Q_j};
        }
      },
      force.element);
}

void check_force_storage(const Model& model, const VecX& q, const VecX& qd, const VecX& Q_a) {
  Model::check_size(q, model.num_coordinates(), "q", "applied_forces");
  Model::check_size(qd, model.num_coordinates(), "q_dot", "applied_forces");
  Model::check_size(Q_a, model.num_coordinates(), "Q_a", "applied_forces");
}

VecX applied_forces(const Model& model, const VecX& q, const VecX& qd, double t) {
  VecX Q = VecX::Zero(model.num_coordinates());
  applied_forces(model, q, qd, t, Q);
  return Q;
}

}  // namespace fmbd
