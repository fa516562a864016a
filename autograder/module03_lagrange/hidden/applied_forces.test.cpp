// Module 3, tasks T2 and T3: the applied forces of whole models against virtual work and
// potentials: follower forces (T2: the student's kernels stacked by the test), and spring-dampers
// with the ground on either side (T3: the student's own assembly) (hidden tests).
#include <cmath>
#include <string>

#include "dynamics_checks.hpp"
#include "fmbd/applied_forces.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m03;

namespace {

// -grad V of the model at q by central differences of the test's own potential.
VecX minus_gradient(const Model& model, const VecX& q) {
  auto V = [&](const VecX& x) { return vec({potential_energy_of(model, x)}); };
  return -finite_difference_jacobian(V, q).transpose();
}

// Q_a stacked by the test from the student's kernels (gravity_force of each body and
// element_forces of each element, at their bodies' rows): the kernel tests of T2 need not the
// student's assembly (T3).
VecX kernel_applied_forces(const Model& model, const VecX& q, const VecX& qd, double t) {
  VecX Q = VecX::Zero(model.num_coordinates());
  for (int k = 0; k < model.num_bodies(); ++k)
    Q.segment<3>(model.offset(BodyId{k})) += gravity_force(model.bodies()[k].mass, model.gravity());
  for (const Force& force : model.forces()) {
    const ElementForces f = element_forces(model, force, q, qd, t);
    if (!f.i.body.is_ground()) Q.segment<3>(f.i.offset) += f.Q_i;
    if (!f.j.body.is_ground()) Q.segment<3>(f.j.offset) += f.Q_j;
  }
  return Q;
}

// Three free bodies at random places.
Model three_bodies(Random& rnd) {
  Model m;
  for (int k = 0; k < 3; ++k)
    m.add_body("body " + std::to_string(k), rnd.uniform(0.5, 3.0), rnd.uniform(0.05, 0.5), rnd.vec3(-1, 1));
  return m;
}

// Q of gravity and point forces with a slip: follower forces not rotated, or the moment arm
// wrong (`arm`: 0 none, 1 right A I~ s, 2 A s instead of A I~ s).
VecX point_forces_with(const Model& model, const VecX& q, bool rotate_followers, int arm) {
  VecX Q = VecX::Zero(model.num_coordinates());
  for (int k = 0; k < model.num_bodies(); ++k) Q.segment<2>(3 * k) += model.bodies()[k].mass * model.gravity();
  for (const Force& f : model.forces()) {
    const auto& e = std::get<PointForce>(f.element);
    const Point& P = point_of(model, e.P);
    if (P.body.is_ground()) continue;
    const double phi = coords(q, P.body)(2);
    const Vec2 F = e.frame == Frame::body && rotate_followers ? rotate(phi, e.F) : e.F;
    const Vec2 As = rotate(phi, P.s_bar);
    Q.segment<2>(3 * P.body.index) += F;
    Q(3 * P.body.index + 2) += arm == 0 ? 0.0 : arm == 1 ? cross(As, F) : As.dot(F);
  }
  return Q;
}

std::string point_forces_hint(const Model& model, const VecX& q, const VecX& actual) {
  return diagnose(actual, point_forces_with(model, q, true, 1),
                  {{"your Q_a: body-frame force not rotated? A follower force (Frame::body) turns with its body",
                    point_forces_with(model, q, false, 1)},
                   {with_formula("your Q_a: moment term missing? A force adds its moment about the centroid",
                                 "Q_phi = (A_i I~ s_i)^T F"),
                    point_forces_with(model, q, true, 0)},
                   {with_formula("your Q_a: A where A I~ belongs in the moment of a force?", "Q_phi = (A_i I~ s_i)^T F"),
                    point_forces_with(model, q, true, 2)}},
                  with_formula("your Q_a differs from gravity and the point forces on every body: check gravity_force "
                               "and point_force (T2 tests)",
                               "gravity (m g_x, m g_y, 0); a force F at s_i adds (F_g, (A_i I~ s_i)^T F_g), F_g = F "
                               "(global) or A_i F (body frame)"));
}

}  // namespace

