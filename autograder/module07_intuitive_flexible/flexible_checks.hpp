#pragma once
// Shared helpers of the module 7 graded tests: the node kinematics written out by hand (pose,
// Jacobian, convective acceleration), random nodes and states, finite differences in time,
// whole-model checks of C_q and gamma against finite differences of C(q, t), the rigid-body and
// translation columns of a beam, a basis that is not M-orthogonal to the rigid modes, the
// potential energy of the intuitive body written out from the FE matrices, and the static
// Ritz solution of a clamped beam in a reduced basis. The mistake catalogue's `expect:` phrases
// open the hints (Catch wraps long lines, so each phrase stays at the start of its hint).
//
// Every oracle here is independent of the student's module 7 code: plain formulas, Eigen's
// solvers, the FE matrices of module 5 and the basis of module 6 (reference stages under the
// graded module 7 targets), and module 1's C(q, t), which sees a flexible body only through the
// node pose (task T1).
//
// The definitions are in flexible_checks.cpp, compiled once for all the module's test files.

#include <cmath>
#include <functional>
#include <string>

#include "fmbd/constraints.hpp"
#include "fmbd/fe_assembly.hpp"
#include "fmbd/fe_model.hpp"
#include "fmbd/flexible_body.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/gamma.hpp"
#include "fmbd/intuitive_flexible.hpp"
#include "fmbd/marker.hpp"
#include "fmbd/model.hpp"
#include "fmbd/reduction.hpp"
#include "grading.hpp"

