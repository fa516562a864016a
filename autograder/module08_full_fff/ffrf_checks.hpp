#pragma once
// Shared helpers of the module 8 graded tests: random node data, the node pose written out,
// its time derivatives by central finite differences (Richardson-extrapolated), the nodal
// velocities in frame j, the FE kinetic energy, a Lagrangian quadratic velocity vector from a
// mass matrix built here, the energy and angular momentum of a flexible body from its nodes,
// and hints that name the likely mistake. The mistake catalogue's `expect:` phrases open these
// hints (Catch wraps long lines, so each phrase stays at the start of its hint).
//
// Every oracle here is independent of the module 8 code under test: the node pose
// r_k = R + A(theta) (x_bar_k + Phi_t,k q_f), phi_k = theta + Phi_psi,k q_f is written out in
// ffrf_checks.cpp (not taken from module 7), accelerations and velocities come from finite
// differences of that pose along smooth motions, and the FE matrices come from the (reference)
// modules 5 to 7.
//
// The definitions are in ffrf_checks.cpp, compiled once for all the module's test files.

#include <cmath>
#include <memory>
#include <string>

#include "fmbd/fe_assembly.hpp"
#include "fmbd/fe_model.hpp"
#include "fmbd/ffrf.hpp"
#include "fmbd/flexible_body.hpp"
#include "fmbd/reduction.hpp"
#include "grading.hpp"

