#pragma once
// Shared helpers of the module 3 graded tests: plain formulas for the energies, the applied
// forces per body (as a free-body diagram) and the multipliers, the example models with their
// exact configurations, the power balance and free-body-diagram checks, and hints that name
// the likely mistake (the mistake catalogue's `expect:` phrases open these hints; Catch wraps
// long lines, so each phrase stays at the start of its hint).
//
// Every oracle here is independent of the student's module 3 code: it uses the model's data,
// module 1 constraint values and Jacobians, the module 2 kinematic analysis (for q, q_dot and
// q_ddot of a driven motion), the given closed forms of examples.hpp, and formulas written out
// below. The given code of module 3 (applied_forces assembly, energy) is not used as an oracle.
//
// The functions are defined in dynamics_checks.cpp, compiled once and linked into every graded
// program of the module. Helpers of the hidden tests only are in hidden/dynamics_hidden_checks.hpp.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fmbd/constraints.hpp"
#include "fmbd/drive_function.hpp"
#include "fmbd/applied_forces.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/inverse_dynamics.hpp"
#include "fmbd/kinematic_analysis.hpp"
#include "fmbd/mass_matrix.hpp"
#include "fmbd/model.hpp"
#include "fmbd/reactions.hpp"
#include "fmbd/deformable.hpp"
#include "grading.hpp"

namespace fmbd::testing::m03 {

inline constexpr Tolerance kExact{1e-12, 1e-12};  ///< identities of plain arithmetic
inline constexpr Tolerance kFD{1e-7, 1e-6};       ///< central differences in q, h = 1e-6
inline constexpr Tolerance kSolve{1e-8, 1e-8};    ///< against a multiplier solve of the test
inline constexpr Tolerance kPower{1e-6, 1e-6};    ///< power balance with dE/dt by differences in time
inline constexpr Tolerance kSame{1e-9, 1e-9};     ///< the same formula evaluated in another order

// ---- plain planar formulas ------------------------------------------------------------------

/// A(phi) s, written out.
Vec2 rotate(double phi, const Vec2& s);
/// Planar cross product a x b = a_x b_y - a_y b_x.
double cross(const Vec2& a, const Vec2& b);

/// r_P = R + A(phi) s on a body with coordinates qi (zero for the ground: r_P = s).
Vec2 point_at(const Vec3& qi, const Vec2& s);
/// v_P = R_dot + phi_dot I~ A s.
Vec2 velocity_at(const Vec3& qi, const Vec3& vi, const Vec2& s);
/// dr_P/dq_i = [I_2 | I~ A s], written out.
Eigen::Matrix<double, 2, 3> jacobian_at(const Vec3& qi, const Vec2& s);

/// Coordinates of `body` in q (zero for the ground).
Vec3 coords(const VecX& q, BodyId body);
const Point& point_of(const Model& model, PointId P);
/// Global position r_P of point P at q.
Vec2 position(const Model& model, const VecX& q, PointId P);

// ---- energies and applied forces, from the model's data -------------------------------------

/// Diagonal of the mass matrix: (m_k, m_k, J_k) per body.
VecX mass_diagonal(const Model& model);

/// V = -sum m g^T R - sum (global point forces) F^T r_P + sum 1/2 k (L - L0)^2 + sum 1/2 k (theta - theta0)^2.
double potential_energy_of(const Model& model, const VecX& q);

/// Q_a from a free-body diagram of every body (gravity at the centroid, each force element as
/// forces at its points and pure moments), stacked as (F_x, F_y, M_centroid) per body.
VecX applied_forces_of(const Model& model, const VecX& q, const VecX& qd, double t);

/// A flexible stand-in for the assembly tests (T1, T3): n_f modes, a node at its frame's origin
/// (G = [I 0]), and add_mass and add_forces that add known blocks (block_of(), forces_of()).
class StandInBody final : public DeformableBody {
 public:
  explicit StandInBody(int modes) : modes_(modes) {}
  int num_modes() const override { return modes_; }
  int num_nodes() const override { return 1; }
  Vec2 node_position(int) const override { return Vec2::Zero(); }
  double mass() const override { return 2.0; }
  double inertia() const override { return 0.5; }
  NodeMarker node_marker(int node, const VecX& q, const VecX& qd) const override;
  void add_node_columns(const NodeMarker& node, const RowBlock& B, int first_row, int at, MatX& Cq) const override {
    Cq.block(first_row, at, B.rows(), node.G.cols()) += B * node.G;
  }
  RowVector node_gamma_term(const NodeMarker& node, const RowBlock& B) const override { return -(B * node.convective); }
  void add_node_force(const NodeMarker& node, const Vec3& Q, int at, VecX& Q_a) const override {
    Q_a.segment(at, node.G.cols()) += node.G.transpose() * Q;
  }
  void add_mass(const VecX& q, int at, MatX& M) const override { M.block(at, at, size(), size()) += block_of(q.segment(at, size())); }
  void add_forces(const VecX& q, const VecX& qd, const Vec2& g, int at, VecX& Q_a) const override {
    Q_a.segment(at, size()) += forces_of(q.segment(at, size()), qd.segment(at, size()), g);
  }
  double kinetic_energy(const VecX& q, const VecX& qd) const override { return 0.5 * qd.dot(block_of(q) * qd); }
  double potential_energy(const VecX&, const Vec2&) const override { return 0.0; }
  /// Its block of M at its coordinates q_j: symmetric positive definite, every entry non-zero,
  /// depending on q_j.
  MatX block_of(const VecX& q_j) const;
  /// Its own forces at (q_j, q_j_dot) under gravity g: every entry non-zero.
  VecX forces_of(const VecX& q_j, const VecX& qd_j, const Vec2& g) const;

