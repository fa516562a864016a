#pragma once
// Shared helpers of the module-1 graded tests: finite-difference oracles for one
// ConstraintBlock and for a whole model, closed-form configurations, and the hints that
// name the likely mistake (the mistake catalogue's `expect:` phrases live in these hints;
// keep each phrase within the first ~100 characters of its hint: Catch wraps long lines).

#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <variant>

#include "fmbd/constraint_block.hpp"
#include "fmbd/constraints.hpp"
#include "fmbd/drive_function.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/model.hpp"
#include "fmbd/planar.hpp"
#include "grading.hpp"

namespace fmbd::m01 {

using testing::Tolerance;

inline constexpr double kPi = 3.14159265358979323846;

// ---- tolerances ------------------------------------------------------------------------
inline constexpr Tolerance kExact{1e-12, 1e-12};     ///< closed-form identities
inline constexpr Tolerance kGeometry{1e-10, 1e-10};  ///< C on closed-form configurations
inline constexpr Tolerance kFD{1e-7, 1e-6};          ///< central differences, h = 1e-6 (q) / 1e-5 (t)

// ---- hints: "what differs: the likely mistake" ------------------------------------------
namespace hint {
// T1
inline const char* const rotation_orthonormal =
    "A(phi) must be orthonormal with det +1: A = [[cos, -sin], [sin, cos]]";
inline const char* const rotation_group = "A(a) A(b) must equal A(a + b): are sin and cos of the same angle?";
inline const char* const rotation_transposed =
    "A(pi/2) must turn (1, 0) into (0, 1): is A transposed (sign of sin swapped)?";
inline const char* const rotation_derivative =
    "dA/dphi differs from finite differences of A: it is A I~ = [[-sin, -cos], [cos, -sin]]";
inline const char* const point_position = "r_P = R_i + A(phi_i) s_bar: did you add R_i and rotate s_bar by A?";
inline const char* const jacobian_translation =
    "the x and y columns of dr_P/dq_i are I_2: r_P moves one to one with R_i";
inline const char* const jacobian_rotation =
    "did you use A where A*I~ belongs? The phi column is d(A s)/dphi = A I~ s, not A s";
// T2
inline const char* const revolute_closed =
    "C = R_i + A_i s_i - R_j - A_j s_j must vanish when the two points coincide";
inline const char* const revolute_gap =
    "C = r_Pi - r_Pj: moving body j by delta must give C = -delta; are the points swapped?";
inline const char* const revolute_Cq_i_translation = "C_q_i columns x, y must be +I_2 because C = r_Pi - r_Pj";
inline const char* const revolute_Cq_j_translation =
    "did you forget the minus sign of body j? C = r_Pi - r_Pj, so C_q_j = -dr_Pj/dq_j";
inline const char* const revolute_Cq_phi =
    "did you use A where A*I~ belongs? C_q column phi is +-A I~ s (minus for body j)";
inline const char* const joint_Ct = "a joint does not depend on time: C_t must be zero (start from ConstraintBlock::zero)";
// T3
inline const char* const translational_on_line =
    "C_1 = n_i^T (r_Pj - r_Pi) with n_i = A_i I~ axis must vanish when P_j is on the sliding line";
inline const char* const translational_offset =
    "moving P_j by delta along n_i = A_i I~ axis must give C_1 = +delta: check n_i and d = r_Pj - r_Pi";
inline const char* const angle_row =
    "angle row: C = phi_j - phi_i - phi0; did you write phi_i - phi_j or drop phi0?";
inline const char* const translational_Cq_translation =
    "dC_1/dR_i = -n_i^T and dC_1/dR_j = +n_i^T: check n_i = A_i I~ axis and d = r_Pj - r_Pi";
inline const char* const translational_Cq_phi_i =
    "did you forget that the normal n_i turns with body i? dC_1/dphi_i = -(A_i axis)^T d - n_i^T A_i I~ s_i";
inline const char* const translational_Cq_phi_j =
    "dC_1/dphi_j = n_i^T A_j I~ s_j: did you use A where A*I~ belongs?";
inline const char* const angle_row_Cq =
    "the angle row of C_q disagrees with finite differences of your own C: C = phi_j - phi_i - phi0 has "
    "-1 in column phi_i and +1 in column phi_j; check the sign of C as well as C_q";
// T4
inline const char* const fixed_closed =
    "fixed joint: rows 1-2 are the revolute rows r_Pi - r_Pj, row 3 is phi_j - phi_i - phi0";
// T5
inline const char* const driver_Ct =
    "is C_t missing or its sign flipped? For C = (quantity) - f(t), C_t = -f'(t)";
inline const char* const driver_C = "a driver reads C = (measured quantity) - f(t): check the quantity and the sign of f";
inline const char* const absolute_Cq = "absolute-angle driver: C = phi_i - f(t), so C_q_i = [0, 0, 1]";
inline const char* const relative_Cq = "relative-angle driver: C_q_i = [0, 0, -1] and C_q_j = [0, 0, +1]";
inline const char* const coordinate_Cq =
    "point-coordinate driver: C_q_i is row k of dr_P/dq_i (k = 0 for x, 1 for y); A I~ s, not A s";
inline const char* const distance_Cq =
    "check the factor 1/2 and the sign of body i: C_q_i = -d^T dr_Pi/dq_i, C_q_j = +d^T dr_Pj/dq_j";
inline const char* const distance_C = "distance driver: C = 1/2 (d^T d - f^2) with d = r_Pj - r_Pi";
inline const char* const distance_Ct = "distance driver: C_t = -f f' (chain rule on -f(t)^2 / 2); is the factor f missing?";
// T6
inline const char* const rank_relative =
    "the threshold is relative to the largest singular value: count sigma_k > rank_tolerance * sigma_max";
inline const char* const rank_empty = "the rank of an empty matrix (no constraints) is 0";
inline const char* const rank_value = "jacobian_rank: count the singular values above rank_tolerance * sigma_max";
inline const char* const dof_rank =
    "DOF = 3 n_b - rank C_q, not the number of rows (redundant rows remove no freedom); a wrong C_q also "
    "changes the rank, so fix failing joint tests first";
}  // namespace hint

// ---- formatting --------------------------------------------------------------------------
template <typename Derived>
std::string show(const Eigen::MatrixBase<Derived>& v) {
  std::ostringstream s;
  s.precision(6);
  s << "(";
  for (Eigen::Index k = 0; k < v.size(); ++k) s << (k ? ", " : "") << v(k);
  s << ")";
  return s.str();
}

// ---- one block: finite differences in q_i, q_j and t --------------------------------------
using BlockOfQ = std::function<ConstraintBlock(const Vec3& q_i, const Vec3& q_j)>;

struct BlockDifferences {
  MatX Cq_i, Cq_j;
};

/// Central differences of the block's C with respect to q_i and q_j (h = 1e-6).
inline BlockDifferences block_differences(const BlockOfQ& block, const Vec3& q_i, const Vec3& q_j) {
  VecX x(6);
  x << q_i, q_j;
  const MatX J = testing::finite_difference_jacobian(
      [&](const VecX& y) -> VecX {
        const ConstraintBlock b = block(y.head<3>(), y.tail<3>());
        return VecX(b.C);
      },
      x, 1e-6);
  return {J.leftCols(3), J.rightCols(3)};
}

/// Central difference in time of C(t) = block(f(t)).C (h = 1e-5).
inline VecX time_difference(const std::function<ConstraintBlock(const DriveValue&)>& block,
                            const DriveFunction& f, double t) {
  return testing::finite_difference_first([&](double s) -> VecX { return VecX(block(f(s)).C); }, t, 1e-5);
}

// ---- whole model ---------------------------------------------------------------------------

/// The hint for entries of C_q in local row `row` of constraint `c`, in the columns of body i
/// (`body_i`) or body j, x-y columns or the phi column (`phi`).
inline const char* jacobian_hint(const Constraint& c, int row, bool body_i, bool phi) {
  switch (c.type.index()) {
    case 1:  // translational: row 0 normal offset, row 1 angle
      if (row == 1) return hint::angle_row_Cq;
      if (!phi) return hint::translational_Cq_translation;
      return body_i ? hint::translational_Cq_phi_i : hint::translational_Cq_phi_j;
    case 0:
    case 2:  // revolute, fixed: rows 0-1 points, fixed row 2 angle
      if (row == 2) return hint::angle_row_Cq;
      if (phi) return hint::revolute_Cq_phi;
      return body_i ? hint::revolute_Cq_i_translation : hint::revolute_Cq_j_translation;
    case 3: return hint::absolute_Cq;
    case 4: return hint::relative_Cq;
    case 5: return hint::coordinate_Cq;
    default: return hint::distance_Cq;
  }
}

inline std::string where(const Model& model, const Constraint& c) {
  return model.describe_row(c.first_row) + ", rows " + std::to_string(c.first_row) + ".." +
         std::to_string(c.first_row + c.rows - 1);
}

/// Checks the assembled C_q and C_t of `model` at (q, t) against central differences of the
/// assembled C, constraint by constraint and column group by column group (x-y or phi of
/// each body), with the hint of the first row that differs. Returns false if any differs.
inline bool check_model_derivatives(const Model& model, const VecX& q, double t) {
  const ConstraintEvaluation e = evaluate_constraints(model, q, t);
  const MatX J = testing::finite_difference_jacobian(
      [&](const VecX& y) -> VecX { return constraints(model, y, t); }, q, 1e-6);
  const VecX Ct = testing::finite_difference_first(
      [&](double s) -> VecX { return constraints(model, q, s); }, t, 1e-5);
  bool ok = true;
  for (const Constraint& c : model.constraints()) {
    INFO(where(model, c) << " at q = " << show(q) << ", t = " << t);
    for (bool side_i : {true, false}) {
      const BodyId body = side_i ? c.body_i : c.body_j;
      if (body.is_ground()) continue;
      INFO("columns of body " << (side_i ? "i" : "j") << " '" << model.body_name(body) << "'");
      for (bool phi : {false, true}) {
        const auto got = e.Cq.block(c.first_row, 3 * body.index + (phi ? 2 : 0), c.rows, phi ? 1 : 2);
        const auto fd = J.block(c.first_row, 3 * body.index + (phi ? 2 : 0), c.rows, phi ? 1 : 2);
        int bad = 0;
        while (bad < c.rows && testing::compare(got.row(bad), fd.row(bad), kFD).ok) ++bad;
        CHECK_CLOSE(got, fd, kFD, jacobian_hint(c, bad < c.rows ? bad : 0, side_i, phi));
        ok = ok && bad == c.rows;
      }
    }
    const auto rows_Ct = e.Ct.segment(c.first_row, c.rows);
    const auto fd_Ct = Ct.segment(c.first_row, c.rows);
    const char* h = !c.is_driver() ? hint::joint_Ct : c.type.index() == 6 ? hint::distance_Ct : hint::driver_Ct;
    CHECK_CLOSE(rows_Ct, fd_Ct, kFD, h);
    ok = ok && testing::compare(rows_Ct, fd_Ct, kFD).ok;
  }
  return ok;
}

/// Checks C(q, t) = 0 constraint by constraint, with the constraint's hint.
inline bool check_model_closes(const Model& model, const VecX& q, double t, Tolerance tol = kGeometry) {
  const VecX C = constraints(model, q, t);
  bool ok = true;
  for (const Constraint& c : model.constraints()) {
    INFO(where(model, c) << " at q = " << show(q) << ", t = " << t);
    const auto rows = C.segment(c.first_row, c.rows);
    const VecX zero = VecX::Zero(c.rows);
    const char* h = hint::driver_C;
    switch (c.type.index()) {
      case 0: h = hint::revolute_closed; break;
      case 1: h = hint::translational_on_line; break;
      case 2: h = hint::fixed_closed; break;
      case 6: h = hint::distance_C; break;
      default: break;
    }
    const bool ok_c = testing::compare(rows, zero, tol).ok;
    CHECK_CLOSE(rows, zero, tol, h);
    ok = ok && ok_c;
  }
  return ok;
}

// ---- closed-form configurations ------------------------------------------------------------

/// Coordinates of a link from end point a to end point b with its centroid at mid-length and
/// its body x axis along a -> b (the convention of examples.cpp).
inline Vec3 link_between(const Vec2& a, const Vec2& b) {
  const Vec2 mid = 0.5 * (a + b), d = b - a;
  return Vec3(mid.x(), mid.y(), std::atan2(d.y(), d.x()));
}

/// Coordinates (9) of the four-bar at crank angle theta on the open branch, from the closed-form
/// position of joint C; the crank angle is theta itself (not wrapped), as its driver prescribes.
inline VecX four_bar_configuration(const examples::FourBarParameters& p, double theta) {
  Vec2 C;
  REQUIRE(examples::four_bar_joint_C(p, theta, C));
  const Vec2 B(p.a * std::cos(theta), p.a * std::sin(theta));
  VecX q(9);
  q << link_between(Vec2::Zero(), B), link_between(B, C), link_between(C, Vec2(p.d, 0));
  q(2) = theta;
  return q;
}

/// Body coordinates that put the body-fixed point s_bar at the global position r with angle phi.
inline Vec3 place(const Vec2& r, const Vec2& s_bar, double phi) {
  const double c = std::cos(phi), s = std::sin(phi);
  const Vec2 As(c * s_bar.x() - s * s_bar.y(), s * s_bar.x() + c * s_bar.y());
  return Vec3(r.x() - As.x(), r.y() - As.y(), phi);
}

/// Independent A(phi) (no student code) for building geometry.
inline Mat2 rot(double phi) {
  Mat2 A;
  A << std::cos(phi), -std::sin(phi), std::sin(phi), std::cos(phi);
  return A;
}

}  // namespace fmbd::m01
