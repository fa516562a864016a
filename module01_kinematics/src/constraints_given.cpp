#include "fmbd/constraints.hpp"

#include <type_traits>

#include "fmbd/drivers.hpp"
#include "fmbd/joints.hpp"

namespace fmbd {

ConstraintBlock evaluate_constraint(const Model& model, const Constraint& constraint, const VecX& q,
                                    double t) {
  return evaluate_constraint(constraint, constraint_markers(model, constraint, q, VecX::Zero(q.size())), t);
}

ConstraintBlock evaluate_constraint(const Constraint& constraint, const ConstraintMarkers& markers, double t) {
  const Vec3& q_i = markers.i.q;
  const Vec3& q_j = markers.j.q;
  const Vec2& s_i = markers.i.s_bar;  // the point P_i (or P) as its kernel sees it
  const Vec2& s_j = markers.j.s_bar;
  return std::visit(
      [&](const auto& c) -> ConstraintBlock {
        using T = std::decay_t<decltype(c)>;
        if constexpr (std::is_same_v<T, Revolute>) {
          return revolute_constraint(q_i, s_i, q_j, s_j);
        } else if constexpr (std::is_same_v<T, Translational>) {
          return translational_constraint(q_i, s_i, q_j, s_j, c.axis_i, c.phi0);
        } else if constexpr (std::is_same_v<T, Fixed>) {
          return fixed_constraint(q_i, s_i, q_j, s_j, c.phi0);
        } else if constexpr (std::is_same_v<T, AbsoluteAngleDriver>) {
          return absolute_angle_constraint(q_i, c.f(t));
        } else if constexpr (std::is_same_v<T, RelativeAngleDriver>) {
          return relative_angle_constraint(q_i, q_j, c.f(t));
        } else if constexpr (std::is_same_v<T, PointCoordinateDriver>) {
          return point_coordinate_constraint(q_i, s_i, c.axis, c.f(t));
        } else {
          static_assert(std::is_same_v<T, DistanceDriver>);
          return distance_constraint(q_i, s_i, q_j, s_j, c.f(t));
        }
      },
      constraint.type);
}

void add_jacobian_columns(MatX& Cq, int first_row, const Marker& marker, const RowBlock& block) {
  if (marker.body.is_ground()) return;
  Cq.block(first_row, marker.offset, block.rows(), marker.G.cols()) += block * marker.G;
}

ConstraintEvaluation evaluate_constraints(const Model& model, const VecX& q, double t) {
  Model::check_size(q, model.num_coordinates(), "q", "evaluate_constraints");
  const int m = model.num_constraints();
  const VecX zero = VecX::Zero(q.size());
  ConstraintEvaluation e{VecX::Zero(m), MatX::Zero(m, model.num_coordinates()), VecX::Zero(m)};
  for (const Constraint& c : model.constraints()) {
    const ConstraintMarkers markers = constraint_markers(model, c, q, zero);
    const ConstraintBlock b = evaluate_constraint(c, markers, t);
    if (b.C.size() != c.rows || b.Cq_i.rows() != c.rows || b.Cq_j.rows() != c.rows || b.Ct.size() != c.rows)
      throw std::logic_error(std::string(c.type_name()) + " '" + c.name + "': its block has " +
                             std::to_string(b.C.size()) + " rows, expected " + std::to_string(c.rows) +
                             " (start from ConstraintBlock::zero(rows))");
    e.C.segment(c.first_row, c.rows) = b.C;
    e.Ct.segment(c.first_row, c.rows) = b.Ct;
    add_jacobian_columns(e.Cq, c.first_row, markers.i, b.Cq_i);
    add_jacobian_columns(e.Cq, c.first_row, markers.j, b.Cq_j);
  }
  return e;
}

VecX constraints(const Model& model, const VecX& q, double t) { return evaluate_constraints(model, q, t).C; }

MatX constraint_jacobian(const Model& model, const VecX& q, double t) {
  return evaluate_constraints(model, q, t).Cq;
}

VecX constraint_time_derivative(const Model& model, const VecX& q, double t) {
  return evaluate_constraints(model, q, t).Ct;
}

}  // namespace fmbd