namespace fmbd::testing::m08 {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kG = 9.81;

// ---- small helpers ------------------------------------------------------------------------

/// A number in scientific notation for CAPTURE (Catch prints doubles in fixed notation).
std::string sci(double x);

inline double max_abs(const MatX& A) { return A.size() == 0 ? 0.0 : A.cwiseAbs().maxCoeff(); }

/// The rotation matrix written out (not module 1's rotation()).
inline Mat2 rot(double phi) {
  Mat2 A;
  A << std::cos(phi), -std::sin(phi), std::sin(phi), std::cos(phi);
  return A;
}

inline VecX elastic_part(const VecX& q) { return q.tail(q.size() - 3); }

// ---- the node pose, written out ------------------------------------------------------------

/// Absolute acceleration of the node in frame j at t = 0 along q0 + v t + a t^2/2: A^T r_ddot and
/// phi_ddot, by finite differences of the pose.
Vec3 fd_acceleration(const NodeModes& node, const VecX& q0, const VecX& v, const VecX& a);

/// Absolute velocity of the node in frame j at q0 moving with v: (A^T r_dot, phi_dot), by finite
/// differences of the pose.
Vec3 fd_velocity(const NodeModes& node, const VecX& q0, const VecX& v);

/// The node's L_k by finite differences: column i is the frame-j velocity for q_dot = e_i.
MatX fd_map(const NodeModes& node, const VecX& q);

/// All nodes: the frame-j velocities of q_dot = e_i stacked in the DOF order of the FE model.
MatX fd_stacked_map(const FlexibleBodyData& data, const VecX& q);

/// The frame-j nodal velocities w written out: A^T R_dot + theta_dot I~ (x_bar + u_bar) + Phi_t q_f_dot,
/// and theta_dot + Phi_psi q_f_dot.
VecX nodal_velocities(const FlexibleBodyData& data, const VecX& q, const VecX& qd);

/// The mass matrix of the FE kinetic energy 1/2 w^T M_FE w, built here.
MatX mass_oracle(const FlexibleBodyData& data, const VecX& q);

/// The velocity terms of Lagrange's equations of T = 1/2 q_dot^T M(q) q_dot (M = mass_oracle):
///   Q_v = 1/2 d/dq (q_dot^T M q_dot) - (dM/dt) q_dot,
/// with both derivatives by central differences.
VecX lagrangian_qv(const FlexibleBodyData& data, const VecX& q, const VecX& qd, double h = 1e-5);

/// Stacked undeformed positions (x_bar_k, 0) and displacements Phi_f q_f.
VecX stacked_positions(const FlexibleBodyData& data);

/// Rigid translation columns t_x, t_y (3N x 2).
MatX translations(int nodes);

/// M_bar = Phi^T M_FE Phi with Phi = [rigid columns, Phi_f], computed here.
MatX reduced_mass(const FlexibleBodyData& data);

/// M(q) at q_f = 0 (any theta): T^T M_bar T.
MatX rotated_reduced_mass(const FlexibleBodyData& data, double theta);

/// Hint for a wrong mass matrix M(q); `expected` from the FE kinetic energy.
std::string mass_hint(const MatX& got, const MatX& expected, const FlexibleBodyData& data, const VecX& q);

/// Hint for a wrong Q_v; `expected` from an oracle (Lagrange's equations or the nodal inertia).
std::string qv_hint(const VecX& got, const VecX& expected, const FlexibleBodyData& data, const VecX& q, const VecX& qd);

/// (0, 0, 0, K_ff q_f).
VecX elastic_rows(const FlexibleBodyData& data, const VecX& q);

/// Hint for wrong body forces at rest; `expected` from an oracle.
std::string rest_force_hint(const VecX& got, const VecX& expected, const FlexibleBodyData& data, const VecX& q,
                            const Vec2& g);

// ---- energy and momentum of one flexible body from its nodes -------------------------------

/// T = 1/2 w^T M_FE w (frame-j nodal velocities written out).
double fe_kinetic_energy(const FlexibleBodyData& data, const VecX& q, const VecX& qd);

/// V = -g^T (first moment of the mass) + 1/2 u^T K_FE u, first moment m R + A T_xy^T M_FE (X + u).
double fe_potential_energy(const FlexibleBodyData& data, const VecX& q, const Vec2& g);

/// Angular momentum about the mass centre of a body with a diagonal (lumped) mass matrix: the
/// translational masses m_k at the node positions r_k with velocities v_k, and the rotary
/// inertias J_k turning with phi_dot_k:
///   H = sum_k m_k (r_k - r_c) x v_k + J_k phi_dot_k,   r_c = sum m_k r_k / m.
double lumped_angular_momentum(const FlexibleBodyData& data, const VecX& q, const VecX& qd);

/// True when M is diagonal with equal masses in x and y at every node (HRZ lumped).
bool isotropic_lumped(const MatX& M);

// ---- random data ---------------------------------------------------------------------------

/// A node with random x_bar and random rows in the basis (n_f columns).
NodeModes random_node(Random& rnd, int n_f);

/// A random state: R in [-2, 2], theta in [-pi, pi], q_f of size n_f in [-f, f].
VecX random_q(Random& rnd, int n_f, double f);

/// The nodal elastic-coordinate scale of a body: q_f of this size moves the nodes by about
/// `fraction` of the body size (the modes are mass-normalised, Phi ~ 1/sqrt(m)).
double modal_scale(const FlexibleBodyData& data, double fraction);

// ---- bodies ----------------------------------------------------------------------------------

/// An L-shaped frame (10 elements): 0.9 m along x of a 20 mm square, then 0.6 m up of a 15 mm square,
/// a soft polymer-like material.
FeModel l_frame(const Vec2& start = Vec2(0.2, -0.1));

/// `d` moved into a shared pointer to const data.
std::shared_ptr<const FlexibleBodyData> shared(FlexibleBodyData d);

// ---- hints -----------------------------------------------------------------------------------

/// Hint for a wrong L_k; `expected` is the finite-difference map of the node at q.
std::string map_hint(const MatX& got, const MatX& expected, const NodeModes& node, const VecX& q);

/// Hint for a wrong b_k; `expected` is the finite-difference acceleration of the node along
/// q + v t (no q_ddot).
std::string bias_hint(const Vec3& got, const Vec3& expected, const NodeModes& node, const VecX& q, const VecX& qd);

}  // namespace fmbd::testing::m08
