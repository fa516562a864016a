// Module 3, tasks T1 and T3: the system's M and Q_a assembled by the student, into storage that
// holds an earlier call's numbers, on a model whose flexible stand-in body (dynamics_checks.hpp)
// shifts the rigid bodies' offsets and adds its own known blocks. Oracles: the bodies' data,
// the stand-in's known blocks, and the kernels' forces placed by the test.
#include <memory>
#include <string>

#include "dynamics_checks.hpp"
#include "fmbd/applied_forces.hpp"
#include "fmbd/mass_matrix.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m03;

namespace {

struct Mixed {
  Model model;
  std::shared_ptr<const StandInBody> flexible = std::make_shared<StandInBody>(2);
  BodyId a, f, b;
  Mixed() {
    a = model.add_body("A", 1.5, 0.2, Vec3(0.1, 0.2, 0.3));
    f = model.add_flexible_body("F", flexible, Vec3(1.0, 0.0, 0.1));
    b = model.add_body("B", 2.5, 0.4, Vec3(2.0, 0.5, -0.2));
    model.set_gravity(Vec2(0.5, -9.81));
    model.add_point_force("push", model.add_point(a, Vec2(0.2, 0.1), "A tip"), Vec2(3.0, -1.0));
    model.add_tsda("spring", model.add_point(ground, Vec2(2.0, 2.0), "anchor"), model.add_point(b, Vec2(0.1, -0.3), "B tip"),
                   40.0, 1.0, 2.0);
    model.add_rsda("coupling", a, b, 15.0, 0.2, 1.0);
    model.add_torque("motor", b, DriveFunction::constant(4.0));
  }
};

// The likely mistake behind a wrong block: `got` where `want`, `before` what the storage held.
std::string block_hint(const MatX& got, const MatX& want, const MatX& before, const char* whose, const char* own) {
  const double scale = 1e-9 * std::max(1.0, want.cwiseAbs().maxCoeff());
  if ((got - want - before).cwiseAbs().maxCoeff() <= scale)
    return "your result kept an earlier call's entries: clear the storage before adding into it";
  if (got.isZero(0.0) && !want.isZero(0.0))
    return std::string("nothing at ") + whose + ": " + own;
  return std::string("wrong entries at ") + whose +
         ": a body's coordinates start at model.offset(body), which is not 3 k when a flexible body comes before it";
}

}  // namespace

GRADED_TEST("mass_matrix: a flexible body's own block at its coordinates, rigid blocks at their offsets, storage overwritten",
            "[M03][T1][points=2]") {
  Mixed x;
  Random rnd(3101);
  const int n = x.model.num_coordinates();
  MatX M = MatX::Constant(n, n, 7.0);  // an earlier call's numbers
  for (int trial = 0; trial < 3; ++trial) {
    const VecX q = rnd.vector(n, -1, 1);
    const MatX before = M;
    mass_matrix(x.model, q, M);
    MatX want = MatX::Zero(n, n);
    for (BodyId body : {x.a, x.b}) {
      const Body& data = x.model.body(body);
      want.diagonal().segment<3>(x.model.offset(body)) << data.mass, data.mass, data.inertia;
    }
    const int at = x.model.offset(x.f);
    want.block(at, at, 5, 5) = x.flexible->block_of(q.segment(at, 5));
    CAPTURE(trial);
    for (BodyId body : {x.a, x.f, x.b}) {
      const int from = x.model.offset(body), size = body == x.f ? 5 : 3;
      INFO("M: the rows and columns of body '" << x.model.body_name(body) << "', from " << from);
      const MatX got = M.block(from, from, size, size), expected = want.block(from, from, size, size);
      CHECK_CLOSE_NAMED("your M in these rows and columns", got, expected, (Tolerance{1e-12, 1e-12}),
                  block_hint(got, expected, before.block(from, from, size, size), "a flexible body's coordinates",
                             "a flexible body adds its own block through its deformable->add_mass(q, offset, M)"));
    }
    CHECK_CLOSE_NAMED("your M", M, want, (Tolerance{1e-12, 1e-12}),
                      block_hint(M, want, before, "the rows and columns between bodies", "every other entry is zero"));
  }
}

GRADED_TEST("applied_forces: gravity on rigid bodies, a flexible body's own forces, each element on both its markers' rows",
            "[M03][T3][points=2]") {
  Mixed x;
  Random rnd(3102);
  const int n = x.model.num_coordinates();
  VecX Q = VecX::Constant(n, 7.0);  // an earlier call's numbers
  for (int trial = 0; trial < 3; ++trial) {
    const VecX q = rnd.vector(n, -1, 1), qd = rnd.vector(n, -1, 1);
    const VecX before = Q;
    applied_forces(x.model, q, qd, 0.4, Q);
    VecX want = VecX::Zero(n);
    for (BodyId body : {x.a, x.b}) want.segment<2>(x.model.offset(body)) += x.model.body(body).mass * x.model.gravity();
    const int at = x.model.offset(x.f);
    want.segment(at, 5) += x.flexible->forces_of(q.segment(at, 5), qd.segment(at, 5), x.model.gravity());
    for (const Force& force : x.model.forces()) {
      const ElementForces f = element_forces(x.model, force, q, qd, 0.4);
      if (!f.i.body.is_ground()) want.segment<3>(f.i.offset) += f.Q_i;
      if (!f.j.body.is_ground()) want.segment<3>(f.j.offset) += f.Q_j;
    }
    CAPTURE(trial);
    std::string hint = block_hint(Q, want, before, "a body's rows", "gravity, the body's own forces or an element's");
    const int a = x.model.offset(x.a);
    if ((Q - want).segment(at, 5).cwiseAbs().maxCoeff() > 1e-9 && (Q - want).segment(a, 3).isZero(1e-9))
      hint = "wrong forces on the flexible body: it adds its own gravity and elastic forces through "
             "deformable->add_forces(q, qd, g, offset, Q_a), not gravity_force";
    const VecX ground_side = element_forces(x.model, x.model.forces()[1], q, qd, 0.4).Q_i;  // the spring's anchor side
    if (((Q - want).segment<3>(a) - ground_side).isZero(1e-9))
      hint = "the ground has no rows: your Q_a adds the ground's force to the first body's rows";
    const ElementForces rsda = element_forces(x.model, x.model.forces()[2], q, qd, 0.4);
    if (!rsda.Q_j.isZero(0.0) && ((want - Q).segment<3>(x.model.offset(x.b)) - rsda.Q_j -
                                  element_forces(x.model, x.model.forces()[1], q, qd, 0.4).Q_j)
                                     .isZero(1e-9))
      hint = "a force element acts on two markers: add its force on the second marker (Q_j) too";
    CHECK_CLOSE_NAMED("your Q", Q, want, (Tolerance{1e-9, 1e-9}), hint);
  }
}
