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

VecX constraint_gamma(const Model& model, const VecX& q, const VecX& qd, double t) {
  Model::check_size(q, model.num_coordinates(), "q", "constraint_gamma");
  Model::check_size(qd, model.num_coordinates(), "q_dot", "constraint_gamma");
  VecX gamma = VecX::Zero(model.num_constraints());
  for (const Constraint& c : model.constraints()) {
    // The kernels see the markers (marker.hpp): a rigid body's own coordinates, or an FE node.
    const ConstraintMarkers markers = constraint_markers(model, c, q, qd);
    RowVector g = kernel_gamma(c, markers, t);
    // A marker that accelerates without q_ddot (an FE node: c = G_dot q_dot) moves the kernel's
    // acceleration equation B q_marker_ddot = g to B G q_ddot = g - B c.
    if (!markers.i.convective.isZero(0.0) || !markers.j.convective.isZero(0.0)) {
      const ConstraintBlock b = evaluate_constraint(c, markers, t);
      if (g.size() == c.rows && b.Cq_i.rows() == c.rows && b.Cq_j.rows() == c.rows)
        g -= b.Cq_i * markers.i.convective + b.Cq_j * markers.j.convective;
    }
    if (g.size() != c.rows)
      throw std::logic_error(std::string(c.type_name()) + " '" + c.name + "': gamma has " +
                             std::to_string(g.size()) + " rows, expected " + std::to_string(c.rows));
    gamma.segment(c.first_row, c.rows) = g;
  }
  return gamma;
}

}  // namespace fmbd
