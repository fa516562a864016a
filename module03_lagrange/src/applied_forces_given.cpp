#include <cmath>
#include <stdexcept>
#include <type_traits>

#include "fmbd/applied_forces.hpp"
#include "fmbd/marker.hpp"

namespace fmbd {

VecX applied_forces(const Model& model, const VecX& q, const VecX& qd, double t) {
  Model::check_size(q, model.num_coordinates(), "q", "applied_forces");
  Model::check_size(qd, model.num_coordinates(), "q_dot", "applied_forces");
  VecX Q = VecX::Zero(model.num_coordinates());
  for (int k = 0; k < model.num_bodies(); ++k) {
    const Body& body = model.bodies()[k];
    const int at = model.offset(BodyId{k});
    if (body.is_flexible()) {
      body.deformable->add_forces(q, qd, model.gravity(), at, Q);  // module 7 on: the body's own terms
    } else {
      Q.segment<3>(at) += gravity_force(body.mass, model.gravity());
    }
  }

  // Every element acts through markers (marker.hpp): its kernel force Q_kernel becomes G^T Q_kernel.
  for (const Force& force : model.forces()) {
    std::visit(
        [&](const auto& e) {
          using T = std::decay_t<decltype(e)>;
          if constexpr (std::is_same_v<T, PointForce>) {
            const Marker m = point_marker(model, e.P, q, qd);
            add_generalised_force(Q, m, point_force(m.q, m.s_bar, e.F, e.frame));
          } else if constexpr (std::is_same_v<T, Torque>) {
            add_generalised_force(Q, body_marker(model, e.body, q, qd), Vec3(0.0, 0.0, e.T(t).f));
          } else if constexpr (std::is_same_v<T, Tsda>) {
            const Marker mi = point_marker(model, e.P_i, q, qd), mj = point_marker(model, e.P_j, q, qd);
            const Vec2 d = point_position(mj.q, mj.s_bar) - point_position(mi.q, mi.s_bar);
            if (!(d.norm() > 1e-12))
              throw std::domain_error("spring-damper '" + force.name + "': its points '" + model.point(e.P_i).name +
                                      "' and '" + model.point(e.P_j).name +
                                      "' coincide, so the force direction is undefined");
            const PairForces f =
                tsda_force(mi.q, mi.qd, mi.s_bar, mj.q, mj.qd, mj.s_bar, e.k, e.L0, e.c, e.actuator(t).f);
            add_generalised_force(Q, mi, f.Q_i);
            add_generalised_force(Q, mj, f.Q_j);
          } else {
            static_assert(std::is_same_v<T, Rsda>);
            const Marker mi = body_marker(model, e.body_i, q, qd), mj = body_marker(model, e.body_j, q, qd);
            const PairForces f = rsda_force(mi.q, mi.qd, mj.q, mj.qd, e.k, e.theta0, e.c, e.actuator(t).f);
            add_generalised_force(Q, mi, f.Q_i);
            add_generalised_force(Q, mj, f.Q_j);
          }
        },
        force.element);
  }
  return Q;
}

}  // namespace fmbd