 private:
  int size() const { return 3 + modes_; }
  int modes_;
};

/// lambda from C_q^T lambda = Q_a - M q_ddot with the test's own Q_a and M (full-pivot LU).
VecX multipliers_of(const Model& model, const VecX& q, const VecX& qd, const VecX& qdd, double t);

// ---- hints ----------------------------------------------------------------------------------

/// The formulas behind the named mistakes of the force elements: a message shows them through
/// with_formula (hint_gate.hpp), at the task's last hint level only.
inline constexpr const char* kTensionFormula = "f = k (L - L0) + c L_dot + f_a, L_dot = u^T d_dot";
inline constexpr const char* kTorqueFormula =
    "T = k (theta - theta0) + c theta_dot + T_a, theta = phi_j - phi_i; Q_i = (0, 0, +T), Q_j = (0, 0, -T)";

/// Hint for wrong multipliers at one instant: which slip of C_q^T lambda = Q_a - M q_ddot
/// reproduces them. Starts with "mass_matrix is wrong ... " or "applied_forces is wrong ..."
/// if the student's T1-T3 results differ from the test's own.
std::string lambda_hint(const Model& model, const VecX& q, const VecX& qd, const VecX& qdd, double t,
                        const VecX& actual);

// ---- driven motions -------------------------------------------------------------------------

/// q, q_dot, q_ddot of a driven model at time t.
struct State {
  double t = 0;
  VecX q, qd, qdd;
};

/// The state at time t from the module 2 kinematic analysis, with a tight position tolerance.
State state_at(const Model& model, const VecX& guess, double t);

/// Power balance at time t: d(T + V)/dt (central difference of the test's own energies along
/// the kinematic analysis at t +- h) = lambda^T C_t + (power of dampers, actuators, torques,
/// follower forces), with lambda from the student's lagrange_multipliers at t.
void check_power_balance(const Model& model, const VecX& guess_before, double t, double h = 1e-4);

// ---- reactions ------------------------------------------------------------------------------

/// Checks joint_reaction for joint c against -C_q^T lambda of its module 1 block (with hints
/// naming the usual slips), Newton's third law between its two bodies, and a zero moment at a
/// revolute joint.
void check_joint_reaction(const Model& model, int c, const VecX& q, const VecX& lambda);

/// Checks driver_effort for driver c: effort x (rate of the driven quantity) = lambda_c C_t,c,
/// and the effort itself, -lambda dC/d(quantity).
void check_driver_effort(const Model& model, int c, const State& s, const VecX& lambda);

/// Free-body diagram of every body at a state: m a = applied forces + reactions (joint_reaction:
/// force at the joint point, moment about it) + driver forces (driver_effort), J phi_ddot = their
/// moments about the centroid. lambda from the test's own solve.
void check_free_bodies(const Model& model, const State& s);

// ---- example models -------------------------------------------------------------------------

/// Slider-crank parameters with the crank angle A(t) = A0 + omega t.
examples::SliderCrankParameters slider_crank_parameters(double r, double l, double A0, double omega);

/// The slider-crank's exact configuration at time t (given closed form).
VecX slider_crank_at(const examples::SliderCrankParameters& p, double t);

/// The driven slider-crank with gravity and a spring from a ground anchor to the rod.
Model sprung_slider_crank(const examples::SliderCrankParameters& p, double k, double c = 0.0);

/// A uniform rod (mass m, length L) hinged at its end to the ground origin, turned at
/// theta(t) = theta0 + w t, with gravity (0, -g).
struct Pendulum {
  Model model;
  double m, L, g, theta0, w;
  double theta(double t) const { return theta0 + w * t; }
  VecX q(double t) const;
  VecX qd(double t) const;
  VecX qdd(double t) const;
};
Pendulum pendulum(double m, double L, double g, double theta0, double w);

/// Two links: link 1 (length L1) hinged to the ground origin at one end with its angle driven,
/// link 2 (length L2) hinged to the tip of link 1 with the relative angle driven. Gravity.
struct DoublePendulum {
  Model model;
  double L1, L2;
  DriveFunction a1, a12;
  VecX exact(double t) const;
};
DoublePendulum double_pendulum(double L1, double L2, DriveFunction a1, DriveFunction a12);

/// An arm (pivot-to-tip length 2 h) turning about the ground origin, a collar sliding along it
/// (translational joint). Drivers: y of the arm tip f_y(t) (point coordinate) and the distance
/// from the origin to the collar f_d(t). Gravity, and a spring-damper from a ground anchor to
/// the collar. Closed form: phi = asin(f_y / 2h), collar at f_d (cos phi, sin phi).
struct ArmCollar {
  Model model;
  double h;
  DriveFunction tip_y, radius;
  VecX exact(double t) const;
};
ArmCollar arm_collar(double h, DriveFunction tip_y, DriveFunction radius, double k, double c,
                     DriveFunction actuator = DriveFunction::constant(0.0));

}  // namespace fmbd::testing::m03
