#include <type_traits>

#include "fmbd/gamma.hpp"

namespace fmbd {

VecX constraint_gamma(const Model& model, const VecX& q, const VecX& qd, double t) {
  Model::check_size(q, model.num_coordinates(), "q", "constraint_gamma");
  Model::check_size(qd, model.num_coordinates(), "q_dot", "constraint_gamma");
  VecX gamma = VecX::Zero(model.num_constraints());
  for (const Constraint& c : model.constraints()) {
    const Vec3 q_i = model.body_coordinates(q, c.body_i), qd_i = model.body_coordinates(qd, c.body_i);
    const Vec3 q_j = model.body_coordinates(q, c.body_j), qd_j = model.body_coordinates(qd, c.body_j);
    auto s = [&](PointId P) { return model.point(P).s_bar; };
    const RowVector g = std::visit(
        [&](const auto& k) -> RowVector {
          using T = std::decay_t<decltype(k)>;
          if constexpr (std::is_same_v<T, Revolute>) {
            return revolute_gamma(q_i, qd_i, s(k.P_i), q_j, qd_j, s(k.P_j));
          } else if constexpr (std::is_same_v<T, Translational>) {
            return translational_gamma(q_i, qd_i, s(k.P_i), q_j, qd_j, s(k.P_j), k.axis_i);
          } else if constexpr (std::is_same_v<T, Fixed>) {
            return fixed_gamma(q_i, qd_i, s(k.P_i), q_j, qd_j, s(k.P_j));
          } else if constexpr (std::is_same_v<T, AbsoluteAngleDriver>) {
            return absolute_angle_gamma(k.f(t));
          } else if constexpr (std::is_same_v<T, RelativeAngleDriver>) {
            return relative_angle_gamma(k.f(t));
          } else if constexpr (std::is_same_v<T, PointCoordinateDriver>) {
            return point_coordinate_gamma(q_i, qd_i, s(k.P), k.axis, k.f(t));
          } else {
            static_assert(std::is_same_v<T, DistanceDriver>);
            return distance_gamma(q_i, qd_i, s(k.P_i), q_j, qd_j, s(k.P_j), k.f(t));
          }
        },
        c.type);
    if (g.size() != c.rows)
      throw std::logic_error(std::string(c.type_name()) + " '" + c.name + "': gamma has " +
                             std::to_string(g.size()) + " rows, expected " + std::to_string(c.rows));
    gamma.segment(c.first_row, c.rows) = g;
  }
  return gamma;
}

}  // namespace fmbd
