#pragma once
// Helpers of the module 8 graded tests of the geometric stiffening (tasks T7 and T8): a random
// chain of elements with the foreshortening of its last node written from the README's definition
// (f_k = -1/2 sum_e (q_f^T H_e q_f) t_e), its derivatives by central finite differences, the
// stiffened node pose and its accelerations by finite differences, and hints that name the likely
// mistake from finite-difference quantities only (no formula of a task is written here).
//
// The definitions are in stiffening_checks.cpp, compiled once for all the module's test files.
#include <string>
#include <vector>

#include "ffrf_checks.hpp"
#include "fmbd/geometric_stiffening.hpp"

namespace fmbd::testing::m08 {

/// Elements from the anchor to a node: per element H_e (symmetric positive semi-definite) and t_e.
struct Chain {
  std::vector<MatX> H;
  std::vector<Vec2> t;
};

/// A chain of `elements` random elements over n_f elastic coordinates.
Chain random_chain(Random& rnd, int elements, int n_f);

/// The last node's foreshortening by the README's definition: -1/2 sum_e (q_f^T H_e q_f) t_e.
Vec2 chain_shortening(const Chain& chain, const VecX& q_f);

/// The last node's NodeShortening from your shortening_across_element, element by element from
/// the anchor (whose f, J, c are zero).
NodeShortening chained(const Chain& chain, const VecX& q_f, const VecX& q_f_dot);

/// The node's foreshortening from finite differences of chain_shortening: f, J = df/dq_f and
/// c = d^2/dt^2 f(q_f + q_f_dot t) at t = 0.
NodeShortening fd_shortening(const Chain& chain, const VecX& q_f, const VecX& q_f_dot);

/// Hint for a wrong J_k or c_k of the last element of `chain`, from the finite-difference parts of
/// its parent and of the element itself.
std::string shortening_hint(const NodeShortening& got, const Chain& chain, const VecX& q_f, const VecX& q_f_dot);

/// The absolute acceleration in frame j of a node at x_bar + Phi_t q_f + f(q_f) (f from
/// chain_shortening) along q0 + v t + a t^2 / 2, by finite differences of its pose.
Vec3 fd_stiffened_acceleration(const NodeModes& node, const Chain& chain, const VecX& q0, const VecX& v,
                               const VecX& a);

/// Its L_k by finite differences: column i is the frame-j velocity for q_dot = e_i.
MatX fd_stiffened_map(const NodeModes& node, const Chain& chain, const VecX& q);

/// Hint for wrong rows after add_shortening_rows at (q, qd); `before` are the rows you were given,
/// s the foreshortening you were given. Each suspect is the finite-difference answer with one of
/// its parts, measured by finite differences too, left out or changed.
std::string stiffened_rows_hint(const MatX& L, const Vec3& b, const MatX& L_before, const Vec3& b_before,
                                const NodeModes& node, const Chain& chain, const VecX& q, const VecX& qd,
                                const NodeShortening& s);

/// The stiffness of the elastic coordinates of a body whose frame is clamped at node 0, spinning at
/// Omega about that node (at the origin) with q_f = 0: K = -dF/dq_f by central differences, with
/// F = Q_f - (M q_ddot_rigid)_f the elastic rows of the body's equations when the frame's steady
/// spin is prescribed (R_ddot = -Omega^2 R).
MatX spin_stiffness(const DeformableBody& body, const FlexibleBodyData& data, double Omega);

}  // namespace fmbd::testing::m08
