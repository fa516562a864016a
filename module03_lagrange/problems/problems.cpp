// Tutorial problems of module 3 (README.md in this folder): the reaction at the pivot of a driven
// pendulum, the generalised mass of a slider-crank referred to its crank angle, the motor
// torque of a driven pendulum (inverse dynamics), and the hinge forces of a door on two hinges
// (a redundant constraint: the multipliers of least norm). Every answer and every named mistake
// is computed by the engine on a model built here.
#include <Eigen/LU>
#include <Eigen/QR>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "fmbd/applied_forces.hpp"
#include "fmbd/constraints.hpp"
#include "fmbd/dof.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/inverse_dynamics.hpp"
#include "fmbd/mass_matrix.hpp"
#include "fmbd/model.hpp"
#include "fmbd/reactions.hpp"
#include "fmbd/velocity_acceleration.hpp"
#include "modules.hpp"

namespace fmbd::problems {

namespace {

// ---- a driven pendulum: a uniform rod pinned at one end -----------------------------------

struct Pendulum {
  double m = 1, L = 1, g = 9.81;  // kg, m, m/s^2 (gravity along -y)
  double phi_deg = 0;             // rod angle from the x axis, counter-clockwise
  double omega = 0, alpha = 0;    // rad/s, rad/s^2
};

struct PendulumResult {
  Vec2 reaction;  // force of the pivot on the rod [N]
  double torque;  // motor torque on the rod [N m]
};

// Inverse dynamics of the rod O-B (centroid at mid-length, J = m L^2 / 12) pinned at O = (0, 0),
// its angle driven as phi + omega t + alpha t^2 / 2, at t = 0. `inertia` < 0: the uniform rod's.
PendulumResult pendulum(const Pendulum& p, double phi, double inertia = -1) {
  Model m;
  const double J = inertia < 0 ? p.m * p.L * p.L / 12 : inertia;
  const BodyId rod = m.add_body("rod", p.m, J, Vec3(p.L / 2 * std::cos(phi), p.L / 2 * std::sin(phi), phi));
  const PointId O = m.add_point(ground, Vec2::Zero(), "O");
  const PointId end = m.add_point(rod, Vec2(-p.L / 2, 0), "rod O");
  const int pin = m.add_revolute("pivot", O, end);
  const int motor = m.add_absolute_angle_driver("motor", rod, DriveFunction::polynomial({phi, p.omega, p.alpha / 2}));
  m.set_gravity(Vec2(0, -p.g));
  const VecX q = m.initial_guess();
  const VecX qd = solve_velocities(m, q, 0.0);
  const VecX qdd = solve_accelerations(m, q, qd, 0.0);
  const VecX lambda = lagrange_multipliers(m, q, qd, qdd, 0.0);
  return {joint_reaction(m, pin, q, lambda).on_j.force, driver_effort(m, motor, q, lambda)};
}

Pendulum draw_pendulum(Parameters& r, bool accelerating) {
  Pendulum p;
  p.m = r.grid(0.5, 0.1, 46);
  p.L = r.grid(0.20, 0.05, 17);
  p.phi_deg = r.grid(5, 5, 17) + 90 * r.integer(0, 3);
  p.omega = (r.integer(0, 1) ? 1 : -1) * r.grid(1.0, 0.5, 13);
  if (accelerating) p.alpha = (r.integer(0, 1) ? 1 : -1) * r.grid(2, 1, 19);
  return p;
}

std::string pendulum_text(const Pendulum& p) {
  std::string text = "A uniform rod of mass m = " + format_value(p.m) + " kg and length L = " + format_value(p.L) +
                     " m is pinned to the ground at its end O = (0, 0) and turns in the vertical plane (gravity g = " +
                     format_value(p.g) + " m/s^2 along -y). A motor at O drives its angle phi (from the x axis, counter-clockwise). "
                     "At this instant phi = " + format_value(p.phi_deg) + " deg and phi_dot = " + format_value(p.omega) + " rad/s";
  return text + (p.alpha == 0 ? ", at a constant rate (phi_ddot = 0)." : ", phi_ddot = " + format_value(p.alpha) + " rad/s^2.");
}

// ---- M03P1: the pivot's reaction ---------------------------------------------------------

Problem reaction_problem() {
  Problem p;
  p.id = "M03P1";
  p.title = "reaction at the pivot of a driven pendulum";
  p.points = 3;
  p.tolerance = Tolerance(2e-3, 1e-4);
  p.kind = Kind::vector;
  p.rows = 2;
  p.unit = "N";
  p.make = [](Parameters& r) {
    const Pendulum d = draw_pendulum(r, false);
    Variant v;
    v.statement = pendulum_text(d) + "\nGive the force (F_x, F_y) that the pivot exerts on the rod.";
    v.solve = [d] {
      const double phi = d.phi_deg * kDeg;
      const Vec2 F = pendulum(d, phi).reaction;
      Pendulum still = d;
      still.omega = 0;
      Pendulum weightless = d;
      weightless.g = 0;
      Solution s;
      s.answer = vec2(F);
      s.mistakes.emplace_back("the centrifugal term m (L/2) phi_dot^2 left out", vec2(pendulum(still, phi).reaction));
      s.mistakes.emplace_back("the weight left out", vec2(pendulum(weightless, phi).reaction));
      s.mistakes.emplace_back("degrees against radians: phi in degrees put into cos and sin as radians",
                              vec2(pendulum(d, d.phi_deg).reaction));
      const Vec2 a_G = -(d.L / 2) * d.omega * d.omega * Vec2(std::cos(phi), std::sin(phi));
      s.steps.push_back("phi = " + format_value(phi) + " rad; the centroid moves on a circle of radius L/2 = " + format_value(d.L / 2) + " m");
      s.steps.push_back("a_G = -(L/2) phi_dot^2 (cos phi, sin phi) = " + format_quantity(vec2(a_G)) + " m/s^2");
      s.steps.push_back("m g = " + format_quantity(vec2(Vec2(0, -d.m * d.g))) + " N");
      s.steps.push_back("F = m a_G - m g = " + format_quantity(vec2(F)) + " N");
      return s;
    };
    return v;
  };
  return p;
}

// ---- M03P2: generalised mass of a slider-crank -------------------------------------------

struct CrankMasses {
  double r, l, A_deg;     // m, m, deg
  double m1, m2, m3;      // crank, rod, slider [kg]
};

// A slider-crank (examples::slider_crank's geometry) with the masses given, uniform links
// (J = m L^2 / 12); rod_inertia < 0: the uniform rod's.
Model crank_model(const CrankMasses& d, double m3, double rod_inertia) {
  examples::SliderCrankParameters p;
  p.r = d.r;
  p.l = d.l;
  p.A0 = d.A_deg * kDeg;
  p.omega = 1.0;
  const VecX q0 = examples::slider_crank_configuration(p, p.A0);
  Model m;
  const BodyId crank = m.add_body("crank", d.m1, d.m1 * d.r * d.r / 12, q0.segment<3>(0));
  const BodyId rod = m.add_body("rod", d.m2, rod_inertia < 0 ? d.m2 * d.l * d.l / 12 : rod_inertia, q0.segment<3>(3));
  const BodyId slider = m.add_body("slider", m3, 0.0, q0.segment<3>(6));
  const PointId O = m.add_point(ground, Vec2::Zero(), "O");
  m.add_revolute("O", O, m.add_point(crank, Vec2(-d.r / 2, 0), "crank O"));
  m.add_revolute("B", m.add_point(crank, Vec2(d.r / 2, 0), "crank B"), m.add_point(rod, Vec2(-d.l / 2, 0), "rod B"));
  const PointId C = m.add_point(slider, Vec2::Zero(), "slider C");
  m.add_revolute("C", m.add_point(rod, Vec2(d.l / 2, 0), "rod C"), C);
  m.add_translational("guide", m.add_point(ground, Vec2::Zero(), "guide"), C, Vec2::UnitX());
  m.add_absolute_angle_driver("crank angle", crank, DriveFunction::linear(p.A0, 1.0));
  return m;
}

// v^T M v with v = dq/dA (the velocities at a crank speed of 1 rad/s).
double generalised_mass(const CrankMasses& d, double m3, double rod_inertia) {
  const Model m = crank_model(d, m3, rod_inertia);
  const VecX q = m.initial_guess();
  const VecX v = solve_velocities(m, q, 0.0);
  return v.dot(mass_matrix(m) * v);
}

Problem mass_problem() {
  Problem p;
  p.id = "M03P2";
  p.title = "generalised mass of a slider-crank";
  p.points = 3;
  p.tolerance = Tolerance(2e-3, 1e-7);
  p.unit = "kg m^2";
  p.make = [](Parameters& r) {
    CrankMasses d{};
    d.r = r.grid(0.05, 0.01, 11);
    d.l = r.grid(0.20, 0.02, 11);
    d.A_deg = r.grid(10, 10, 8) + 180 * r.integer(0, 1);
    d.m1 = r.grid(0.5, 0.1, 16);
    d.m2 = r.grid(1.0, 0.1, 21);
    d.m3 = r.grid(0.5, 0.1, 26);
    Variant v;
    v.statement = "A slider-crank: the crank O-B (r = " + format_value(d.r) + " m, m_1 = " + format_value(d.m1) +
                  " kg) turns about O = (0, 0); the rod B-C (l = " + format_value(d.l) + " m, m_2 = " + format_value(d.m2) +
                  " kg) drives the slider C (m_3 = " + format_value(d.m3) + " kg) along the x axis. Crank and rod are uniform "
                  "bars (J = m L^2 / 12 about their centroids, at mid-length).\nAt the crank angle A = " + format_value(d.A_deg) +
                  " deg, the kinetic energy is T = 1/2 M_A(A) A_dot^2. Give the generalised mass M_A (about the crank "
                  "angle).";
    v.solve = [d] {
      const double M = generalised_mass(d, d.m3, -1);
      Solution s;
      s.answer = Quantity::number(M);
      s.mistakes.emplace_back("the rod's rotation left out (its J_2 phi_dot_2^2 term)",
                              Quantity::number(generalised_mass(d, d.m3, 0.0)));
      s.mistakes.emplace_back("the slider left out", Quantity::number(generalised_mass(d, 0.0, -1)));
      const Model m = crank_model(d, d.m3, -1);
      const VecX vel = solve_velocities(m, m.initial_guess(), 0.0);
      s.steps.push_back("dq/dA = " + format_quantity(Quantity::vector(std::vector<double>(vel.data(), vel.data() + vel.size()))) +
                        " (per rad: crank, rod, slider as x, y, phi)");
      s.steps.push_back("M = diag(m_1, m_1, J_1, m_2, m_2, J_2, m_3, m_3, 0)");
      s.steps.push_back("M_A = (dq/dA)^T M (dq/dA) = " + format_value(M) + " kg m^2");
      return s;
    };
    return v;
  };
  return p;
}

// ---- M03P3: the motor torque of inverse dynamics ------------------------------------------

Problem torque_problem() {
  Problem p;
  p.id = "M03P3";
  p.title = "motor torque of a driven pendulum";
  p.points = 2;
  p.tolerance = Tolerance(2e-3, 1e-5);
  p.unit = "N m";
  p.make = [](Parameters& r) {
    const Pendulum d = draw_pendulum(r, true);
    Variant v;
    v.statement = pendulum_text(d) + "\nGive the torque that the motor applies to the rod (counter-clockwise positive).";
    v.solve = [d] {
      const double phi = d.phi_deg * kDeg;
      const double T = pendulum(d, phi).torque;
      // J about the centroid instead of the pivot: take m (L/2)^2 alpha, the torque that turns a
      // point mass m at L/2 without gravity, away.
      Pendulum point = d;
      point.g = 0;
      const double steiner = pendulum(point, phi, 0.0).torque;
      Pendulum upside_down = d;
      upside_down.g = -d.g;
      Solution s;
      s.answer = Quantity::number(T);
      s.mistakes.emplace_back("J about the centroid (m L^2 / 12) instead of the pivot (m L^2 / 3)", Quantity::number(T - steiner));
      s.mistakes.emplace_back("the moment of the weight with the wrong sign",
                              Quantity::number(pendulum(upside_down, phi).torque));
      s.mistakes.emplace_back("the angle taken from the vertical: sin phi instead of cos phi in the weight's moment",
                              Quantity::number(pendulum(d, phi - kPi / 2).torque));
      s.mistakes.emplace_back("degrees against radians: phi in degrees put into cos as radians",
                              Quantity::number(pendulum(d, d.phi_deg).torque));
      s.steps.push_back("J_O = m L^2 / 3 = " + format_value(d.m * d.L * d.L / 3) + " kg m^2");
      s.steps.push_back("moment of the weight about O: -m g (L/2) cos phi = " + format_value(-d.m * d.g * d.L / 2 * std::cos(phi)) + " N m");
      s.steps.push_back("T = J_O phi_ddot + m g (L/2) cos phi = " + format_value(T) + " N m");
      return s;
    };
    return v;
  };
  return p;
}

// ---- M03P4: a door on two hinges, the multipliers of least norm ---------------------------

struct Door {
  double m = 1, w = 1, H = 2;  // door: mass [kg], width and height [m], a uniform plate
  double arm = 0.5;            // horizontal distance of its centroid from the hinge axis [m] (w/2)
  double y1 = 0, y2 = 1;       // heights of the lower and the upper hinge above the bottom edge [m]
  double mb = 0, d = 0;        // the bag at the handle: mass [kg], distance from the hinge axis [m]
  double g = 9.81;             // m/s^2, along -y
};

inline constexpr double kHandleHeight = 1.0;  // m above the bottom edge (a vertical load: any height)

// Which hinge carries the vertical load: both (two revolute joints, one row redundant: the
// multipliers of least norm), or one, the other guiding the door only horizontally (a point
// coordinate driver on x: the door held statically determinate).
enum class Hold { both, lower_only, upper_only };

struct HingeForces {
  Vec2 lower, upper;  // force of the hinge at y1 and at y2 on the door [N]
};

// The multipliers of least norm |lambda| solving C_q^T lambda = Q_a - M q_ddot with q_ddot = 0 (the
// door cannot move: rank C_q = n). It is the solve of solve_multipliers without its refusal of
// dependent rows, as module 4's solve_augmented takes it on its rank-revealing path.
VecX least_norm_multipliers(const Model& model, const VecX& q) {
  const MatX Cq = constraint_jacobian(model, q, 0.0);
  const VecX rhs = applied_forces(model, q, VecX::Zero(q.size()), 0.0);
  Eigen::CompleteOrthogonalDecomposition<MatX> cod(Cq.transpose());
  cod.setThreshold(rank_tolerance);
  const VecX lambda = cod.solve(rhs);
  if ((Cq.transpose() * lambda - rhs).norm() > 1e-9 * (1 + rhs.norm()))
    throw std::logic_error("M03P4: the hinges cannot hold the door at rest");
  return lambda;
}

// The door in its own plane: x from the hinge axis towards the free edge, y up from its bottom
// edge; its hinges on x = 0, gravity and the bag's weight on it, at rest.
Model door_model(const Door& d, Hold hold, int& lower, int& upper) {
  Model m;
  m.set_gravity(Vec2(0, -d.g));
  const BodyId door = m.add_body("door", d.m, d.m * (d.w * d.w + d.H * d.H) / 12, Vec3(d.arm, d.H / 2, 0));
  auto hinge = [&](const std::string& name, double y, bool carries) {
    const PointId leaf = m.add_point(door, Vec2(-d.arm, y - d.H / 2), name + " leaf");
    if (!carries) return m.add_point_coordinate_driver(name + " guide", leaf, Axis::x, DriveFunction::constant(0.0));
    return m.add_revolute(name + " hinge", m.add_point(ground, Vec2(0, y), name + " frame"), leaf);
  };
  lower = hinge("lower", d.y1, hold != Hold::upper_only);
  upper = hinge("upper", d.y2, hold != Hold::lower_only);
  m.add_point_force("bag", m.add_point(door, Vec2(d.d - d.arm, kHandleHeight - d.H / 2), "handle"), Vec2(0, -d.mb * d.g));
  return m;
}

HingeForces door_forces(const Door& d, Hold hold) {
  int lower = 0, upper = 0;
  const Model m = door_model(d, hold, lower, upper);
  const VecX q = m.initial_guess();
  const int n = m.num_coordinates();
  const VecX lambda = hold == Hold::both ? least_norm_multipliers(m, q)
                                         : lagrange_multipliers(m, q, VecX::Zero(n), VecX::Zero(n), 0.0);
  auto force = [&](int c, bool carries) {
    return carries ? Vec2(joint_reaction(m, c, q, lambda).on_j.force) : Vec2(driver_effort(m, c, q, lambda), 0.0);
  };
  return {force(lower, hold != Hold::upper_only), force(upper, hold != Hold::lower_only)};
}

Quantity hinge_answer(const HingeForces& f) { return Quantity::vector({f.lower.x(), f.lower.y(), f.upper.x(), f.upper.y()}); }

std::string door_statement(const Door& d) {
  return "A door, a uniform plate of mass m = " + format_value(d.m) + " kg, width w = " + format_value(d.w) +
         " m and height H = " + format_value(d.H) + " m, hangs on two hinges on its vertical edge. Take x horizontal, "
         "from the hinge axis towards the free edge, and y up from the door's bottom edge: hinge 1 (the lower) is at "
         "y_1 = " + format_value(d.y1) + " m, hinge 2 (the upper) at y_2 = " + format_value(d.y2) + " m. A bag of m_b = " +
         format_value(d.mb) + " kg hangs from the handle, a horizontal distance d = " + format_value(d.d) +
         " m from the hinge axis. The door is at rest under gravity (g = " + format_value(d.g) + " m/s^2 along -y).\n"
         "Model the door as a planar body in its own plane and each hinge as a revolute joint to the ground: 4 "
         "constraint equations for 3 coordinates, one of them redundant, so the multipliers lambda are not unique. "
         "Give the forces of the hinges on the door that the multipliers of least norm |lambda| give (the ones the "
         "engine reports; a hinge's two multipliers are its force, up to the sign), as (F_1x, F_1y, F_2x, F_2y).";
}

// The named mistakes, each the engine's answer on the door with the mistake made.
std::vector<Mistake> door_mistakes(const Door& d, const HingeForces& F) {
  Door swapped = d;  // the hinges swapped: the horizontal forces change sign
  std::swap(swapped.y1, swapped.y2);
  Door wide = d;
  wide.arm = d.w;
  Door no_bag = d;
  no_bag.mb = 0;
  Door corners = d;
  corners.y1 = 0;
  corners.y2 = d.H;
  Quantity no_couple = hinge_answer(F);
  no_couple.values[0] = no_couple.values[2] = 0;
  std::vector<Mistake> mistakes;
  mistakes.emplace_back("all the vertical load on the upper hinge (one hinge takes everything): a split that holds "
                        "the door, but not the one of least norm",
                        hinge_answer(door_forces(d, Hold::upper_only)));
  mistakes.emplace_back("all the vertical load on the lower hinge (one hinge takes everything): a split that holds "
                        "the door, but not the one of least norm",
                        hinge_answer(door_forces(d, Hold::lower_only)));
  mistakes.emplace_back("the horizontal forces with the wrong signs (the upper hinge pushing the door away from the "
                        "hinge axis, the lower one pulling it in)",
                        hinge_answer(door_forces(swapped, Hold::both)));
  mistakes.emplace_back("the horizontal forces left out: they form the couple that balances the moment of the loads",
                        no_couple);
  mistakes.emplace_back("the weight of the door at the lever w instead of w/2 (its centroid is at mid-width)",
                        hinge_answer(door_forces(wide, Hold::both)));
  mistakes.emplace_back("the bag left out", hinge_answer(door_forces(no_bag, Hold::both)));
  mistakes.emplace_back("the distance of the hinges taken as the height H of the door instead of y_2 - y_1",
                        hinge_answer(door_forces(corners, Hold::both)));
  return mistakes;
}

// The worked numbers. The engine's view first: C_q of full column rank (the door cannot move),
// one dependent row, and the hinge forces of a null vector of C_q^T (a change of lambda that
// changes no equation); then the statics of the door.
std::vector<std::string> door_steps(const Door& d, const HingeForces& F, const Quantity& answer) {
  int lower = 0, upper = 0;
  const Model m = door_model(d, Hold::both, lower, upper);
  const VecX q = m.initial_guess();
  const MatX Cq = constraint_jacobian(m, q, 0.0);
  const Eigen::FullPivLU<MatX> lu(Cq.transpose());
  VecX null = lu.kernel().col(0);
  null /= joint_reaction(m, lower, q, null).on_j.force.y();
  for (Eigen::Index k = 0; k < null.size(); ++k)
    if (std::abs(null(k)) < 1e-12) null(k) = 0.0;  // round-off of the kernel
  const double W = (d.m + d.mb) * d.g, M = d.g * (d.m * d.w / 2 + d.mb * d.d);
  std::vector<std::string> steps;
  steps.push_back("C_q has " + std::to_string(Cq.rows()) + " rows and rank " + std::to_string(lu.rank()) +
                  " = n: the door cannot move (q_ddot = 0); " + std::to_string(Cq.rows() - lu.rank()) +
                  " row is redundant");
  steps.push_back("lambda + t n with n a null vector of C_q^T changes the hinge forces by t " +
                  format_quantity(vec2(joint_reaction(m, lower, q, null).on_j.force)) + " (hinge 1) and t " +
                  format_quantity(vec2(joint_reaction(m, upper, q, null).on_j.force)) +
                  " (hinge 2) for any t [N]: only the sum F_1y + F_2y is fixed");
  steps.push_back("W = (m + m_b) g = " + format_value(W) + " N; moment of the loads about the hinge axis "
                  "g (m w/2 + m_b d) = " + format_value(M) + " N m; h = y_2 - y_1 = " + format_value(d.y2 - d.y1) + " m");
  steps.push_back("F_2x = -g (m w/2 + m_b d) / h = " + format_value(F.upper.x()) + " N, F_1x = -F_2x = " +
                  format_value(F.lower.x()) + " N");
  steps.push_back("least |lambda|: F_1y = F_2y = W/2 = " + format_value(F.lower.y()) + " N");
  steps.push_back("(F_1x, F_1y, F_2x, F_2y) = " + format_quantity(answer) + " N");
  return steps;
}

Problem door_problem() {
  Problem p;
  p.id = "M03P4";
  p.title = "hinge forces of a door on two hinges (a redundant constraint)";
  p.points = 2;
  p.tolerance = Tolerance(2e-3, 1e-4);
  p.kind = Kind::vector;
  p.rows = 4;
  p.unit = "N";
  p.make = [](Parameters& r) {
    Door d;
    d.m = r.grid(15, 1, 26);
    d.w = r.grid(0.70, 0.05, 7);
    d.H = r.grid(1.90, 0.05, 7);
    d.y1 = r.grid(0.15, 0.05, 6);
    d.y2 = d.H - r.grid(0.15, 0.05, 6);
    d.mb = r.grid(2, 0.5, 13);
    d.d = d.w - r.grid(0.05, 0.01, 6);
    d.arm = d.w / 2;
    Variant v;
    v.statement = door_statement(d);
    v.solve = [d] {
      const HingeForces F = door_forces(d, Hold::both);
      Solution s;
      s.answer = hinge_answer(F);
      s.mistakes = door_mistakes(d, F);
      s.steps = door_steps(d, F, s.answer);
      return s;
    };
    return v;
  };
  return p;
}

}  // namespace

std::vector<Problem> module03_problems() {
  return {reaction_problem(), mass_problem(), torque_problem(), door_problem()};
}

}  // namespace fmbd::problems
