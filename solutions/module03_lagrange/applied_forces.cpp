// Module 3, tasks T2 and T3: generalised forces of gravity, point forces and spring-dampers, and
// the system's Q_a assembled from them.
#include "fmbd/applied_forces.hpp"
#include "fmbd/errors.hpp"

namespace fmbd {

Vec3 gravity_force(double mass, const Vec2& g) {
  // TASK(M03T2): the generalised force (Q_x, Q_y, Q_phi) of gravity g on a body of mass m
  //   (README section 2, applied_forces.hpp). Stuck? ./workbook hint M03T2
  // BEGIN SOLUTION
  return Vec3(mass * g.x(), mass * g.y(), 0.0);
  // END SOLUTION
  // STUB: unused(mass, g);
  // STUB: throw NotImplemented("M03T2 gravity_force");
}

Vec3 point_force(const Vec3& q_i, const Vec2& s_i, const Vec2& F, Frame frame) {
  // TASK(M03T2): the generalised force Q_i = (Q_x, Q_y, Q_phi) of a force F at the point s_i of
  //   body i, by virtual work (README section 2, applied_forces.hpp). F is global for
  //   Frame::global and turns with body i for Frame::body. Build on point_jacobian() of module 1.
  // BEGIN SOLUTION
  const Vec2 F_global = frame == Frame::global ? F : Vec2(rotation(q_i(2)) * F);
  return point_jacobian(q_i, s_i).transpose() * F_global;
  // END SOLUTION
  // STUB: unused(q_i, s_i, F, frame);
  // STUB: throw NotImplemented("M03T2 point_force");
}

PairForces tsda_force(const Vec3& q_i, const Vec3& qd_i, const Vec2& s_i, const Vec3& q_j, const Vec3& qd_j,
                      const Vec2& s_j, double k, double L0, double c, double f_a) {
  // TASK(M03T3): the generalised forces Q_i, Q_j of a translational spring-damper-actuator
  //   (README section 2, applied_forces.hpp): tension f = k (L - L0) + c L_dot + f_a along
  //   u = d / L, with d = r_Pj - r_Pi, L = |d| and L_dot the rate of L; +f u acts on P_i and
  //   -f u on P_j. Stuck? ./workbook hint M03T3
  // BEGIN SOLUTION
  const PointJacobian J_i = point_jacobian(q_i, s_i), J_j = point_jacobian(q_j, s_j);
  const Vec2 d = point_position(q_j, s_j) - point_position(q_i, s_i);
  const Vec2 d_dot = J_j * qd_j - J_i * qd_i;
  const double L = d.norm();
  const Vec2 u = d / L;
  const double f = k * (L - L0) + c * u.dot(d_dot) + f_a;
  return {J_i.transpose() * (f * u), J_j.transpose() * (-f * u)};
  // END SOLUTION
  // STUB: unused(q_i, qd_i, s_i, q_j, qd_j, s_j, k, L0, c, f_a);
  // STUB: throw NotImplemented("M03T3 tsda_force");
}

PairForces rsda_force(const Vec3& q_i, const Vec3& qd_i, const Vec3& q_j, const Vec3& qd_j, double k,
                      double theta0, double c, double T_a) {
  // TASK(M03T3): the generalised forces Q_i, Q_j of a rotational spring-damper-actuator on
  //   theta = phi_j - phi_i: T = k (theta - theta0) + c theta_dot + T_a, +T on body i and -T on
  //   body j (README section 2, applied_forces.hpp).
  // BEGIN SOLUTION
  const double T = k * (q_j(2) - q_i(2) - theta0) + c * (qd_j(2) - qd_i(2)) + T_a;
  return {Vec3(0.0, 0.0, T), Vec3(0.0, 0.0, -T)};
  // END SOLUTION
  // STUB: unused(q_i, qd_i, q_j, qd_j, k, theta0, c, T_a);
  // STUB: throw NotImplemented("M03T3 rsda_force");
}

void add_generalised_force(VecX& Q, const Marker& marker, const Vec3& Q_kernel) {
  if (marker.on_node()) {  // a node of a flexible body: the force chained with the node's G (module 7)
    add_node_generalised_force(Q, marker, Q_kernel);
    return;
  }
  // TASK(M03T3): add the kernel force Q_kernel = (Q_x, Q_y, Q_phi) of the rigid body marker.body
  //   to Q at the body's 3 rows, which start at marker.offset (README section 2,
  //   applied_forces.hpp). The ground has no rows. Stuck? ./workbook hint M03T3
  // BEGIN SOLUTION
  if (marker.body.is_ground()) return;
  Q.segment<3>(marker.offset) += Q_kernel;
  // END SOLUTION
  // STUB: unused(Q, Q_kernel);
  // STUB: throw NotImplemented("M03T3 add_generalised_force");
}

void applied_forces(const Model& model, const VecX& q, const VecX& qd, double t, VecX& Q_a) {
  check_force_storage(model, q, qd, Q_a);
  // TASK(M03T3): the system's Q_a into Q_a (n), README section 2, applied_forces.hpp; it holds an
  //   earlier call's entries. Gravity model.gravity() on each rigid body (your gravity_force) at
  //   its rows from model.offset(BodyId{k}); a flexible body adds its own forces:
  //   bodies()[k].deformable->add_forces(q, qd, model.gravity(), offset, Q_a) (from module 7 on);
  //   then each force element of model.forces(): element_forces(model, force, q, qd, t) gives
  //   its markers and forces, which your add_generalised_force places.
  // BEGIN SOLUTION
  Q_a.setZero();
  for (int k = 0; k < model.num_bodies(); ++k) {
    const Body& body = model.bodies()[k];
    const int at = model.offset(BodyId{k});
    if (body.is_flexible()) {
      body.deformable->add_forces(q, qd, model.gravity(), at, Q_a);
    } else {
      Q_a.segment<3>(at) += gravity_force(body.mass, model.gravity());
    }
  }
  for (const Force& force : model.forces()) {
    const ElementForces f = element_forces(model, force, q, qd, t);
    add_generalised_force(Q_a, f.i, f.Q_i);
    add_generalised_force(Q_a, f.j, f.Q_j);
  }
  // END SOLUTION
  // STUB: unused(model, q, qd, t, Q_a);
  // STUB: throw NotImplemented("M03T3 applied_forces");
}

}  // namespace fmbd
