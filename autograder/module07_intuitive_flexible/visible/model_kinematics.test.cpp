// Module 7, tasks T2-T3 through whole models (visible tests): the flexible slider-crank's
// constraint Jacobian against central differences of C(q, t), and its gamma against the second
// time derivative of C along a smooth motion, at random states with deformed rods. The given
// assembly of modules 1 and 2 chains the joint kernels with the node markers of tasks T1-T3.
#include <string>

#include "fmbd/applied_forces.hpp"
#include "fmbd/constraints.hpp"
#include "fmbd/marker.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/gamma.hpp"
#include "flexible_checks.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m07;

GRADED_TEST("flexible slider crank constraint Jacobian matches differences of C at deformed states",
            "[M07][T2][points=2]") {
  Random rnd(7211);
  const FlexibleExample ex = flexible_slider_crank();
  for (int trial = 0; trial < 3; ++trial) {
    const VecX q = random_model_state(ex.model, ex.q0, rnd, 0.02, 0.4, 0.05);
    const double t = rnd.uniform(0.0, 0.05);
    check_constraint_jacobian(ex.model, q, t, "slider crank, trial " + std::to_string(trial));
  }
}

GRADED_TEST("flexible slider crank gamma matches the second time derivative of C at deformed states",
            "[M07][T3][points=2]") {
  Random rnd(7311);
  FlexibleSliderCrankParameters p;
  p.crank_speed = 40.0;
  const FlexibleExample ex = flexible_slider_crank(p);
  for (int trial = 0; trial < 3; ++trial) {
    const VecX q = random_model_state(ex.model, ex.q0, rnd, 0.02, 0.4, 0.05);
    const VecX qd = random_model_rates(ex.model, rnd, 2.0, 40.0, 20.0);
    const double t = rnd.uniform(0.0, 0.05);
    check_gamma(ex.model, q, qd, t, "slider crank, trial " + std::to_string(trial));
  }
}

GRADED_TEST("a force at a node of the flexible rod does the virtual work of F on the node's displacement",
            "[M07][T2][points=1]") {
  // Q_a's change from a force F at the rod's end, against F^T (r_end(q + h e_i) - r_end(q - h e_i)) / 2h:
  // the generalised force of F on every coordinate of the rod (oracle: differences of the node's
  // position through module 1's point_position).
  Random rnd(7221);
  const FlexibleExample plain = flexible_slider_crank();
  FlexibleExample pushed = flexible_slider_crank();
  const Vec2 F(30.0, -12.0);
  pushed.model.add_point_force("push", pushed.model.find_point("rod end"), F);
  for (int trial = 0; trial < 3; ++trial) {
    const VecX q = random_model_state(plain.model, plain.q0, rnd, 0.02, 0.4, 0.05);
    const VecX qd = VecX::Zero(q.size());
    const VecX Q = applied_forces(pushed.model, q, qd, 0.0) - applied_forces(plain.model, q, qd, 0.0);
    const auto work = [&](const VecX& x) {
      return VecX::Constant(1, F.dot(point_position(pushed.model, pushed.model.find_point("rod end"), x)));
    };
    const VecX expected = finite_difference_jacobian(work, q, 1e-6).transpose();
    CAPTURE(trial);
    CHECK_CLOSE_NAMED(
        "your generalised force Q of the force on the node", Q, expected, (Tolerance{1e-6, 1e-6}),
        "a force on a node's pose acts on all of its body's coordinates, by the virtual work it does through "
        "the node's G_k (add_node_force_rows, M07T2)");
  }
}
