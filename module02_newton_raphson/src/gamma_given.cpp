#include <type_traits>

#include "fmbd/constraints.hpp"
#include "fmbd/gamma.hpp"

namespace fmbd {

RowVector kernel_gamma(const Constraint& c, const ConstraintMarkers& markers, double t) {
  const Vec3 &q_i = markers.i.q, &qd_i = markers.i.qd, &q_j = markers.j.q, &qd_j = markers.j.qd;
  const Vec2 &s_i = markers.i.s_bar, &s_j = markers.j.s_bar;
  return std::visit(
      [&](const auto& k) -> RowVector {
        using T = std::decay_t<decltype(k)>;
        if constexpr (std::is_same_v<T, Revolute>) {
          return revolute_gamma(q_i, qd_i, s_i, q_j, qd_j, s_j);
        } else if constexpr (std::is_same_v<T, Translational>) {
          return translational_gamma(q_i, qd_i, s_i, q_j, qd_j, s_j, k.axis_i);
        } else if constexpr (std::is_same_v<T, Fixed>) {
          return fixed_gamma(q_i, qd_i, s_i, q_j, qd_j, s_j);
        } else if constexpr (std::is_same_v<T, AbsoluteAngleDriver>) {
          return absolute_angle_gamma(k.f(t));
        } else if constexpr (std::is_same_v<T, RelativeAngleDriver>) {
          return relative_angle_gamma(k.f(t));
        } else if constexpr (std::is_same_v<T, PointCoordinateDriver>) {
          return point_coordinate_gamma(q_i, qd_i, s_i, k.axis, k.f(t));
        } else {
          static_assert(std::is_same_v<T, DistanceDriver>);
          return distance_gamma(q_i, qd_i, s_i, q_j, qd_j, s_j, k.f(t));
        }
      },
      c.type);
}

RowVector node_gamma_terms(const Constraint& c, const ConstraintMarkers& markers, double t) {
  RowVector terms = RowVector::Zero(c.rows);
  if (!markers.i.on_node() && !markers.j.on_node()) return terms;
  // Each node's body applies its own chain rule (module 7's node_gamma_term).
  const ConstraintBlock b = evaluate_constraint(c, markers, t);
  if (markers.i.on_node()) terms += markers.i.deformable->node_gamma_term(markers.i.node_kinematics(), b.Cq_i);
  if (markers.j.on_node()) terms += markers.j.deformable->node_gamma_term(markers.j.node_kinematics(), b.Cq_j);
  return terms;
}

void check_gamma_storage(const Model& model, const VecX& q, const VecX& qd, const VecX& gamma) {
  Model::check_size(q, model.num_coordinates(), "q", "constraint_gamma");
  Model::check_size(qd, model.num_coordinates(), "q_dot", "constraint_gamma");
  Model::check_size(gamma, model.num_constraints(), "gamma", "constraint_gamma");
}

VecX constraint_gamma(const Model& model, const VecX& q, const VecX& qd, double t) {
  VecX gamma = VecX::Zero(model.num_constraints());
  constraint_gamma(model, q, qd, t, gamma);
  return gamma;
}

}  // namespace fmbd