namespace fmbd::testing::m07 {

inline constexpr double kSteelE = 2.1e11;
inline constexpr double kSteelRho = 7850.0;

/// Appended to the hints of tests on whole models: the engine puts each flexible body into M and
/// Q_a through T4 to T6, and module 1 evaluates the whole node marker (pose, G_k and c_k) for C.
inline const std::string kNeedsT4 =
    " (the model needs M07T4-T6: the engine adds M_bar to M and gravity and -K_bar q to Q_a through them; C(q, t) "
    "calls all of T1-T3)";

/// The node's formulas behind the hint gate (with_formula): shown at the task's last hint level only.
inline constexpr const char* kPose = "p_k = (R + A (x_bar_k + u_bar_k), theta + psi_k), u_bar = Phi_t q_f";
inline constexpr const char* kColumn2 = "column 2 of G_k is dA/dtheta (x_bar + u_bar) = A I~ (x_bar + u_bar)";
inline constexpr const char* kElasticColumns = "dr_k/dq_f = A(theta) Phi_t";

// ---- plain planar formulas (not the student's) ------------------------------------------

/// A(phi) = [[cos, -sin], [sin, cos]], written out.
inline Mat2 rot(double phi) {
  Mat2 A;
  A << std::cos(phi), -std::sin(phi), std::sin(phi), std::cos(phi);
  return A;
}
/// I~ = [[0, -1], [1, 0]]: turns a vector by +90 degrees.
inline Mat2 tilde() {
  Mat2 T;
  T << 0.0, -1.0, 1.0, 0.0;
  return T;
}

inline double max_abs(const MatX& A) { return A.size() == 0 ? 0.0 : A.cwiseAbs().maxCoeff(); }

// ---- one node: the kinematics by hand ----------------------------------------------------

inline VecX elastic_part(const VecX& q) { return q.tail(q.size() - 3); }

/// u_bar_k = Phi_t,k q_f (frame), psi_k = Phi_psi,k q_f.
inline Vec2 u_bar(const NodeModes& node, const VecX& q) { return node.Phi_t * elastic_part(q); }
inline double psi(const NodeModes& node, const VecX& q) { return node.Phi_psi.row(0).dot(elastic_part(q)); }

/// p_k = (R + A (x_bar + u_bar), theta + psi).
Vec3 pose_oracle(const NodeModes& node, const VecX& q);

/// The two parts of c_k (position rows): centripetal -theta_dot^2 A (x_bar + u_bar) and
/// Coriolis 2 theta_dot A I~ Phi_t q_f_dot.
struct ConvectiveParts {
  Vec2 centripetal = Vec2::Zero();
  Vec2 coriolis = Vec2::Zero();
};
ConvectiveParts convective_parts(const NodeModes& node, const VecX& q, const VecX& qd);

/// A random node with n_f modes: x_bar, Phi_t and Phi_psi of order one.
NodeModes random_node(Random& rnd, int n_f);

/// A random q = (R, theta, q_f): R of order one, any angle, q_f of order `elastic`.
VecX random_node_state(Random& rnd, int n_f, double elastic = 0.3);

/// Second derivative of g at 0 by the five-point stencil (error O(h^4)).
VecX second_derivative(const std::function<VecX(double)>& g, double h);

// ---- whole models --------------------------------------------------------------------------

/// A state near q0: every frame moved by up to `shift` [m] and turned by up to `turn` [rad], the
/// elastic coordinates of each flexible body of order `deflection` times its length scale
/// (mass-normalised modes: amplitude about 1/sqrt(m) per unit q_f).
VecX random_model_state(const Model& model, const VecX& q0, Random& rnd, double shift, double turn, double deflection);

/// Random rates: frame velocities up to `speed` [m/s], angular rates up to `spin` [rad/s],
/// elastic rates `elastic_rate` times the elastic scale of random_model_state.
VecX random_model_rates(const Model& model, Random& rnd, double speed, double spin, double elastic_rate);

/// C_q of the model at (q, t) against central differences of module 1's C(q, t), checked
/// block by block: rows of each constraint, and for each flexible body its frame translation,
/// its angle and its elastic columns, each with the hint of the slip that breaks it.
void check_constraint_jacobian(const Model& model, const VecX& q, double t, const std::string& label);

/// gamma of the model at (q, q_dot, t) against the second time derivative of C along the
/// straight motion q(s) = q + s q_dot at time t + s (q_ddot = 0, so gamma = -d2C/ds2, driver
/// terms C_tt included).
void check_gamma(const Model& model, const VecX& q, const VecX& qd, double t, const std::string& label);

// ---- beams and bases ------------------------------------------------------------------------

inline Section steel(double side) { return square_section(kSteelE, kSteelRho, side); }

/// A basis that is NOT M-orthogonal to the rigid modes: rigid columns, then the static shape of a
/// tip load of the beam clamped at node 0, then its `modes` lowest cantilever modes (zero at
/// node 0, so their mean displacement, S_f, does not vanish). M_bar and K_bar filled from Phi.
ReducedBasis cantilever_basis(const FeModel& fe, const FeMatrices& fm, int modes);

/// The intuitive potential written out from the FE matrices of the body's data:
///   V(q) = -g^T (m R + A S_f q_f) + 1/2 q_f^T K_ff q_f,
/// m = t_x^T M t_x, S_f = [t_x t_y]^T M Phi_f, K_ff = Phi_f^T K Phi_f.
struct Potential {
  double mass = 0.0;
  MatX S_f, K_ff;
  Vec2 g = Vec2::Zero();
  double operator()(const VecX& q) const;
};
Potential potential_of(const FlexibleBodyData& d, const Vec2& g);

// ---- static Ritz solution of a clamped beam ------------------------------------------------

/// The nodal displacements u = Phi q (FE frame of the data) that minimise
/// 1/2 q^T K_bar q - q^T Phi^T F over q subject to (Phi q) = 0 at the three DOFs of `clamped`,
/// F = M_FE times the uniform gravity field g: the static solution of the FE model in the
/// body's own reduced basis, by its KKT system.
VecX ritz_static_clamped(const FlexibleBodyData& d, int clamped, const Vec2& g);

/// Checks node_pose at every node against the FE field u = Phi_f q_f placed by the frame:
/// p_k = (R + A (x_k + u_k), theta + psi_k), with the hints of the likely slips.
void check_poses_follow_fe_field(const FlexibleBodyData& d, const VecX& q, double tolerance);

}  // namespace fmbd::testing::m07
