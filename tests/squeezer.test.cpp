// Project test (not graded) of the rigid capstone's grading (task M04T5): a squeezer built in a
// different but equivalent way scores full on every check of the graded tests, and the checks'
// own oracle, the position analysis by circle intersections, meets a published configuration.
#include <cmath>
#include <string>

#include "fmbd/projection.hpp"
#include "fmbd/squeezer.hpp"
#include "grading.hpp"
#include "integration_checks.hpp"
#include "squeezer_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m04;

namespace {

namespace s = fmbd::squeezer;

Vec2 n_of(double a) { return Vec2(std::sin(a), -std::cos(a)); }

// The squeezer as another student might build it: the bodies in reverse order, every frame turned
// by its own angle, the points entered in another order and with other names where free, the
// joints with i and j swapped, the four bodies at E chained (3 on 2, 4 on 3, 6 on 4), body 7
// pinned at A to body 5 instead of to the ground, the spring from D to C, and q0 found by the
// projection from a guess 0.5 mm and 0.01 rad away.
SqueezerModel equivalent_squeezer() {
  const SqueezerAngles a = squeezer_angles_at_start();
  const SqueezerPoints p = squeezer_points(a);
  const Vec2 A(s::xa, s::ya), B(s::xb, s::yb), C(s::xc, s::yc);
  const Vec2 centroid[7] = {s::ra * unit(a.beta),
                            p.F - s::da * unit(a.beta + a.Theta),
                            B + s::sa * n_of(a.gamma) + s::sb * unit(a.gamma),
                            p.E - s::ea * n_of(a.Phi + a.delta),
                            A + s::ta * unit(a.delta) + s::tb * perp(unit(a.delta)),
                            p.E - s::fa * unit(a.Omega + a.epsilon),
                            A + s::ua * n_of(a.epsilon) + s::ub * unit(a.epsilon)};
  const double frame[7] = {-2.0, 0.4, 3.0, -1.2, 2.2, 0.9, -0.3};  // each body frame's angle at t = 0
  SqueezerModel out;
  Model& m = out.model;
  BodyId body[7];
  for (int k = 6; k >= 0; --k)
    body[k] = m.add_body("body" + std::to_string(k + 1), s::mass[k], s::inertia[k],
                         Vec3(centroid[k].x(), centroid[k].y(), frame[k]));
  // A revolute joint at `at`: the point on body j first, then body i's.
  const auto pin = [&m](const std::string& name, BodyId i, const std::string& point_i, BodyId j,
                        const std::string& point_j, const Vec2& at) {
    const PointId Pj = m.add_point_at(j, at, point_j);
    const PointId Pi = m.add_point_at(i, at, point_i);
    m.add_revolute(name, Pi, Pj);
  };
  pin("H joint", body[5], "H of 6", body[6], "H", p.H);
  pin("A of 7", body[6], "A on 7", body[4], "A on 5", A);
  pin("A of 5", ground, "A", body[4], "A of 5 on 5", A);
  pin("G joint", body[3], "G of 4", body[4], "G", p.G);
  pin("E 3-2", body[2], "E of 3", body[1], "E", p.E);
  pin("E 4-3", body[3], "E of 4", body[2], "E of 3 for 4", p.E);
  pin("E 6-4", body[5], "E of 6", body[3], "E of 4 for 6", p.E);
  pin("B joint", ground, "B", body[2], "B of 3", B);
  pin("F joint", body[1], "F of 2", body[0], "F", p.F);
  pin("O joint", ground, "O", body[0], "O of 1", Vec2::Zero());
  m.add_tsda("spring", m.add_point_at(body[2], p.D, "D"), m.add_point_at(ground, C, "C"), s::stiffness,
             s::rest_length, 0.0);
  m.add_torque("motor", body[0], DriveFunction::constant(s::torque));

  VecX guess = m.initial_guess();
  for (int k = 0; k < guess.size(); ++k) guess(k) += (k % 3 == 2 ? 0.01 : 5e-4) * (k % 2 == 0 ? 1 : -1);
  // The crank's angle stays at beta0: fix it while projecting, then drop the extra driver.
  Model held = m;
  held.add_absolute_angle_driver("hold the crank", body[0], DriveFunction::constant(frame[0]));
  const int c = m.offset(body[0]) + 2;
  guess(c) = frame[0];
  out.q0 = consistent_initial_conditions(held, guess, VecX::Zero(guess.size()), 0.0).q;
  out.qd0 = VecX::Zero(guess.size());
  return out;
}

}  // namespace

TEST_CASE("squeezer: an equivalent model scores full on every check of the capstone", "[squeezer]") {
  const SqueezerModel sq = equivalent_squeezer();
  REQUIRE(check_squeezer_structure(sq));
  check_squeezer_start(sq);
  check_squeezer_positions(sq, {0.5, 1.7, 3.0, 4.4, 5.9});
  check_squeezer_reactions(sq);
  check_squeezer_motion(sq);
}

TEST_CASE("squeezer: the circle intersections meet a published configuration", "[squeezer]") {
  // E. Gekeler, Mathematical Methods for Mechanics, Springer 2008: a configuration of the squeezer
  // drawn in its chapter 11, the seven angles to four decimals (its loops close to 1e-6 m).
  const SqueezerAngles published{0.6620, -0.5329, 0.4148, 0.1422, 0.4959, -0.1422, 1.2008};
  const SqueezerPoints expected = squeezer_points(published);
  const SqueezerPoints found = squeezer_points_at_crank_angle(published.beta);
  VecX e(10), f(10);
  e << expected.F, expected.E, expected.D, expected.G, expected.H;
  f << found.F, found.E, found.D, found.G, found.H;
  CHECK_CLOSE(f, e, (Tolerance{1e-5, 0}), "the oracle's branch or a length of squeezer.hpp");
  // And at t = 0 the oracle gives the published configuration to round-off.
  const SqueezerPoints start = squeezer_points(squeezer_angles_at_start());
  const SqueezerPoints again = squeezer_points_at_crank_angle(s::beta0);
  CHECK_NEAR((again.E - start.E).norm() + (again.G - start.G).norm() + (again.H - start.H).norm(), 0.0,
             (Tolerance{1e-15, 0}), "the circle intersections at beta0");
}
