// Module 4 demo (with module 3's multipliers): what redundant constraints and singular positions
// do to forward dynamics.
//   1. A door on two coaxial hinges swings exactly as on one: q_ddot is unique, lambda is not.
//      The engine reports the minimum-norm lambda, which shares the load evenly; any split with
//      the same sum gives the same motion.
//   2. A parallelogram at its flat position has two motions from the same position: on the
//      parallelogram branch the coupler translates; on the antiparallelogram branch it turns.
//      A velocity that mixes them has no acceleration at all (SingularJacobianError): at a
//      singular position the velocity must lie on one branch's tangent, which is why a projection
//      that leaves a residual near a flat position can hand the motion to the other branch.
#include <Eigen/LU>
#include <cmath>
#include <cstdio>
#include <gnuplot-iostream.h>

#include "demo.hpp"
#include "fmbd/constraints.hpp"
#include "fmbd/forward_dynamics.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/mass_matrix.hpp"
#include "fmbd/simulation.hpp"

namespace {

using namespace fmbd;

SimulationOptions rk4(double h, double output) {
  SimulationOptions o;
  o.integrator = Integrator::rk4;
  o.step = h;
  o.stabilisation = Stabilisation::projection;
  o.output_interval = output;
  return o;
}

// A door of 12 kg (J = 1.5 kg m^2, centroid 0.4 m from the hinge axis) under gravity and a
// closing torque of 2 N m, on `hinges` coaxial hinges.
Model door(int hinges) {
  Model m;
  m.set_gravity(Vec2(0, -9.81));
  const BodyId leaf = m.add_body("door", 12.0, 1.5, Vec3(0.4, 0, 0));
  for (int k = 0; k < hinges; ++k) {
    const std::string name = k == 0 ? "upper" : "lower";
    m.add_revolute(name + " hinge", m.add_point(ground, Vec2::Zero(), name + " frame"),
                   m.add_point(leaf, Vec2(-0.4, 0), name + " leaf"));
  }
  m.add_torque("closer", leaf, DriveFunction::constant(-2.0));
  return m;
}

void two_hinges(const demo::Options& options) {
  const Model one = door(1), two = door(2);
  SimulationOptions o = rk4(1e-3, 0.01);
  o.record_multipliers = true;
  const VecX q0 = one.initial_guess(), qd0 = VecX::Zero(3);
  const Trajectory a = simulate(one, q0, qd0, 0.0, 3.0, o), b = simulate(two, q0, qd0, 0.0, 3.0, o);
  const auto single = a.reactions(one, "upper hinge"), upper = b.reactions(two, "upper hinge"),
             lower = b.reactions(two, "lower hinge");
  demo::Table table{{"t [s]", "phi_one_hinge [rad]", "phi_two_hinges [rad]", "force_one_hinge [N]",
                     "force_upper_hinge [N]", "force_lower_hinge [N]"},
                    {}};
  double motion = 0, share = 0;
  for (std::size_t i = 0; i < a.t.size(); ++i) {
    const double f1 = single[i].on_j.force.norm(), fu = upper[i].on_j.force.norm(), fl = lower[i].on_j.force.norm();
    table.add({a.t[i], a.q[i](2), b.q[i](2), f1, fu, fl});
    motion = std::max(motion, std::abs(a.q[i](2) - b.q[i](2)));
    if (f1 > 0) share = std::max(share, std::abs(fu / f1 - 0.5));
  }
  std::printf("door: the angle on two hinges differs from one hinge by at most %.1e rad; each hinge "
              "carries 50 %% of the force within %.1e\n",
              motion, share);
  demo::write_csv(options, "door_two_hinges", table);

  demo::Figure figure(options, "door_two_hinges", 1100, 500);
  if (!figure.active()) return;
  char title[200];
  std::snprintf(title, sizeof title, "two hinges: phi differs by %.0e rad; each hinge carries 50 %% (minimum-norm lambda)",
                motion);
  figure.gp() << "set multiplot layout 1,2 title 'Door (12 kg) on one hinge and on two coaxial hinges: " << title
              << "'\nset xlabel 't [s]'\nset key top center\nset yrange [-3.5:1.2]\nset ylabel 'phi [rad]'\nset title 'door angle'\n"
              << "plot '-' w l lw 4 title 'one hinge', '-' w l lw 2 dt 2 title 'two hinges'\n";
  figure.send(table, {0, 1});
  figure.send(table, {0, 2});
  figure.gp() << "set autoscale y\nset ylabel '|F| [N]'\nset title 'hinge force (any split of the sum moves the door alike)'\n"
              << "set key top right\n"
              << "plot '-' w l lw 3 title 'one hinge', '-' w l lw 2 title 'upper of two', "
                 "'-' w l lw 2 dt 2 title 'lower of two'\n";
  for (int c = 3; c <= 5; ++c) figure.send(table, {0, c});
  figure.gp() << "unset multiplot\n";
}

// A parallelogram: cranks of 0.2 m at x = 0 and 0.6 m, joined by a coupler of 0.6 m, under
// gravity, at its flat position (every angle 0).
struct Parallelogram {
  static constexpr double a = 0.2, d = 0.6;
  Model model;
  VecX q;
  Parallelogram() : q(9) {
    model.set_gravity(Vec2(0, -9.81));
    const BodyId c1 = model.add_body("crank 1", 0.6, 0.6 * a * a / 12), c2 = model.add_body("crank 2", 0.6, 0.6 * a * a / 12);
    const BodyId coupler = model.add_body("coupler", 1.8, 1.8 * d * d / 12);
    model.add_revolute("pivot 1", model.add_point(ground, Vec2(0, 0), "ground 1"), model.add_point(c1, Vec2(-a / 2, 0), "foot 1"));
    model.add_revolute("pivot 2", model.add_point(ground, Vec2(d, 0), "ground 2"), model.add_point(c2, Vec2(-a / 2, 0), "foot 2"));
    model.add_revolute("top 1", model.add_point(c1, Vec2(a / 2, 0), "head 1"), model.add_point(coupler, Vec2(-d / 2, 0), "end 1"));
    model.add_revolute("top 2", model.add_point(c2, Vec2(a / 2, 0), "head 2"), model.add_point(coupler, Vec2(d / 2, 0), "end 2"));
    q << a / 2, 0, 0, d + a / 2, 0, 0, d / 2 + a, 0, 0;
  }
};

// The two branch tangents at the flat position, crank 1 at rate w. The null space of C_q there has
// two directions; the branches are the two that keep the loop closed to second order:
// (theta1 - theta2) (d (theta1 + theta2) + a (theta1 - theta2)) = 0, so crank 2 turns at w on the
// parallelogram branch (the coupler translates) and at -w (d + a) / (d - a) on the
// antiparallelogram branch (the coupler turns).
std::pair<VecX, VecX> branch_tangents(const Parallelogram& p, double w) {
  const double a = Parallelogram::a, d = Parallelogram::d;
  const MatX Z = Eigen::FullPivLU<MatX>(evaluate_constraints(p.model, p.q, 0.0).Cq).kernel();
  auto tangent = [&](double w2) {  // the null vector with crank rates w and w2
    Eigen::Matrix2d rates;
    rates << Z(2, 0), Z(2, 1), Z(5, 0), Z(5, 1);
    return VecX(Z * rates.lu().solve(Eigen::Vector2d(w, w2)));
  };
  return {tangent(w), tangent(-w * (d + a) / (d - a))};
}

void two_branches(const demo::Options& options) {
  const Parallelogram p;
  const auto [along, other] = branch_tangents(p, 3.0);
  const SimulationOptions o = rk4(1e-4, 0.005);
  const Trajectory first = simulate(p.model, p.q, along, 0.0, 1.0, o);
  const Trajectory second = simulate(p.model, p.q, other, 0.0, 1.0, o);
  std::string mixed = "accepted (unexpected)";
  try {
    forward_dynamics(p.model, p.q, along + 1e-3 * other, 0.0);
  } catch (const SingularJacobianError&) {
    mixed = "no acceleration (SingularJacobianError)";
  }
  demo::Table table{{"t [s]", "crank1_parallelogram [rad]", "crank2_parallelogram [rad]", "coupler_parallelogram [rad]",
                     "crank1_antiparallelogram [rad]", "crank2_antiparallelogram [rad]",
                     "coupler_antiparallelogram [rad]"},
                    {}};
  double coupler = 0, turned = 0;
  for (std::size_t i = 0; i < first.t.size() && i < second.t.size(); ++i) {
    table.add({first.t[i], first.q[i](2), first.q[i](5), first.q[i](8), second.q[i](2), second.q[i](5), second.q[i](8)});
    coupler = std::max(coupler, std::abs(first.q[i](8)));
    turned = std::max(turned, std::abs(second.q[i](8)));
  }
  std::printf("parallelogram from its flat position: the parallelogram branch keeps the coupler within %.1e rad; "
              "the antiparallelogram branch turns it by up to %.2f rad; a velocity that mixes them: %s\n",
              coupler, turned, mixed.c_str());
  demo::write_csv(options, "parallelogram_branches", table);

  demo::Figure figure(options, "parallelogram_branches", 1100, 500);
  if (!figure.active()) return;
  figure.gp() << "set multiplot layout 1,2 title 'Parallelogram released flat, crank 1 at 3 rad/s: two motions from one "
                 "position (a velocity that mixes them: " << mixed << ")'\n"
              << "set xlabel 't [s]'\nset ylabel 'angle [rad]'\nset key bottom left\n"
              << "set title sprintf('parallelogram branch: the coupler stays within %.0e rad', " << coupler << ")\n"
              << "plot '-' w l lw 3 title 'crank 1', '-' w l lw 2 dt 2 title 'crank 2', '-' w l lw 2 title 'coupler'\n";
  for (int c = 1; c <= 3; ++c) figure.send(table, {0, c});
  figure.gp() << "set title sprintf('antiparallelogram branch: the coupler turns by up to %.2f rad', " << turned << ")\n"
              << "plot '-' w l lw 3 title 'crank 1', '-' w l lw 2 dt 2 title 'crank 2', '-' w l lw 2 title 'coupler'\n";
  for (int c = 4; c <= 6; ++c) figure.send(table, {0, c});
  figure.gp() << "unset multiplot\n";
}

}  // namespace

int main(int argc, char** argv) {
  return demo::run(argc, argv, "redundancy", [](const demo::Options& options) {
    two_hinges(options);
    two_branches(options);
  });
}
