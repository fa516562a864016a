#include "fmbd/constraints.hpp"

#include <stdexcept>
#include <string>
#include <type_traits>

#include "fmbd/drivers.hpp"
#include "fmbd/joints.hpp"

namespace fmbd {

ConstraintBlock evaluate_constraint(const Model& model, const Constraint& constraint, const VecX& q,
                                    double t) {
  return evaluate_constraint(constraint, constraint_markers(model, constraint, q), t);
}

namespace {

ConstraintBlock kernel_block(const Constraint& constraint, const ConstraintMarkers& markers, double t) {
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

}  // namespace

ConstraintBlock evaluate_constraint(const Constraint& constraint, const ConstraintMarkers& markers, double t) {
  ConstraintBlock b = kernel_block(constraint, markers, t);
  const int rows = constraint.rows;
  if (b.C.size() != rows || b.Cq_i.rows() != rows || b.Cq_j.rows() != rows || b.Ct.size() != rows)
    throw std::logic_error(std::string(constraint.type_name()) + " '" + constraint.name + "': its block has " +
                           std::to_string(b.C.size()) + " rows, expected " + std::to_string(rows) +
                           " (start from ConstraintBlock::zero(rows))");
  return b;
}

void check_constraint_storage(const Model& model, const VecX& q, const ConstraintEvaluation& out) {
  Model::check_size(q, model.num_coordinates(), "q", "evaluate_constraints");
  const Eigen::Index m = model.num_constraints(), n = model.num_coordinates();
  if (out.C.size() != m || out.Ct.size() != m || out.Cq.rows() != m || out.Cq.cols() != n)
    throw std::invalid_argument("evaluate_constraints: the storage has C " + std::to_string(out.C.size()) + ", C_q " +
                                std::to_string(out.Cq.rows()) + " x " + std::to_string(out.Cq.cols()) + " and C_t " +
                                std::to_string(out.Ct.size()) + " entries; this model needs " + std::to_string(m) +
                                ", " + std::to_string(m) + " x " + std::to_string(n) + " and " + std::to_string(m) +
                                " (constraint_storage(model))");
}

ConstraintEvaluation constraint_storage(const Model& model) {
  const int m = model.num_constraints(), n = model.num_coordinates();
  return ConstraintEvaluation{VecX::Zero(m), MatX::Zero(m, n), VecX::Zero(m)};
}

ConstraintEvaluation evaluate_constraints(const Model& model, const VecX& q, double t) {
  ConstraintEvaluation e = constraint_storage(model);
  evaluate_constraints(model, q, t, e);
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
