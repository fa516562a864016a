// Exercise file of module 3, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 3, tasks T2 and T3: generalised forces of gravity, point forces and spring-dampers, and
// the system's Q_a assembled from them.
#include "fmbd/applied_forces.hpp"
#include "fmbd/errors.hpp"

namespace fmbd {

Vec3 gravity_force(double mass, const Vec2& g) {
  // TODO(M03T2): the generalised force (Q_x, Q_y, Q_phi) of gravity g on a body of mass m
  //   (README section 2, applied_forces.hpp). Stuck? ./workbook hint M03T2
  unused(mass, g);
  throw NotImplemented("M03T2 gravity_force");
}

Vec3 point_force(const Vec3& q_i, const Vec2& s_i, const Vec2& F, Frame frame) {
  // TODO(M03T2): the generalised force Q_i = (Q_x, Q_y, Q_phi) of a force F at the point s_i of
  //   body i, by virtual work (README section 2, applied_forces.hpp). F is global for
  //   Frame::global and turns with body i for Frame::body. Build on point_jacobian() of module 1.
  unused(q_i, s_i, F, frame);
  throw NotImplemented("M03T2 point_force");
}

PairForces tsda_force(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j, const Vec3& qd_j,
                      const Vec2& s_j, double k, double L0, double c, double f_a) {
  // TODO(M03T3): the generalised forces Q_i, Q_j of a translational spring-damper-actuator
  //   (README section 2, applied_forces.hpp): tension f = k (L - L0) + c L_dot + f_a along
  //   u = d / L, with d = r_Pj - r_Pi, L = |d| and L_dot the rate of L; +f u acts on P_i and
  //   -f u on P_j. Stuck? ./workbook hint M03T3
  unused(q_i, qd_i, s_i, q_j, qd_j, s_j, k, L0, c, f_a);
  throw NotImplemented("M03T3 tsda_force");
}

PairForces rsda_force(const Vec3& q_i, const Vec3& qd_i, const Vec3& q_j, const Vec3& qd_j, double k,
                      double theta0, double c, double T_a) {
  // TODO(M03T3): the generalised forces Q_i, Q_j of a rotational spring-damper-actuator on
  //   theta = phi_j - phi_i: T = k (theta - theta0) + c theta_dot + T_a, +T on body i and -T on
  //   body j (README section 2, applied_forces.hpp).
  unused(q_i, qd_i, q_j, qd_j, k, theta0, c, T_a);
  throw NotImplemented("M03T3 rsda_force");
}

void add_generalised_force(VecX& Q, const Marker& marker, const Vec3& Q_kernel) {
  if (marker.on_node()) {  // a node of a flexible body: the force chained with the node's G (module 7)
    add_node_generalised_force(Q, marker, Q_kernel);
    return;
  }
  // TODO(M03T3): add the kernel force Q_kernel = (Q_x, Q_y, Q_phi) of the rigid body marker.body
  //   to Q at the body's 3 rows, which start at marker.offset (README section 2,
  //   applied_forces.hpp). The ground has no rows. Stuck? ./workbook hint M03T3
  unused(Q, Q_kernel);
  throw NotImplemented("M03T3 add_generalised_force");
}

void applied_forces(const Model& model, const VecX& q, const VecX& qd, double t, VecX& Q_a) {
  check_force_storage(model, q, qd, Q_a);
  // TODO(M03T3): the system's Q_a into Q_a (n), README section 2, applied_forces.hpp; it holds an
  //   earlier call's entries. Gravity model.gravity() on each rigid body (your gravity_force) at
  //   its rows from model.offset(BodyId{k}); a flexible body adds its own forces:
  //   bodies()[k].deformable->add_forces(q, qd, model.gravity(), offset, Q_a) (from module 7 on);
  //   then each force element of model.forces(): element_forces(model, force, q, qd, t) gives
  //   its markers and forces, which your add_generalised_force places.
  unused(model, q, qd, t, Q_a);
  throw NotImplemented("M03T3 applied_forces");
}

}  // namespace fmbd
