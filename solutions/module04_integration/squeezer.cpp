// Module 4, task T5: the capstone of the rigid half, Andrews' squeezer built with the Model API
// (capstone/README.md).
#include <cmath>
#include <string>

#include "fmbd/errors.hpp"
#include "fmbd/squeezer.hpp"

namespace fmbd {

namespace {

// The unit vectors of squeezer.hpp: e(a) along the angle a, n(a) = e(a - pi/2).
[[maybe_unused]] Vec2 e_of(double a) { return {std::cos(a), std::sin(a)}; }
[[maybe_unused]] Vec2 n_of(double a) { return {std::sin(a), -std::cos(a)}; }

}  // namespace

SqueezerModel andrews_squeezer() {
  // TASK(M04T5): build Andrews' squeezer of the drawing (capstone/README.md, squeezer.hpp):
  //   seven bodies named "body1" ... "body7" with the published masses and centroidal inertias,
  //   each placed at its centroid in the published configuration at t = 0 (add_body's q0); the
  //   points F, E, D, G, H with those names (add_point_at: the drawing gives global positions);
  //   the revolute joints at O, F, E (three joints join the four bodies there), B, A (twice), G
  //   and H; the torque on the crank and the spring from C to D. Return the model, q0 (its
  //   initial guess, consistent when every point was entered at its place) and qd0 = 0.
  //   Stuck? ./workbook hint M04T5
  // BEGIN SOLUTION
  namespace s = squeezer;
  const Vec2 A(s::xa, s::ya), B(s::xb, s::yb), C(s::xc, s::yc);
  const Vec2 F = s::rr * e_of(s::beta0);
  const Vec2 E = F - s::d * e_of(s::beta0 + s::Theta0);
  const Vec2 D = B + s::sc * n_of(s::gamma0) + s::sd * e_of(s::gamma0);
  const Vec2 G = A + s::zt * e_of(s::delta0);
  const Vec2 H = A + s::u * n_of(s::epsilon0);
  const Vec2 centroid[7] = {
      s::ra * e_of(s::beta0),
      F - s::da * e_of(s::beta0 + s::Theta0),
      B + s::sa * n_of(s::gamma0) + s::sb * e_of(s::gamma0),
      E - s::ea * n_of(s::Phi0 + s::delta0),
      A + s::ta * e_of(s::delta0) + s::tb * Vec2(-std::sin(s::delta0), std::cos(s::delta0)),
      E - s::fa * e_of(s::Omega0 + s::epsilon0),
      A + s::ua * n_of(s::epsilon0) + s::ub * e_of(s::epsilon0)};

  SqueezerModel out;
  Model& m = out.model;
  BodyId body[7];
  for (int k = 0; k < 7; ++k)
    body[k] = m.add_body("body" + std::to_string(k + 1), s::mass[k], s::inertia[k],
                         Vec3(centroid[k].x(), centroid[k].y(), 0.0));
  const auto pin = [&m](const std::string& name, BodyId i, BodyId j, const Vec2& at, const std::string& point_i) {
    const PointId P_i = m.add_point_at(i, at, point_i.empty() ? name + " on " + m.body_name(i) : point_i);
    const PointId P_j = m.add_point_at(j, at, name + " on " + m.body_name(j));
    m.add_revolute(name, P_i, P_j);
  };
  pin("O", body[0], ground, Vec2::Zero(), "");
  pin("F", body[0], body[1], F, "F");
  pin("E 2-3", body[1], body[2], E, "E");
  pin("E 2-4", body[1], body[3], E, "E 2-4 on body2");
  pin("E 2-6", body[1], body[5], E, "E 2-6 on body2");
  pin("B", body[2], ground, B, "");
  pin("A 5", body[4], ground, A, "");
  pin("G", body[4], body[3], G, "G");
  pin("A 7", body[6], ground, A, "");
  pin("H", body[6], body[5], H, "H");
  m.add_torque("motor", body[0], DriveFunction::constant(s::torque));
  m.add_tsda("spring", m.add_point_at(ground, C, "C"), m.add_point_at(body[2], D, "D"), s::stiffness, s::rest_length, 0.0);

  out.q0 = m.initial_guess();
  out.qd0 = VecX::Zero(m.num_coordinates());
  return out;
  // END SOLUTION
  // STUB: throw NotImplemented("M04T5 andrews_squeezer");
}

}  // namespace fmbd
