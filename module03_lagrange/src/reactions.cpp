// Exercise file of module 3, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 3, task T5: reaction forces of the joints and efforts of the drivers.
#include <stdexcept>
#include <string>

#include "fmbd/constraints.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/reactions.hpp"

namespace fmbd {

namespace {

// The constraint with index c, its block at q and its multipliers (given helper).
struct ConstraintForces {
  const Constraint& constraint;
  ConstraintBlock block;
  VecX lambda;  // lambda_c, rows of this constraint
};

[[maybe_unused]] ConstraintForces constraint_forces(const Model& model, int c, const VecX& q, const VecX& lambda,
                                                    bool want_driver) {
  if (c < 0 || c >= static_cast<int>(model.constraints().size()))
    throw std::invalid_argument("constraint " + std::to_string(c) + " does not exist (the model has " +
                                std::to_string(model.constraints().size()) + ")");
  Model::check_size(lambda, model.num_constraints(), "lambda", "reactions");
  const Constraint& constraint = model.constraints()[c];
  if (constraint.is_driver() != want_driver)
    throw std::invalid_argument(std::string(constraint.type_name()) + " '" + constraint.name + "' is " +
                                (want_driver ? "a joint: use joint_reaction()" : "a driver: use driver_effort()"));
  // Joint blocks do not depend on time; drivers' C_q does not either.
  return {constraint, evaluate_constraint(model, constraint, q, 0.0),
          lambda.segment(constraint.first_row, constraint.rows)};
}

// Body-fixed vector of a joint's point on body i (first) or body j (second).
[[maybe_unused]] std::pair<Vec2, Vec2> joint_points(const Model& model, const Constraint& c) {
  return std::visit(
      [&](const auto& joint) -> std::pair<Vec2, Vec2> {
        if constexpr (std::is_same_v<std::decay_t<decltype(joint)>, Revolute> ||
                      std::is_same_v<std::decay_t<decltype(joint)>, Translational> ||
                      std::is_same_v<std::decay_t<decltype(joint)>, Fixed>) {
          return {model.point(joint.P_i).s_bar, model.point(joint.P_j).s_bar};
        } else {
          return {Vec2::Zero(), Vec2::Zero()};
        }
      },
      c.type);
}

}  // namespace

JointReaction joint_reaction(const Model& model, int constraint, const VecX& q, const VecX& lambda) {
  // TODO(M03T5): the reaction of a joint on each of its bodies, at that body's joint point
  //   (README section 4, reactions.hpp): force (global), force_body (body frame) and moment
  //   about the joint point. constraint_forces(model, constraint, q, lambda, false) gives the
  //   joint's block and lambda_c, joint_points() its s_i and s_j. Leave a ground side zero.
  //   Stuck? ./workbook hint M03T5
  unused(model, constraint, q, lambda);
  throw NotImplemented("M03T5 joint_reaction");
}

double driver_effort(const Model& model, int constraint, const VecX& q, const VecX& lambda) {
  // TODO(M03T5): the effort of a driver, -lambda dC/d(driven quantity) (README section 4,
  //   reactions.hpp). constraint_forces(model, constraint, q, lambda, true) gives its lambda.
  //   A distance driver drives |d|, d = r_Pj - r_Pi: compute it from its two points
  //   (std::get_if<DistanceDriver>), since its C does not give it.
  unused(model, constraint, q, lambda);
  throw NotImplemented("M03T5 driver_effort");
}

}  // namespace fmbd
