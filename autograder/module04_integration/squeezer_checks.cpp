// Definitions of the capstone's checks (see squeezer_checks.hpp), compiled once per build.
#include "squeezer_checks.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <variant>

#include "fmbd/constraints.hpp"
#include "fmbd/dof.hpp"
#include "fmbd/forward_dynamics.hpp"
#include "fmbd/kinematic_analysis.hpp"
#include "fmbd/simulation.hpp"
#include "grading.hpp"
#include "integration_checks.hpp"

namespace fmbd::testing::m04 {

namespace s = fmbd::squeezer;

namespace {

Vec2 n_of(double a) { return Vec2(std::sin(a), -std::cos(a)); }
double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

const Vec2 kA(s::xa, s::ya), kB(s::xb, s::yb), kC(s::xc, s::yc);

// The intersection of the circles about P (radius rp) and Q (radius rq) on the side `side`
// (+1: left of P -> Q).
Vec2 circles(const Vec2& P, double rp, const Vec2& Q, double rq, double side) {
  const double L = (Q - P).norm();
  const Vec2 u = (Q - P) / L;
  const double a = (rp * rp - rq * rq + L * L) / (2 * L);
  const double h = std::sqrt(std::max(0.0, rp * rp - a * a));
  return P + a * u + side * h * perp(u);
}

double side_of(const Vec2& P, const Vec2& Q, const Vec2& X) { return cross(Q - P, X - P) > 0 ? 1.0 : -1.0; }

// Position of point P at q, written out: R + A(phi) s_bar (s_bar itself on the ground).
Vec2 point_at(const Model& model, PointId P, const VecX& q) {
  const Point& p = model.point(P);
  if (p.body.is_ground()) return p.s_bar;
  const int o = model.offset(p.body);
  return q.segment<2>(o) + rotate(q(o + 2), p.s_bar);
}

// The named body or point, or -1 with a failure that says what the grader reads.
int body_named(const Model& model, const std::string& name) {
  for (int k = 0; k < model.num_bodies(); ++k)
    if (model.bodies()[k].name == name) return k;
  FAIL_CHECK("the model has no body named \"" << name
                                              << "\": the grader finds the bodies by their names body1 ... body7 "
                                                 "(squeezer.hpp; the numbers of the drawing)");
  return -1;
}

int point_named(const Model& model, const std::string& name) {
  for (int k = 0; k < static_cast<int>(model.points().size()); ++k)
    if (model.points()[k].name == name) return k;
  FAIL_CHECK("the model has no point named \"" << name
                                               << "\": the grader reads the points F, E, D, G and H by their names "
                                                  "(squeezer.hpp)");
  return -1;
}

struct Named {
  int body[7];
  PointId F, E, D, G, H;
};

Named names_of(const Model& model) {
  Named n;
  for (int k = 0; k < 7; ++k) n.body[k] = body_named(model, "body" + std::to_string(k + 1));
  n.F = PointId{point_named(model, "F")};
  n.E = PointId{point_named(model, "E")};
  n.D = PointId{point_named(model, "D")};
  n.G = PointId{point_named(model, "G")};
  n.H = PointId{point_named(model, "H")};
  return n;
}

SqueezerPoints points_of(const Model& model, const Named& n, const VecX& q) {
  return {point_at(model, n.F, q), point_at(model, n.E, q), point_at(model, n.D, q), point_at(model, n.G, q),
          point_at(model, n.H, q)};
}

VecX stacked(const SqueezerPoints& p) {
  VecX v(10);
  v << p.F, p.E, p.D, p.G, p.H;
  return v;
}

// The force that the joints at `place` exert on body `k`, summed (revolute and fixed joints;
// a joint with ground is found the same way).
Vec2 force_on_body_at(const Model& model, int k, const Vec2& place, const VecX& q, const VecX& lambda) {
  Vec2 F = Vec2::Zero();
  const double near = 1e-9;
  for (const Constraint& c : model.constraints()) {
    PointId Pi, Pj;
    if (const auto* r = std::get_if<Revolute>(&c.type)) {
      Pi = r->P_i;
      Pj = r->P_j;
    } else if (const auto* f = std::get_if<Fixed>(&c.type)) {
      Pi = f->P_i;
      Pj = f->P_j;
    } else {
      continue;
    }
    const Vec2 l = lambda.segment<2>(c.first_row);  // C = r_Pi - r_Pj: -l on body i, +l on body j
    if (c.body_i.index == k && (point_at(model, Pi, q) - place).norm() < near) F -= l;
    if (c.body_j.index == k && (point_at(model, Pj, q) - place).norm() < near) F += l;
  }
  return F;
}

Vec2 spring_force_on_D(const Vec2& D) {
  const Vec2 d = D - kC;
  const double L = d.norm();
  return -s::stiffness * (L - s::rest_length) * d / L;
}

const char* const kPlaces =
    "a point of the drawing entered at the wrong place: check its coordinates against the table (the frame's "
    "origin at O; each body's centroid as drawn)";

}  // namespace

SqueezerAngles squeezer_angles_at_start() {
  return {s::beta0, s::Theta0, s::gamma0, s::Phi0, s::delta0, s::Omega0, s::epsilon0};
}

SqueezerAngles squeezer_angles_at_end() {
  return {15.81077119629904,   -15.75637105984298, 0.04082224013073101, -0.5347301163226948,
          0.5244099658805304,  0.5347301163226948, 1.048080741042263};
}

SqueezerAngles squeezer_rates_at_end() {
  return {1139.920302151208,  -1424.379294994111, 11.03291221937134, 19.29337464421385,
          0.5735699284790808, -19.29337464421385, 0.3231791658026955};
}

SqueezerPoints squeezer_points(const SqueezerAngles& a) {
  SqueezerPoints p;
  p.F = s::rr * unit(a.beta);
  p.E = p.F - s::d * unit(a.beta + a.Theta);
  p.D = kB + s::sc * n_of(a.gamma) + s::sd * unit(a.gamma);
  p.G = kA + s::zt * unit(a.delta);
  p.H = kA + s::u * n_of(a.epsilon);
  return p;
}

SqueezerPoints squeezer_points_at_crank_angle(double beta) {
  const SqueezerPoints start = squeezer_points(squeezer_angles_at_start());
  SqueezerPoints p;
  p.F = s::rr * unit(beta);
  p.E = circles(p.F, s::d, kB, s::ss, side_of(start.F, kB, start.E));
  const Vec2 n = (p.E - kB) / s::ss;  // n(gamma)
  p.D = kB + s::sc * n + s::sd * Vec2(-n.y(), n.x());
  p.G = circles(kA, s::zt, p.E, s::e, side_of(kA, start.E, start.G));
  p.H = circles(kA, s::u, p.E, s::zf, side_of(kA, start.E, start.H));
  return p;
}

double squeezer_spring_energy(const Vec2& D) {
  const double stretch = (D - kC).norm() - s::rest_length;
  return 0.5 * s::stiffness * stretch * stretch;
}

bool check_squeezer_structure(const SqueezerModel& sq) {
  const Model& model = sq.model;
  const char* const joints =
      "hint: the squeezer has 7 bodies (21 coordinates) and 10 revolute joints (20 equations): O, F, B, G, H, A "
      "twice, and three at E, where the rod, the triangle and bodies 4 and 6 meet";
  const int n = model.num_coordinates();
  {
    INFO(joints);
    CHECK(model.num_bodies() == 7);
  }
  if (model.num_bodies() != 7) return false;
  const Named names = names_of(model);
  for (int k = 0; k < 7; ++k)
    if (names.body[k] < 0) return false;
  if (names.F.index < 0 || names.E.index < 0 || names.D.index < 0 || names.G.index < 0 || names.H.index < 0)
    return false;
  for (int k = 0; k < 7; ++k) {
    const Body& b = model.bodies()[names.body[k]];
    CAPTURE(b.name);
    CHECK_NEAR_NAMED("your body's mass", b.mass, s::mass[k], (Tolerance{0, 1e-12}),
                     "the body's mass: squeezer::mass[k] for body k + 1");
    CHECK_NEAR_NAMED("your body's inertia", b.inertia, s::inertia[k], (Tolerance{0, 1e-12}),
                     "the body's inertia about its centroid: squeezer::inertia[k] for body k + 1");
  }
  {
    INFO("hint: q0 and qd0 have one entry per coordinate, every one finite");
    CHECK(sq.q0.size() == n);
    CHECK(sq.qd0.size() == n);
    if (sq.q0.size() != n || sq.qd0.size() != n || !sq.q0.allFinite()) return false;
  }
  const int dof = degrees_of_freedom(model, sq.q0);
  {
    INFO(joints);
    CHECK(dof == 1);
  }
  if (dof != 1) return false;
  CHECK_NEAR_NAMED("|C| at your q0", constraints(model, sq.q0, 0.0).norm(), 0.0, (Tolerance{1e-10, 0}),
                   "q0 must satisfy every joint: place each body at its centroid in the published configuration and "
                   "enter each point where the drawing puts it");
  CHECK_CLOSE_NAMED("your qd0", sq.qd0, VecX::Zero(n), (Tolerance{0, 0}), "the squeezer starts at rest: qd0 = 0");
  return true;
}

void check_squeezer_start(const SqueezerModel& sq) {
  const Named names = names_of(sq.model);
  const SqueezerPoints expected = squeezer_points(squeezer_angles_at_start());
  CHECK_CLOSE_NAMED("your points F, E, D, G, H at t = 0", stacked(points_of(sq.model, names, sq.q0)), stacked(expected),
                    (Tolerance{1e-9, 0}), std::string("F, E, D, G, H (in this order, x and y) at t = 0: ") + kPlaces);
}

void check_squeezer_positions(const SqueezerModel& sq, const std::vector<double>& turns) {
  const Named names = names_of(sq.model);
  // The grader's driver: the crank's angle from its angle in q0 (its frame's orientation is free).
  Model driven = sq.model;
  const BodyId crank{names.body[0]};
  const double phi0 = sq.q0(driven.offset(crank) + 2);
  driven.add_absolute_angle_driver("grader's crank driver", crank, DriveFunction::linear(phi0, 1.0));
  double last = 0;
  for (double turn : turns) last = std::max(last, turn);
  std::vector<double> times;
  const int steps = static_cast<int>(std::ceil(last / 0.05));
  for (int k = 0; k <= steps; ++k) times.push_back(last * k / steps);
  for (double turn : turns) times.push_back(turn);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  const KinematicSolution solution = kinematic_analysis(driven, sq.q0, times);
  for (double turn : turns) {
    const std::size_t k = static_cast<std::size_t>(std::find(times.begin(), times.end(), turn) - times.begin());
    const double beta = s::beta0 + turn;
    CAPTURE(beta);
    CHECK_CLOSE_NAMED("your points F, E, D, G, H with the crank turned",
                      stacked(points_of(sq.model, names, solution.q[k])), stacked(squeezer_points_at_crank_angle(beta)),
                      (Tolerance{1e-9, 0}),
                      "F, E, D, G, H with the crank turned: a length of the drawing differs in the model (a point on "
                      "the wrong body, or two bodies pinned at the wrong point)");
  }
}

void check_squeezer_reactions(const SqueezerModel& sq) {
  const Model& model = sq.model;
  const Named names = names_of(model);
  const Accelerations a = forward_dynamics(model, sq.q0, sq.qd0, 0.0);
  // Published: beta'' and Theta'' at t = 0 (the others zero); lambda_1,2 (Hairer and Wanner).
  const double beta_dd = 14222.4439199541138705911625887, Theta_dd = -10666.8329399655854029433719415;
  const Vec2 lambda(98.5668703962410896057654982170, -6.12268834425566265503114393122);
  const int crank = model.offset(BodyId{names.body[0]}), rod = model.offset(BodyId{names.body[1]});
  CHECK_NEAR_NAMED("the crank's angular acceleration beta'' of your model at t = 0", a.qdd(crank + 2), beta_dd,
                   (Tolerance{0, 1e-8}),
                   "your crank's angular acceleration at t = 0 differs: the motor torque (squeezer::torque on body1), "
                   "the spring (squeezer::stiffness, rest_length, from C to D) and the masses set it");
  CHECK_NEAR_NAMED("the rod's angular acceleration beta'' + Theta'' of your model at t = 0", a.qdd(rod + 2),
                   beta_dd + Theta_dd, (Tolerance{0, 1e-8}),
                   "your rod's angular acceleration at t = 0 differs (beta'' + Theta'')");
  const SqueezerPoints p = squeezer_points(squeezer_angles_at_start());
  const int triangle = names.body[2];
  CHECK_CLOSE_NAMED(
      "your force on the triangle at E", force_on_body_at(model, triangle, p.E, sq.q0, a.lambda), lambda,
      (Tolerance{0, 1e-8}),
      "the force on the triangle at E, summed over its joints there, is the published (lambda_1, lambda_2): "
      "the spring's force at D, or the joints at E");
  CHECK_CLOSE_NAMED(
      "your ground's force on the triangle at B", force_on_body_at(model, triangle, kB, sq.q0, a.lambda),
      Vec2(-lambda - spring_force_on_D(p.D)), (Tolerance{0, 1e-8}),
      "the ground's force on the triangle at B: the triangle is at rest and unaccelerated at t = 0, so it "
      "balances the spring at D and the rod at E");
}

void check_squeezer_motion(const SqueezerModel& sq) {
  const Model& model = sq.model;
  const Named names = names_of(model);
  SimulationOptions o;
  o.integrator = Integrator::rk4;
  o.step = 5e-5;
  o.stabilisation = Stabilisation::projection;
  o.output_interval = 0.03;
  const Trajectory run = simulate(model, sq.q0, sq.qd0, 0.0, 0.03, o);
  REQUIRE(run.t.size() >= 2);
  const VecX& q = run.q.back();
  const VecX& qd = run.qd.back();
  const SqueezerAngles end = squeezer_angles_at_end(), rate = squeezer_rates_at_end();
  const SqueezerPoints expected = squeezer_points(end);
  const char* const dynamics =
      "the motion differs from the reference: a mass, an inertia or a centroid of the drawing (frames at the "
      "centroids), the torque or the spring";
  CHECK_CLOSE_NAMED("your points F, E, D, G, H at t = 0.03 s", stacked(points_of(model, names, q)), stacked(expected),
                    (Tolerance{1e-8, 0}),
                    std::string("F, E, D, G, H at t = 0.03 s (2.5 turns of the crank): ") + dynamics);
  CHECK_NEAR_NAMED("your crank's rate at t = 0.03 s", qd(model.offset(BodyId{names.body[0]}) + 2), rate.beta,
                   (Tolerance{0, 1e-6}), std::string("the crank's rate at t = 0.03 s: ") + dynamics);
  // T(0.03) = work of the torque - the spring's gain of energy (starting at rest).
  const double work = s::torque * (end.beta - s::beta0);
  const double T_expected =
      work - (squeezer_spring_energy(expected.D) - squeezer_spring_energy(squeezer_points(squeezer_angles_at_start()).D));
  const double T = 0.5 * qd.dot(mass_matrix_of(model) * qd);
  CHECK_NEAR_NAMED("your kinetic energy at t = 0.03 s", T, T_expected, (Tolerance{0, 1e-6}),
                   std::string("the kinetic energy at t = 0.03 s: ") + dynamics);
  CHECK_NEAR_NAMED("the energy your run gained", run.energy.back() - run.energy.front(), run.work_done.back(),
                   (Tolerance{1e-6, 0}),
                   "energy balance: T + V gained equals the torque's work (a force element that does work V does not "
                   "cover, or a damper)");
}

}  // namespace fmbd::testing::m04
