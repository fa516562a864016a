#include <cmath>
#include <stdexcept>
#include <type_traits>

#include "fmbd/applied_forces.hpp"

namespace fmbd {

VecX applied_forces(const Model& model, const VecX& q, const VecX& qd, double t) {
  Model::check_size(q, model.num_coordinates(), "q", "applied_forces");
  Model::check_size(qd, model.num_coordinates(), "q_dot", "applied_forces");
  VecX Q = VecX::Zero(model.num_coordinates());
  auto add = [&Q](BodyId body, const Vec3& Q_body) {
    if (!body.is_ground()) Q.segment<3>(3 * body.index) += Q_body;
  };
  for (int k = 0; k < model.num_bodies(); ++k) add(BodyId{k}, gravity_force(model.bodies()[k].mass, model.gravity()));

  for (const Force& force : model.forces()) {
    std::visit(
        [&](const auto& e) {
          using T = std::decay_t<decltype(e)>;
          if constexpr (std::is_same_v<T, PointForce>) {
            const Point& P = model.point(e.P);
            add(P.body, point_force(model.body_coordinates(q, P.body), P.s_bar, e.F, e.frame));
          } else if constexpr (std::is_same_v<T, Torque>) {
            add(e.body, Vec3(0.0, 0.0, e.T(t).f));
          } else if constexpr (std::is_same_v<T, Tsda>) {
            const Point &Pi = model.point(e.P_i), &Pj = model.point(e.P_j);
            const Vec3 q_i = model.body_coordinates(q, Pi.body), q_j = model.body_coordinates(q, Pj.body);
            const Vec2 d = point_position(q_j, Pj.s_bar) - point_position(q_i, Pi.s_bar);
            if (!(d.norm() > 1e-12))
              throw std::domain_error("spring-damper '" + force.name + "': its points '" + Pi.name + "' and '" +
                                      Pj.name + "' coincide, so the force direction is undefined");
            const PairForces f = tsda_force(q_i, model.body_coordinates(qd, Pi.body), Pi.s_bar, q_j,
                                            model.body_coordinates(qd, Pj.body), Pj.s_bar, e.k, e.L0, e.c,
                                            e.actuator(t).f);
            add(Pi.body, f.Q_i);
            add(Pj.body, f.Q_j);
          } else {
            static_assert(std::is_same_v<T, Rsda>);
            const PairForces f =
                rsda_force(model.body_coordinates(q, e.body_i), model.body_coordinates(qd, e.body_i),
                           model.body_coordinates(q, e.body_j), model.body_coordinates(qd, e.body_j), e.k,
                           e.theta0, e.c, e.actuator(t).f);
            add(e.body_i, f.Q_i);
            add(e.body_j, f.Q_j);
          }
        },
        force.element);
  }
  return Q;
}

}  // namespace fmbd
