#include "fmbd/energy.hpp"

#include <type_traits>

namespace fmbd {

namespace {

// Length of a spring-damper and its rate.
struct Stretch {
  double L, L_dot;
};
Stretch stretch(const Model& model, const Tsda& e, const VecX& q, const VecX& qd) {
  const Point &Pi = model.point(e.P_i), &Pj = model.point(e.P_j);
  const Vec3 q_i = model.body_coordinates(q, Pi.body), q_j = model.body_coordinates(q, Pj.body);
  const Vec2 d = point_position(q_j, Pj.s_bar) - point_position(q_i, Pi.s_bar);
  const Vec2 d_dot = point_jacobian(q_j, Pj.s_bar) * model.body_coordinates(qd, Pj.body) -
                     point_jacobian(q_i, Pi.s_bar) * model.body_coordinates(qd, Pi.body);
  const double L = d.norm();
  return {L, L > 0 ? d.dot(d_dot) / L : 0.0};
}

}  // namespace

double kinetic_energy(const Model& model, const VecX& qd) {
  Model::check_size(qd, model.num_coordinates(), "q_dot", "kinetic_energy");
  double T = 0;
  for (int k = 0; k < model.num_bodies(); ++k) {
    const Body& b = model.bodies()[k];
    T += 0.5 * (b.mass * qd.segment<2>(3 * k).squaredNorm() + b.inertia * qd(3 * k + 2) * qd(3 * k + 2));
  }
  return T;
}

double potential_energy(const Model& model, const VecX& q) {
  Model::check_size(q, model.num_coordinates(), "q", "potential_energy");
  double V = 0;
  for (int k = 0; k < model.num_bodies(); ++k) V -= model.bodies()[k].mass * model.gravity().dot(q.segment<2>(3 * k));
  const VecX zero = VecX::Zero(q.size());
  for (const Force& force : model.forces()) {
    if (auto* e = std::get_if<PointForce>(&force.element); e && e->frame == Frame::global) {
      const Point& P = model.point(e->P);
      V -= e->F.dot(point_position(model.body_coordinates(q, P.body), P.s_bar));
    } else if (auto* e = std::get_if<Tsda>(&force.element)) {
      const double dL = stretch(model, *e, q, zero).L - e->L0;
      V += 0.5 * e->k * dL * dL;
    } else if (auto* e = std::get_if<Rsda>(&force.element)) {
      const double dtheta = model.body_coordinates(q, e->body_j)(2) - model.body_coordinates(q, e->body_i)(2) - e->theta0;
      V += 0.5 * e->k * dtheta * dtheta;
    }
  }
  return V;
}

double nonconservative_power(const Model& model, const VecX& q, const VecX& qd, double t) {
  Model::check_size(q, model.num_coordinates(), "q", "nonconservative_power");
  Model::check_size(qd, model.num_coordinates(), "q_dot", "nonconservative_power");
  double P = 0;
  for (const Force& force : model.forces()) {
    std::visit(
        [&](const auto& e) {
          using T = std::decay_t<decltype(e)>;
          if constexpr (std::is_same_v<T, PointForce>) {
            if (e.frame == Frame::body) {
              const Point& p = model.point(e.P);
              const Vec3 q_b = model.body_coordinates(q, p.body);
              const Vec2 v = point_jacobian(q_b, p.s_bar) * model.body_coordinates(qd, p.body);
              P += (rotation(q_b(2)) * e.F).dot(v);
            }
          } else if constexpr (std::is_same_v<T, Torque>) {
            P += e.T(t).f * model.body_coordinates(qd, e.body)(2);
          } else if constexpr (std::is_same_v<T, Tsda>) {
            const Stretch s = stretch(model, e, q, qd);  // tension f does power -f L_dot
            P -= (e.c * s.L_dot + e.actuator(t).f) * s.L_dot;
          } else {
            const double theta_dot = model.body_coordinates(qd, e.body_j)(2) - model.body_coordinates(qd, e.body_i)(2);
            P -= (e.c * theta_dot + e.actuator(t).f) * theta_dot;
          }
        },
        force.element);
  }
  return P;
}

}  // namespace fmbd