GRADED_TEST("applied_forces gravity and global point forces are minus the gradient of the potential",
            "[M03][T2][points=1]") {
  Random rnd(3251);
  Model model = three_bodies(rnd);
  model.set_gravity(rnd.vec2(-10, 10));
  for (int k = 0; k < 3; ++k)
    model.add_point_force("F" + std::to_string(k),
                          model.add_point(BodyId{k}, rnd.vec2(-0.5, 0.5), "P" + std::to_string(k)), rnd.vec2(-20, 20));
  model.add_point_force("F0 again", model.add_point(BodyId{0}, rnd.vec2(-0.5, 0.5), "P3"), rnd.vec2(-20, 20));
  for (int trial = 0; trial < 5; ++trial) {
    const VecX q = rnd.vector(9, -2, 2), qd = rnd.vector(9, -1, 1);
    CAPTURE(trial);
    const VecX Q = kernel_applied_forces(model, q, qd, 0.3);
    CHECK_CLOSE_NAMED("your Q", Q, minus_gradient(model, q), kFD, point_forces_hint(model, q, Q));
  }
}

GRADED_TEST("applied_forces follower forces do the virtual work of the turning forces", "[M03][T2][points=1]") {
  Random rnd(3252);
  Model model = three_bodies(rnd);
  model.set_gravity(Vec2(0.0, -9.81));
  model.add_point_force("follower 0", model.add_point(BodyId{0}, rnd.vec2(-0.5, 0.5), "P0"), rnd.vec2(-10, 10),
                        Frame::body);
  model.add_point_force("follower 1", model.add_point(BodyId{1}, rnd.vec2(-0.5, 0.5), "P1"), rnd.vec2(-10, 10),
                        Frame::body);
  model.add_point_force("follower 1b", model.add_point(BodyId{1}, rnd.vec2(-0.5, 0.5), "P2"), rnd.vec2(-10, 10),
                        Frame::body);
  model.add_point_force("global 2", model.add_point(BodyId{2}, rnd.vec2(-0.5, 0.5), "P3"), rnd.vec2(-10, 10));
  for (int trial = 0; trial < 5; ++trial) {
    const VecX q = rnd.vector(9, -3, 3), qd = rnd.vector(9, -1, 1);
    const VecX Q = kernel_applied_forces(model, q, qd, 0.0);
    REQUIRE(Q.size() == 9);
    CAPTURE(trial);
    const std::string hint = point_forces_hint(model, q, Q);
    CHECK_CLOSE_NAMED("your Q", Q, applied_forces_of(model, q, qd, 0.0), kSame, hint);
    // Virtual work of the forces frozen at q, for small random dq.
    for (int k = 0; k < 3; ++k) {
      const VecX dq = 1e-5 * rnd.vector(9, -1, 1);
      double work = 0;
      for (int b = 0; b < 3; ++b) work += model.bodies()[b].mass * model.gravity().dot(dq.segment<2>(3 * b));
      for (const Force& f : model.forces()) {
        const auto& e = std::get<PointForce>(f.element);
        const Point& P = point_of(model, e.P);
        const Vec2 Fg = e.frame == Frame::global ? e.F : rotate(coords(q, P.body)(2), e.F);
        work += Fg.dot(position(model, q + dq, e.P) - position(model, q - dq, e.P)) / 2;
      }
      CHECK_NEAR_NAMED("the virtual work of your Q (per 1e-5 of dq)", Q.dot(dq) / 1e-5, work / 1e-5,
                       (Tolerance{1e-8, 1e-7}), hint);
    }
  }
}

