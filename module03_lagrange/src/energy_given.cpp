#include "fmbd/energy.hpp"

#include <stdexcept>
#include <type_traits>

#include "fmbd/constraints.hpp"
#include "fmbd/marker.hpp"

namespace fmbd {

namespace {

// Length of a spring-damper and its rate.
struct Stretch {
  double L, L_dot;
};
Stretch stretch(const Model& model, const Tsda& e, const VecX& q, const VecX& qd) {
  const Marker mi = point_marker(model, e.P_i, q, qd), mj = point_marker(model, e.P_j, q, qd);
  const Vec2 d = point_position(mj.q, mj.s_bar) - point_position(mi.q, mi.s_bar);
  const Vec2 d_dot = point_jacobian(mj.q, mj.s_bar) * mj.qd - point_jacobian(mi.q, mi.s_bar) * mi.qd;
  const double L = d.norm();
  return {L, L > 0 ? d.dot(d_dot) / L : 0.0};
}

double rigid_kinetic_energy(const Body& b, const Vec3& qd) {
  return 0.5 * (b.mass * qd.head<2>().squaredNorm() + b.inertia * qd(2) * qd(2));
}

}  // namespace

double kinetic_energy(const Model& model, const VecX& qd) {
  Model::check_size(qd, model.num_coordinates(), "q_dot", "kinetic_energy");
  double T = 0;
  for (int k = 0; k < model.num_bodies(); ++k) {
    const Body& b = model.bodies()[k];
    const int at = model.offset(BodyId{k});
    if (b.is_flexible())
      throw std::invalid_argument("kinetic_energy(model, q_dot): body '" + b.name +
                                  "' is flexible, and its kinetic energy depends on q: use kinetic_energy(model, q, q_dot)");
    T += rigid_kinetic_energy(b, qd.segment<3>(at));
  }
  return T;
}

double kinetic_energy(const Model& model, const VecX& q, const VecX& qd) {
  Model::check_size(q, model.num_coordinates(), "q", "kinetic_energy");
  Model::check_size(qd, model.num_coordinates(), "q_dot", "kinetic_energy");
  double T = 0;
  for (int k = 0; k < model.num_bodies(); ++k) {
    const Body& b = model.bodies()[k];
    const int at = model.offset(BodyId{k}), n = b.num_coordinates();
    T += b.is_flexible() ? b.deformable->kinetic_energy(q.segment(at, n), qd.segment(at, n))
                         : rigid_kinetic_energy(b, qd.segment<3>(at));
  }
  return T;
}

double potential_energy(const Model& model, const VecX& q) {
  Model::check_size(q, model.num_coordinates(), "q", "potential_energy");
  double V = 0;
  for (int k = 0; k < model.num_bodies(); ++k) {
    const Body& b = model.bodies()[k];
    const int at = model.offset(BodyId{k});
    V += b.is_flexible() ? b.deformable->potential_energy(q.segment(at, b.num_coordinates()), model.gravity())
                         : -b.mass * model.gravity().dot(q.segment<2>(at));
  }
  const VecX zero = VecX::Zero(q.size());
  for (const Force& force : model.forces()) {
    if (auto* e = std::get_if<PointForce>(&force.element); e && e->frame == Frame::global) {
      const Marker m = point_marker(model, e->P, q, zero);
      V -= e->F.dot(point_position(m.q, m.s_bar));
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
              const Marker m = point_marker(model, e.P, q, qd);
              P += (rotation(m.q(2)) * e.F).dot(point_jacobian(m.q, m.s_bar) * m.qd);
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

double driver_power(const Model& model, const VecX& q, const VecX& lambda, double t) {
  Model::check_size(lambda, model.num_constraints(), "lambda", "driver_power");
  double P = 0;
  for (const Constraint& c : model.constraints()) {
    if (std::holds_alternative<Revolute>(c.type) || std::holds_alternative<Translational>(c.type) ||
        std::holds_alternative<Fixed>(c.type))
      continue;
    P += lambda.segment(c.first_row, c.rows).dot(evaluate_constraint(model, c, q, t).Ct);
  }
  return P;
}

}  // namespace fmbd
