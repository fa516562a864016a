// Definitions of the module 3 checks (see dynamics_checks.hpp), compiled once per build.
#include "dynamics_checks.hpp"

#include "linear_algebra.hpp"

#include <cmath>
#include <exception>
#include <optional>
#include <utility>
#include <variant>

namespace fmbd::testing::m03 {

namespace {

// I~ v: v turned by +90 degrees.
Vec2 perp(const Vec2& v) { return Vec2(-v.y(), v.x()); }

// v_P of point P at (q, q_dot).
Vec2 velocity(const Model& model, const VecX& q, const VecX& qd, PointId P) {
  const Point& p = point_of(model, P);
  return velocity_at(coords(q, p.body), coords(qd, p.body), p.s_bar);
}

// T = sum_k 1/2 (m_k |R_dot_k|^2 + J_k phi_dot_k^2).
double kinetic_energy_of(const Model& model, const VecX& qd) {
  double T = 0;
  for (int k = 0; k < model.num_bodies(); ++k) {
    const Body& b = model.bodies()[k];
    const double vx = qd(3 * k), vy = qd(3 * k + 1), w = qd(3 * k + 2);
    T += 0.5 * b.mass * (vx * vx + vy * vy) + 0.5 * b.inertia * w * w;
  }
  return T;
}

// Length L, rate L_dot and unit vector u = d / L of a spring-damper.
struct Stretch {
  double L = 0, L_dot = 0;
  Vec2 u = Vec2::Zero();
};
Stretch stretch_of(const Model& model, const Tsda& e, const VecX& q, const VecX& qd) {
  const Vec2 d = position(model, q, e.P_j) - position(model, q, e.P_i);
  const Vec2 d_dot = velocity(model, q, qd, e.P_j) - velocity(model, q, qd, e.P_i);
  Stretch s;
  s.L = d.norm();
  s.u = d / s.L;
  s.L_dot = s.u.dot(d_dot);
  return s;
}

// Power of what V does not cover: dampers, actuators, torques, body-frame point forces.
double nonconservative_power_of(const Model& model, const VecX& q, const VecX& qd, double t) {
  double P = 0;
  for (const Force& force : model.forces()) {
    if (const auto* e = std::get_if<PointForce>(&force.element)) {
      if (e->frame == Frame::body) {
        const Point& p = point_of(model, e->P);
        P += rotate(coords(q, p.body)(2), e->F).dot(velocity(model, q, qd, e->P));
      }
    } else if (const auto* T = std::get_if<Torque>(&force.element)) {
      P += T->T(t).f * coords(qd, T->body)(2);
    } else if (const auto* s = std::get_if<Tsda>(&force.element)) {
      const Stretch st = stretch_of(model, *s, q, qd);
      P -= (s->c * st.L_dot + s->actuator(t).f) * st.L_dot;
    } else if (const auto* r = std::get_if<Rsda>(&force.element)) {
      const double theta_dot = coords(qd, r->body_j)(2) - coords(qd, r->body_i)(2);
      P -= (r->c * theta_dot + r->actuator(t).f) * theta_dot;
    }
  }
  return P;
}

// A force through the centroid and a moment about the centroid.
struct Wrench {
  Vec2 F = Vec2::Zero();
  double M = 0.0;
};
// Adds force F acting at the global point r to the wrench of `body` (nothing for the ground).
void add_force_at(std::vector<Wrench>& w, const VecX& q, BodyId body, const Vec2& r, const Vec2& F) {
  if (body.is_ground()) return;
  w[body.index].F += F;
  w[body.index].M += cross(r - coords(q, body).head<2>(), F);
}
void add_moment(std::vector<Wrench>& w, BodyId body, double M) {
  if (!body.is_ground()) w[body.index].M += M;
}

// The applied forces of every body as a free-body diagram.
std::vector<Wrench> applied_wrenches(const Model& model, const VecX& q, const VecX& qd, double t) {
  std::vector<Wrench> w(model.num_bodies());
  for (int k = 0; k < model.num_bodies(); ++k) w[k].F += model.bodies()[k].mass * model.gravity();
  for (const Force& force : model.forces()) {
    if (const auto* e = std::get_if<PointForce>(&force.element)) {
      const Point& p = point_of(model, e->P);
      const Vec2 F = e->frame == Frame::global ? e->F : rotate(coords(q, p.body)(2), e->F);
      add_force_at(w, q, p.body, position(model, q, e->P), F);
    } else if (const auto* T = std::get_if<Torque>(&force.element)) {
      add_moment(w, T->body, T->T(t).f);
    } else if (const auto* s = std::get_if<Tsda>(&force.element)) {
      const Stretch st = stretch_of(model, *s, q, qd);
      const double f = s->k * (st.L - s->L0) + s->c * st.L_dot + s->actuator(t).f;  // tension
      add_force_at(w, q, point_of(model, s->P_i).body, position(model, q, s->P_i), f * st.u);
      add_force_at(w, q, point_of(model, s->P_j).body, position(model, q, s->P_j), -f * st.u);
    } else if (const auto* r = std::get_if<Rsda>(&force.element)) {
      const double theta = coords(q, r->body_j)(2) - coords(q, r->body_i)(2);
      const double theta_dot = coords(qd, r->body_j)(2) - coords(qd, r->body_i)(2);
      const double T = r->k * (theta - r->theta0) + r->c * theta_dot + r->actuator(t).f;
      add_moment(w, r->body_i, T);
      add_moment(w, r->body_j, -T);
    }
  }
  return w;
}

// Solves C_q^T lambda = rhs (or C_q lambda = rhs) with a full-pivot LU.
VecX solve_with(const MatX& A, const VecX& rhs) { return solve_general(A, rhs); }

// What upstream result (mass_matrix, applied_forces) is wrong, or empty.
std::string upstream_hint(const Model& model, const VecX& q, const VecX& qd, double t) {
  std::string out;
  try {
    const MatX M = mass_matrix(model);
    const VecX d = mass_diagonal(model);
    if (M.rows() != d.size() || M.cols() != d.size() || !compare(M, MatX(d.asDiagonal()), Tolerance{1e-12, 1e-12}).ok)
      out += "mass_matrix is wrong (fix the T1 tests first). ";
  } catch (const std::exception&) {
    out += "mass_matrix throws (fix T1 first). ";
  }
  try {
    const VecX Q = applied_forces(model, q, qd, t);
    if (!compare(Q, applied_forces_of(model, q, qd, t), Tolerance{1e-9, 1e-9}).ok)
      out += "applied_forces differs from the model's forces (fix the T2-T3 tests first). ";
  } catch (const std::exception&) {
    out += "applied_forces throws (fix T2-T3 first). ";
  }
  return out;
}

// States at `times` from the module 2 kinematic analysis.
std::vector<State> states_at(const Model& model, const VecX& guess, const std::vector<double>& times) {
  NewtonOptions options;
  options.tolerance = 1e-12;
  const KinematicSolution s = kinematic_analysis(model, guess, times, options);
  std::vector<State> out;
  for (std::size_t k = 0; k < s.q.size(); ++k) out.push_back(State{s.t[k], s.q[k], s.qd[k], s.qdd[k]});
  return out;
}

// The two points of a joint (none for a driver).
std::optional<std::pair<PointId, PointId>> joint_points_of(const Constraint& c) {
  if (const auto* r = std::get_if<Revolute>(&c.type)) return std::make_pair(r->P_i, r->P_j);
  if (const auto* r = std::get_if<Translational>(&c.type)) return std::make_pair(r->P_i, r->P_j);
  if (const auto* r = std::get_if<Fixed>(&c.type)) return std::make_pair(r->P_i, r->P_j);
  return std::nullopt;
}

// The rate of the quantity that driver c drives, from q_dot with the test's own formulas.
double driven_rate(const Model& model, const Constraint& c, const VecX& q, const VecX& qd) {
  if (const auto* d = std::get_if<AbsoluteAngleDriver>(&c.type)) return coords(qd, d->body)(2);
  if (const auto* d = std::get_if<RelativeAngleDriver>(&c.type))
    return coords(qd, d->body_j)(2) - coords(qd, d->body_i)(2);
  if (const auto* d = std::get_if<PointCoordinateDriver>(&c.type))
    return velocity(model, q, qd, d->P)(static_cast<int>(d->axis));
  const auto& d = std::get<DistanceDriver>(c.type);
  const Vec2 dist = position(model, q, d.P_j) - position(model, q, d.P_i);
  return dist.dot(velocity(model, q, qd, d.P_j) - velocity(model, q, qd, d.P_i)) / dist.norm();
}

// Reactions of every joint and efforts of every driver as wrenches on the bodies.
std::vector<Wrench> constraint_wrenches(const Model& model, const VecX& q, const VecX& lambda) {
  std::vector<Wrench> w(model.num_bodies());
  for (int c = 0; c < static_cast<int>(model.constraints().size()); ++c) {
    const Constraint& con = model.constraints()[c];
    if (const auto points = joint_points_of(con)) {
      const JointReaction r = joint_reaction(model, c, q, lambda);
      add_force_at(w, q, con.body_i, position(model, q, points->first), r.on_i.force);
      add_moment(w, con.body_i, r.on_i.moment);
      add_force_at(w, q, con.body_j, position(model, q, points->second), r.on_j.force);
      add_moment(w, con.body_j, r.on_j.moment);
      continue;
    }
    const double e = driver_effort(model, c, q, lambda);
    if (const auto* d = std::get_if<AbsoluteAngleDriver>(&con.type)) {
      add_moment(w, d->body, e);
    } else if (const auto* d = std::get_if<RelativeAngleDriver>(&con.type)) {
      add_moment(w, d->body_j, e);
      add_moment(w, d->body_i, -e);
    } else if (const auto* d = std::get_if<PointCoordinateDriver>(&con.type)) {
      Vec2 dir = Vec2::Zero();
      dir(static_cast<int>(d->axis)) = 1.0;
      add_force_at(w, q, point_of(model, d->P).body, position(model, q, d->P), e * dir);
    } else {
      const auto& dd = std::get<DistanceDriver>(con.type);
      const Vec2 ri = position(model, q, dd.P_i), rj = position(model, q, dd.P_j);
      const Vec2 u = (rj - ri).normalized();
      add_force_at(w, q, point_of(model, dd.P_j).body, rj, e * u);
      add_force_at(w, q, point_of(model, dd.P_i).body, ri, -e * u);
    }
  }
  return w;
}

}  // namespace

// ---- plain planar formulas ------------------------------------------------------------------

Vec2 rotate(double phi, const Vec2& s) {
  const double c = std::cos(phi), n = std::sin(phi);
  return Vec2(c * s.x() - n * s.y(), n * s.x() + c * s.y());
}

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

Vec2 point_at(const Vec3& qi, const Vec2& s) { return qi.head<2>() + rotate(qi(2), s); }

Vec2 velocity_at(const Vec3& qi, const Vec3& vi, const Vec2& s) {
  return vi.head<2>() + vi(2) * perp(rotate(qi(2), s));
}

Eigen::Matrix<double, 2, 3> jacobian_at(const Vec3& qi, const Vec2& s) {
  Eigen::Matrix<double, 2, 3> J;
  J.leftCols<2>().setIdentity();
  J.col(2) = perp(rotate(qi(2), s));
  return J;
}

Vec3 coords(const VecX& q, BodyId body) {
  return body.is_ground() ? Vec3(Vec3::Zero()) : Vec3(q.segment<3>(3 * body.index));
}

const Point& point_of(const Model& model, PointId P) { return model.points()[P.index]; }

Vec2 position(const Model& model, const VecX& q, PointId P) {
  const Point& p = point_of(model, P);
  return point_at(coords(q, p.body), p.s_bar);
}

// ---- energies and applied forces, from the model's data -------------------------------------

VecX mass_diagonal(const Model& model) {
  VecX d(model.num_coordinates());
  for (int k = 0; k < model.num_bodies(); ++k) {
    const Body& b = model.bodies()[k];
    d.segment<3>(3 * k) << b.mass, b.mass, b.inertia;
  }
  return d;
}

double potential_energy_of(const Model& model, const VecX& q) {
  double V = 0;
  for (int k = 0; k < model.num_bodies(); ++k)
    V -= model.bodies()[k].mass * (model.gravity().x() * q(3 * k) + model.gravity().y() * q(3 * k + 1));
  for (const Force& force : model.forces()) {
    if (const auto* e = std::get_if<PointForce>(&force.element)) {
      if (e->frame == Frame::global) V -= e->F.dot(position(model, q, e->P));
    } else if (const auto* s = std::get_if<Tsda>(&force.element)) {
      const double L = (position(model, q, s->P_j) - position(model, q, s->P_i)).norm();
      V += 0.5 * s->k * (L - s->L0) * (L - s->L0);
    } else if (const auto* r = std::get_if<Rsda>(&force.element)) {
      const double dtheta = coords(q, r->body_j)(2) - coords(q, r->body_i)(2) - r->theta0;
      V += 0.5 * r->k * dtheta * dtheta;
    }
  }
  return V;
}

VecX applied_forces_of(const Model& model, const VecX& q, const VecX& qd, double t) {
  const std::vector<Wrench> w = applied_wrenches(model, q, qd, t);
  VecX Q(model.num_coordinates());
  for (int k = 0; k < model.num_bodies(); ++k) Q.segment<3>(3 * k) << w[k].F, w[k].M;
  return Q;
}

VecX multipliers_of(const Model& model, const VecX& q, const VecX& qd, const VecX& qdd, double t) {
  const MatX Cq = constraint_jacobian(model, q, t);
  const VecX rhs = applied_forces_of(model, q, qd, t) - mass_diagonal(model).cwiseProduct(qdd);
  return solve_with(Cq.transpose(), rhs);
}

// ---- hints ----------------------------------------------------------------------------------

std::string lambda_hint(const Model& model, const VecX& q, const VecX& qd, const VecX& qdd, double t,
                        const VecX& actual) {
  const MatX Cq = constraint_jacobian(model, q, t);
  const VecX Q = applied_forces_of(model, q, qd, t);
  const VecX Mqdd = mass_diagonal(model).cwiseProduct(qdd);
  const VecX expected = solve_with(Cq.transpose(), Q - Mqdd);
  const char* top_row = "C_q^T lambda = Q_a - M q_ddot";  // the top row of (3)
  return diagnose(
      actual, expected,
      {{with_formula("your lambda: the sign of M q_ddot is flipped?", top_row), solve_with(Cq.transpose(), Q + Mqdd)},
       {with_formula("your lambda: the matrix is C_q^T (n x m), not C_q", top_row), solve_with(Cq, Q - Mqdd)},
       {with_formula("your lambda: the matrix is C_q^T (n x m), not C_q, and the sign of M q_ddot is flipped", top_row),
        solve_with(Cq, Q + Mqdd)},
       {with_formula("your lambda leaves out M q_ddot, the inertia forces of the driven motion", top_row),
        solve_with(Cq.transpose(), Q)},
       {with_formula("your lambda leaves out Q_a = applied_forces(model, q, qd, t)", top_row),
        solve_with(Cq.transpose(), -Mqdd)},
       {with_formula("your lambda has the wrong sign", top_row), -expected}},
      upstream_hint(model, q, qd, t) +
          with_formula("your lambda does not solve the top row of (3) (solve_multipliers with C_q = "
                       "constraint_jacobian, Q_a = applied_forces, M = mass_matrix)",
                       top_row));
}

// ---- driven motions -------------------------------------------------------------------------

State state_at(const Model& model, const VecX& guess, double t) { return states_at(model, guess, {t}).front(); }

void check_power_balance(const Model& model, const VecX& guess_before, double t, double h) {
  const std::vector<State> s = states_at(model, guess_before, {t - h, t, t + h});
  REQUIRE(s.size() == 3);
  const State& now = s[1];
  const VecX lambda = lagrange_multipliers(model, now.q, now.qd, now.qdd, t);
  const std::string hint = lambda_hint(model, now.q, now.qd, now.qdd, t, lambda);
  {
    INFO("hint: lambda has one entry per constraint equation (m = " << model.num_constraints() << ")");
    REQUIRE(lambda.size() == model.num_constraints());
  }
  auto energy = [&](const State& x) { return kinetic_energy_of(model, x.qd) + potential_energy_of(model, x.q); };
  const double dE_dt = (energy(s[2]) - energy(s[0])) / (2 * h);
  const double driver_power = lambda.dot(constraint_time_derivative(model, now.q, t));
  const double other_power = nonconservative_power_of(model, now.q, now.qd, t);
  CAPTURE(t, dE_dt, driver_power, other_power);
  CHECK_NEAR_NAMED("the power of the drivers and forces with your lambda", driver_power + other_power, dE_dt, kPower,
                   hint);
  CHECK_CLOSE_NAMED("your lambda", lambda, multipliers_of(model, now.q, now.qd, now.qdd, t), kSolve, hint);
}

// ---- reactions ------------------------------------------------------------------------------

namespace {

// The ground side of a joint carries no reaction.
void check_ground_side(const Reaction& reaction) {
  const char* hint =
      "your reaction on the ground side is not zero: the ground side of a joint has no reaction, leave it zero";
  CHECK_CLOSE_NAMED("the force of your reaction on the ground", reaction.force, Vec2::Zero(), kExact, hint);
  CHECK_NEAR_NAMED("the moment of your reaction on the ground", reaction.moment, 0.0, kExact, hint);
}

// Newton's third law between the two bodies of a joint whose points are P_i and P_j.
void check_third_law(const Model& model, const VecX& q, const JointReaction& r, PointId P_i, PointId P_j) {
  const std::string hint = with_formula("your reactions on the two bodies break Newton's third law: a joint pushes "
                                        "its two bodies with opposite forces and moments",
                                        "-C_q_i^T lambda_c for body i, -C_q_j^T lambda_c for body j");
  CHECK_CLOSE_NAMED("the sum of your reaction forces on the two bodies", r.on_i.force + r.on_j.force, Vec2::Zero(),
                    (Tolerance{1e-9, 0}), hint);
  const double about_origin = r.on_i.moment + cross(position(model, q, P_i), r.on_i.force) + r.on_j.moment +
                              cross(position(model, q, P_j), r.on_j.force);
  CHECK_NEAR_NAMED("the sum of your reactions' moments about the origin", about_origin, 0.0, (Tolerance{1e-9, 0}),
                   hint);
}

}  // namespace

void check_joint_reaction(const Model& model, int c, const VecX& q, const VecX& lambda) {
  const Constraint& con = model.constraints()[c];
  const auto points = joint_points_of(con);
  REQUIRE(points.has_value());
  CAPTURE(con.name);
  const JointReaction r = joint_reaction(model, c, q, lambda);
  const ConstraintBlock b = evaluate_constraint(model, con, q, 0.0);
  const VecX lc = lambda.segment(con.first_row, con.rows);
  const bool revolute = std::holds_alternative<Revolute>(con.type);

  auto side = [&](const char* which, BodyId body, const RowBlock& Cq, PointId P, const Reaction& reaction) {
    CAPTURE(which);
    if (body.is_ground()) {
      check_ground_side(reaction);
      return;
    }
    const Vec3 Q = -(Cq.transpose() * lc);
    const Vec2 F = Q.head<2>();
    const double phi = coords(q, body)(2);
    const Vec2 arm = rotate(phi, point_of(model, P).s_bar);
    const double M_P = Q(2) - cross(arm, F);
    const char* force_of_lambda = "Q_i = -C_q_i^T lambda_c (the joint's rows of lambda)";
    const char* moment_transfer = "M_P = M_centroid - (A_i s_i) x F";
    const std::string sign = with_formula("reaction sign flipped? Your reaction has the sign of +C_q^T lambda",
                                          force_of_lambda);
    CHECK_CLOSE_NAMED(
        "the force of your reaction", reaction.force, F, kSame,
        diagnose(reaction.force, F, {{sign, -F}},
                 with_formula("your reaction force is not the x-y part of the joint's constraint force on "
                              "the body",
                              force_of_lambda)));
    CHECK_NEAR_NAMED(
        "the moment of your reaction", reaction.moment, M_P, kSame,
        diagnose(
            vec({reaction.moment}), vec({M_P}),
            {{with_formula("your moment is the moment about the centroid instead of the joint point?", moment_transfer),
              vec({Q(2)})},
             {with_formula("your moment is moved from the centroid to the joint point with the wrong "
                           "sign (moment transfer sign)",
                           moment_transfer),
              vec({Q(2) + cross(arm, F)})},
             {sign, vec({-M_P})}},
            with_formula("your moment must be about the joint point", moment_transfer)));
    const Vec2 Fb = rotate(-phi, F);
    const char* to_body = "force_body = A_i^T F";
    CHECK_CLOSE_NAMED(
        "the force_body of your reaction", reaction.force_body, Fb, kSame,
        diagnose(reaction.force_body, Fb,
                 {{with_formula("your force_body is turned by +phi: turn the global force into the body "
                                "frame, by -phi",
                                to_body),
                   rotate(phi, F)},
                  {with_formula("your force_body is the global F, not turned into the body frame", to_body), F},
                  {sign, -Fb}},
                 with_formula("your force_body must be the reaction in the frame of its body", to_body)));
    if (revolute)
      CHECK_NEAR_NAMED(
          "the moment of your reaction at a revolute joint", reaction.moment, 0.0, (Tolerance{1e-9, 0}),
          diagnose(vec({reaction.moment}), vec({0.0}),
                   {{with_formula("your moment is the moment about the centroid instead of the joint point? A "
                                  "revolute transmits no moment about its point",
                                  moment_transfer),
                     vec({Q(2)})}},
                   "your revolute's moment is not 0: a revolute joint transmits no moment about its point"));
  };
  side("body i", con.body_i, b.Cq_i, points->first, r.on_i);
  side("body j", con.body_j, b.Cq_j, points->second, r.on_j);

  if (!con.body_i.is_ground() && !con.body_j.is_ground()) check_third_law(model, q, r, points->first, points->second);
}

void check_driver_effort(const Model& model, int c, const State& s, const VecX& lambda) {
  const Constraint& con = model.constraints()[c];
  CAPTURE(con.name, s.t);
  const double effort = driver_effort(model, c, s.q, lambda);
  const double lam = lambda(con.first_row);
  const double Ct = evaluate_constraint(model, con, s.q, s.t).Ct(0);
  double factor = 1.0;  // dC/d(quantity)
  if (const auto* d = std::get_if<DistanceDriver>(&con.type))
    factor = (position(model, s.q, d->P_j) - position(model, s.q, d->P_i)).norm();
  const double expected = -lam * factor;
  const char* effort_of_lambda = "effort = -lambda dC/d(quantity): -lambda for angle and point-coordinate drivers, "
                                 "-lambda |d| for a distance driver (C = 1/2 (|d|^2 - f^2))";
  const std::string hint = diagnose(
      vec({effort}), vec({expected}),
      {{with_formula("your distance driver's effort: |d| factor missing? Differentiate its C with respect to the "
                     "distance", effort_of_lambda),
        vec({-lam})},
       {with_formula("your effort has the wrong sign (effort sign): the driver acts on the bodies with -C_q^T lambda",
                     effort_of_lambda),
        vec({-expected})}},
      with_formula("your effort is not the driver's force or torque on its quantity: its power effort x rate must "
                   "equal lambda C_t", effort_of_lambda));
  const double rate = driven_rate(model, con, s.q, s.qd);
  CAPTURE(effort, rate, lam, Ct);
  CHECK_NEAR_NAMED("the power of your effort", effort * rate, lam * Ct, (Tolerance{1e-8, 1e-7}), hint);
  CHECK_NEAR_NAMED("your effort", effort, expected, (Tolerance{1e-10, 1e-10}), hint);
}

void check_free_bodies(const Model& model, const State& s) {
  const VecX lambda = multipliers_of(model, s.q, s.qd, s.qdd, s.t);
  const std::vector<Wrench> applied = applied_wrenches(model, s.q, s.qd, s.t);
  const std::vector<Wrench> reactions = constraint_wrenches(model, s.q, lambda);
  for (int k = 0; k < model.num_bodies(); ++k) {
    const Body& b = model.bodies()[k];
    CAPTURE(b.name, s.t);
    const std::string hint = "your reactions or efforts break the free-body diagram of body '" + b.name +
                             "': m a must equal gravity + applied forces + the joint reactions on it (force at the "
                             "joint point, moment about that point) + the driver efforts";
    CHECK_CLOSE_NAMED("the forces on the body, applied and your reactions", applied[k].F + reactions[k].F,
                      b.mass * s.qdd.segment<2>(3 * k), kPower, hint);
    CHECK_NEAR_NAMED(
        "the moments on the body, applied and your reactions", applied[k].M + reactions[k].M,
        b.inertia * s.qdd(3 * k + 2), kPower,
        with_formula(hint + "; the moments are about the centroid", "M_P + (r_P - R) x F for each reaction"));
  }
}

// ---- example models -------------------------------------------------------------------------

examples::SliderCrankParameters slider_crank_parameters(double r, double l, double A0, double omega) {
  examples::SliderCrankParameters p;
  p.r = r;
  p.l = l;
  p.A0 = A0;
  p.omega = omega;
  return p;
}

VecX slider_crank_at(const examples::SliderCrankParameters& p, double t) {
  return examples::slider_crank_configuration(p, p.A0 + p.omega * t);
}

Model sprung_slider_crank(const examples::SliderCrankParameters& p, double k, double c) {
  Model m = examples::slider_crank(p);
  m.set_gravity(Vec2(0.0, -9.81));
  const PointId anchor = m.add_point(ground, Vec2(-0.05, 0.25), "spring anchor");
  const PointId rod = m.add_point(m.find_body("rod"), Vec2(0.04, 0.01), "rod spring point");
  m.add_tsda("rod spring", anchor, rod, k, 0.1, c);
  return m;
}

VecX Pendulum::q(double t) const {
  return vec({L / 2 * std::cos(theta(t)), L / 2 * std::sin(theta(t)), theta(t)});
}
VecX Pendulum::qd(double t) const {
  return vec({-L / 2 * w * std::sin(theta(t)), L / 2 * w * std::cos(theta(t)), w});
}
VecX Pendulum::qdd(double t) const {
  return vec({-L / 2 * w * w * std::cos(theta(t)), -L / 2 * w * w * std::sin(theta(t)), 0.0});
}
Pendulum pendulum(double m, double L, double g, double theta0, double w) {
  Pendulum p{Model{}, m, L, g, theta0, w};
  const BodyId rod = p.model.add_body("rod", m, m * L * L / 12, p.q(0.0));
  const PointId O = p.model.add_point(ground, Vec2::Zero(), "O");
  const PointId end = p.model.add_point(rod, Vec2(-L / 2, 0.0), "rod end");
  p.model.add_revolute("pin", O, end);
  p.model.add_absolute_angle_driver("motor", rod, DriveFunction::linear(theta0, w));
  p.model.set_gravity(Vec2(0.0, -g));
  return p;
}

VecX DoublePendulum::exact(double t) const {
  const double t1 = a1(t).f, t2 = t1 + a12(t).f;
  const Vec2 e1(std::cos(t1), std::sin(t1)), e2(std::cos(t2), std::sin(t2));
  const Vec2 c1 = L1 / 2 * e1, c2 = L1 * e1 + L2 / 2 * e2;
  return vec({c1.x(), c1.y(), t1, c2.x(), c2.y(), t2});
}
DoublePendulum double_pendulum(double L1, double L2, DriveFunction a1, DriveFunction a12) {
  DoublePendulum d{Model{}, L1, L2, a1, a12};
  const VecX q0 = d.exact(0.0);
  Model& m = d.model;
  const BodyId l1 = m.add_body("link 1", 1.2, 1.2 * L1 * L1 / 12, q0.segment<3>(0));
  const BodyId l2 = m.add_body("link 2", 0.8, 0.8 * L2 * L2 / 12, q0.segment<3>(3));
  const PointId O = m.add_point(ground, Vec2::Zero(), "O");
  const PointId l1_O = m.add_point(l1, Vec2(-L1 / 2, 0.0), "link 1 base");
  const PointId l1_tip = m.add_point(l1, Vec2(L1 / 2, 0.0), "link 1 tip");
  const PointId l2_base = m.add_point(l2, Vec2(-L2 / 2, 0.0), "link 2 base");
  m.add_revolute("shoulder", O, l1_O);
  m.add_revolute("elbow", l1_tip, l2_base);
  m.add_absolute_angle_driver("shoulder motor", l1, a1);
  m.add_relative_angle_driver("elbow motor", l1, l2, a12);
  m.set_gravity(Vec2(0.0, -9.81));
  return d;
}

VecX ArmCollar::exact(double t) const {
  const double phi = std::asin(tip_y(t).f / (2 * h)), rho = radius(t).f;
  return vec({h * std::cos(phi), h * std::sin(phi), phi, rho * std::cos(phi), rho * std::sin(phi), phi});
}
ArmCollar arm_collar(double h, DriveFunction tip_y, DriveFunction radius, double k, double c,
                     DriveFunction actuator) {
  ArmCollar a{Model{}, h, tip_y, radius};
  const VecX q0 = a.exact(0.0);
  Model& m = a.model;
  const BodyId arm = m.add_body("arm", 1.0, 0.02, q0.segment<3>(0));
  const BodyId collar = m.add_body("collar", 0.5, 0.001, q0.segment<3>(3));
  const PointId O = m.add_point(ground, Vec2::Zero(), "O");
  const PointId arm_O = m.add_point(arm, Vec2(-h, 0.0), "arm pivot");
  const PointId arm_tip = m.add_point(arm, Vec2(h, 0.0), "arm tip");
  const PointId collar_c = m.add_point(collar, Vec2::Zero(), "collar centre");
  const PointId collar_hook = m.add_point(collar, Vec2(0.01, 0.02), "collar hook");
  const PointId anchor = m.add_point(ground, Vec2(0.1, -0.3), "anchor");
  m.add_revolute("pivot", O, arm_O);
  m.add_translational("collar guide", arm_O, collar_c, Vec2::UnitX());
  m.add_point_coordinate_driver("tip height", arm_tip, Axis::y, tip_y);
  m.add_distance_driver("collar radius", O, collar_c, radius);
  m.set_gravity(Vec2(0.0, -9.81));
  m.add_tsda("collar spring", anchor, collar_hook, k, 0.2, c, actuator);
  return a;
}

NodeMarker StandInBody::node_marker(int, const VecX& q, const VecX& qd) const {
  NodeMarker marker;
  marker.pose = q.head<3>();
  marker.velocity = qd.head<3>();
  marker.G = MatX::Identity(3, size());
  return marker;
}

MatX StandInBody::block_of(const VecX& q_j) const {
  MatX B = MatX::Constant(size(), size(), 0.1 + 0.01 * q_j.sum());
  B.diagonal().array() += 2.0 + VecX::LinSpaced(size(), 0.0, 1.0).array();
  return B;
}

VecX StandInBody::forces_of(const VecX& q_j, const VecX& qd_j, const Vec2& g) const {
  return VecX::LinSpaced(size(), 1.0, 2.0) * (1.0 + g.norm()) - 0.5 * q_j - 0.1 * qd_j;
}

}  // namespace fmbd::testing::m03