GRADED_TEST("applied_forces tsda with the ground on either side", "[M03][T3][points=1]") {
  Random rnd(3351);
  for (int variant = 0; variant < 2; ++variant) {
    const bool damped = variant == 1;
    Model model;
    const BodyId A = model.add_body("A", 1.0, 0.1), B = model.add_body("B", 2.0, 0.2);
    const PointId g1 = model.add_point(ground, Vec2(-1.0, 0.5), "anchor 1");
    const PointId g2 = model.add_point(ground, Vec2(1.5, -0.5), "anchor 2");
    const PointId a = model.add_point(A, Vec2(0.2, 0.1), "a"), a2 = model.add_point(A, Vec2(-0.1, 0.3), "a2");
    const PointId b = model.add_point(B, Vec2(-0.3, 0.05), "b"), b2 = model.add_point(B, Vec2(0.1, -0.2), "b2");
    const double c = damped ? 3.0 : 0.0;
    auto act = [&](double f0) { return damped ? DriveFunction::harmonic(f0, 2.0, 3.0) : DriveFunction::constant(0.0); };
    model.add_tsda("ground to A", g1, a, 40.0, 0.6, c, act(5.0));
    model.add_tsda("B to ground", b, g2, 25.0, 0.3, 2 * c, act(-4.0));
    model.add_tsda("A to B", a2, b2, 60.0, 0.8, c / 2, act(3.0));
    for (int trial = 0; trial < 4; ++trial) {
      VecX q(6);
      q << rnd.uniform(-0.5, 0.5), rnd.uniform(-0.5, 0.5), rnd.uniform(-3, 3), rnd.uniform(0.5, 1.5),
          rnd.uniform(0.5, 1.5), rnd.uniform(-3, 3);
      const VecX qd = rnd.vector(6, -2, 2);
      const double t = rnd.uniform(0, 2);
      const VecX Q = applied_forces(model, q, qd, t);
      CAPTURE(damped, trial);
      const VecX own = applied_forces_of(model, q, qd, t);
      const std::string hint = diagnose(
          Q, own,
          {{"your Q_a: force direction flipped? Each spring-damper pulls its points together when stretched, "
            "whichever side is the ground",
            -own}},
          with_formula("your Q_a differs from the spring-dampers' tensions, whichever side is the ground (q = 0 "
                       "there): check tsda_force (T3 tests)", kTensionFormula));
      if (!damped) CHECK_CLOSE_NAMED("your Q", Q, minus_gradient(model, q), kFD, hint);
      CHECK_CLOSE_NAMED("your Q", Q, own, kSame, hint);
    }
  }
}

GRADED_TEST("applied_forces rsda with the ground on either side", "[M03][T3][points=1]") {
  Random rnd(3352);
  for (int variant = 0; variant < 2; ++variant) {
    const bool damped = variant == 1;
    Model model;
    const BodyId A = model.add_body("A", 1.0, 0.1), B = model.add_body("B", 2.0, 0.2);
    const double c = damped ? 0.7 : 0.0;
    auto act = [&](double f0) { return damped ? DriveFunction::harmonic(f0, 0.5, 2.0) : DriveFunction::constant(0.0); };
    model.add_rsda("ground to A", ground, A, 4.0, 0.5, c, act(0.3));
    model.add_rsda("B to ground", B, ground, 9.0, -0.2, 2 * c, act(-0.2));
    model.add_rsda("A to B", A, B, 2.5, 1.0, c, act(0.1));
    for (int trial = 0; trial < 4; ++trial) {
      const VecX q = rnd.vector(6, -3, 3), qd = rnd.vector(6, -2, 2);
      const double t = rnd.uniform(0, 2);
      const VecX Q = applied_forces(model, q, qd, t);
      CAPTURE(damped, trial);
      const VecX own = applied_forces_of(model, q, qd, t);
      const std::string hint = diagnose(
          Q, own,
          {{with_formula("your Q_a: RSDA torque sign? It acts +T on body i and -T on body j", kTorqueFormula), -own}},
          with_formula("your Q_a differs from the rotational spring-dampers' torques (the ground's angle is 0): check "
                       "rsda_force (T3 tests)", kTorqueFormula));
      if (!damped) CHECK_CLOSE_NAMED("your Q", Q, minus_gradient(model, q), kFD, hint);
      CHECK_CLOSE_NAMED("your Q", Q, own, kSame, hint);
    }
  }
}
