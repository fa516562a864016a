#pragma once
// Shared helpers of the module-1 graded tests: finite-difference oracles for one
// ConstraintBlock and for a whole model, closed-form configurations, and the hints that
// name the likely mistake (the mistake catalogue's `expect:` phrases live in these hints;
// keep each phrase within the first ~100 characters of its hint: Catch wraps long lines).
//
// The functions are defined in kinematics_checks.cpp, compiled once and linked into every
// graded program of the module.

#include <functional>
#include <ostream>
#include <sstream>
#include <string>

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
// A Hint prints its text after "hint: ". Nearly every formula of the module goes through
// rotation(): while rotation() is not A(phi), a wrong A makes correct code fail as well, so such
// a hint first sends the student to the rotation tests (rotation_is_right). The hints of the
// rotation tests themselves and of the rank, which does not use A, do not.
struct Hint {
  const char* text;
  bool builds_on_rotation = true;
};
std::ostream& operator<<(std::ostream& out, const Hint& hint);
/// Whether rotation() gives A(phi) = [[cos, -sin], [sin, cos]] (false while it throws).
bool rotation_is_right();
namespace hint {
// T1
inline constexpr Hint rotation_orthonormal{"A(phi) must be orthonormal with det +1: A = [[cos, -sin], [sin, cos]]", false};
inline constexpr Hint rotation_group{"A(a) A(b) must equal A(a + b): are sin and cos of the same angle?", false};
inline constexpr Hint rotation_transposed{"A(pi/2) must turn (1, 0) into (0, 1): is A transposed (sign of sin swapped)?", false};
inline constexpr Hint rotation_derivative{"dA/dphi differs from finite differences of A: it is A I~ = [[-sin, -cos], [cos, -sin]]"};
inline constexpr Hint point_position{"r_P = R_i + A(phi_i) s_bar: did you add R_i and rotate s_bar by A?"};
inline constexpr Hint jacobian_translation{"the x and y columns of dr_P/dq_i are I_2: r_P moves one to one with R_i"};
inline constexpr Hint jacobian_rotation{"did you use A where A*I~ belongs? The phi column is d(A s)/dphi = A I~ s, not A s"};
// T2
inline constexpr Hint revolute_closed{"C = R_i + A_i s_i - R_j - A_j s_j must vanish when the two points coincide"};
inline constexpr Hint revolute_gap{"C = r_Pi - r_Pj: moving body j by delta must give C = -delta; are the points swapped?"};
inline constexpr Hint revolute_Cq_i_translation{"C_q_i columns x, y must be +I_2 because C = r_Pi - r_Pj"};
inline constexpr Hint revolute_Cq_j_translation{"did you forget the minus sign of body j? C = r_Pi - r_Pj, so C_q_j = -dr_Pj/dq_j"};
inline constexpr Hint revolute_Cq_phi{"did you use A where A*I~ belongs? C_q column phi is +-A I~ s (minus for body j)"};
inline constexpr Hint joint_Ct{"a joint does not depend on time: C_t must be zero (start from ConstraintBlock::zero)"};
// T3
inline constexpr Hint translational_on_line{"C_1 = n_i^T (r_Pj - r_Pi) with n_i = A_i I~ axis must vanish when P_j is on the sliding line"};
inline constexpr Hint translational_offset{"moving P_j by delta along n_i = A_i I~ axis must give C_1 = +delta: check n_i and d = r_Pj - r_Pi"};
inline constexpr Hint angle_row{"angle row: C = phi_j - phi_i - phi0; did you write phi_i - phi_j or drop phi0?"};
inline constexpr Hint translational_Cq_translation{"dC_1/dR_i = -n_i^T and dC_1/dR_j = +n_i^T: check n_i = A_i I~ axis and d = r_Pj - r_Pi"};
inline constexpr Hint translational_Cq_phi_i{"did you forget that the normal n_i turns with body i? dC_1/dphi_i = -(A_i axis)^T d - n_i^T A_i I~ s_i"};
inline constexpr Hint translational_Cq_phi_j{"dC_1/dphi_j = n_i^T A_j I~ s_j: did you use A where A*I~ belongs?"};
inline constexpr Hint angle_row_Cq{"the angle row of C_q disagrees with finite differences of your own C: C = phi_j - phi_i - phi0 has "
    "-1 in column phi_i and +1 in column phi_j; check the sign of C as well as C_q"};
// T4
inline constexpr Hint fixed_closed{"fixed joint: rows 1-2 are the revolute rows r_Pi - r_Pj, row 3 is phi_j - phi_i - phi0"};
// T5
inline constexpr Hint driver_Ct{"is C_t missing or its sign flipped? For C = (quantity) - f(t), C_t = -f'(t)"};
inline constexpr Hint driver_C{"a driver reads C = (measured quantity) - f(t): check the quantity and the sign of f"};
inline constexpr Hint absolute_Cq{"absolute-angle driver: C = phi_i - f(t), so C_q_i = [0, 0, 1]"};
inline constexpr Hint relative_Cq{"relative-angle driver: C_q_i = [0, 0, -1] and C_q_j = [0, 0, +1]"};
inline constexpr Hint coordinate_Cq{"point-coordinate driver: C_q_i is row k of dr_P/dq_i (k = 0 for x, 1 for y); A I~ s, not A s"};
inline constexpr Hint distance_Cq{"check the factor 1/2 and the sign of body i: C_q_i = -d^T dr_Pi/dq_i, C_q_j = +d^T dr_Pj/dq_j"};
inline constexpr Hint distance_C{"distance driver: C = 1/2 (d^T d - f^2) with d = r_Pj - r_Pi"};
inline constexpr Hint distance_Ct{"distance driver: C_t = -f f' (chain rule on -f(t)^2 / 2); is the factor f missing?"};
// T6
inline constexpr Hint assembly_rows{"your assembled C or C_t differs in a constraint's rows: does each constraint fill its own rows "
    "first_row .. first_row + rows - 1, and every one of them?"};
inline constexpr Hint assembly_Cq_rows{"a constraint's rows of your C_q are empty: are its blocks placed at its own rows, from "
    "first_row?"};
inline constexpr Hint assembly_columns{"a block of your C_q is not in its own body's columns: body i's block goes to the 3 columns of "
    "body i (from its marker's offset), body j's to body j's"};
inline constexpr Hint assembly_ground{"the ground has no columns: your C_q adds the ground's block to the first body's columns; drop "
    "it instead"};
inline constexpr Hint assembly_twice{"an entry of your C_q is twice the right one: is a block added twice?"};
inline constexpr Hint assembly_sign{"a block of your C_q has the wrong sign: add each block as its kernel returns it"};
inline constexpr Hint assembly_stale{"your assembly kept entries of an earlier call: out holds old values, so clear C_q before "
    "adding the blocks and set every row of C and C_t"};
inline constexpr Hint assembly_consistent{"your C_q differs from finite differences of your own assembled C: are the rows of C "
    "and of C_q placed alike?"};
// T7
inline constexpr Hint rank_relative{"the threshold is relative to the largest singular value: count sigma_k > rank_tolerance * sigma_max", false};
inline constexpr Hint rank_empty{"the rank of an empty matrix (no constraints) is 0", false};
inline constexpr Hint rank_value{"jacobian_rank: count the singular values above rank_tolerance * sigma_max", false};
inline constexpr Hint dof_rank{"DOF = n - rank C_q, not the number of rows (redundant rows remove no freedom); a wrong C_q also "
    "changes the rank, so fix failing joint tests first"};
inline constexpr Hint dof_coordinates{"DOF = n - rank C_q with n = model.num_coordinates(): 3 per rigid body, but 3 + n_f for a flexible body"};
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
BlockDifferences block_differences(const BlockOfQ& block, const Vec3& q_i, const Vec3& q_j);

/// Central difference in time of C(t) = block(f(t)).C (h = 1e-5).
VecX time_difference(const std::function<ConstraintBlock(const DriveValue&)>& block, const DriveFunction& f,
                     double t);

// ---- whole model ---------------------------------------------------------------------------

/// C, C_q and C_t of a rigid-body model stacked by the test from the kernels' blocks
/// (evaluate_constraint of each constraint): the kernel tasks T1-T5 are checked through it, so that
/// they need not the student's assembly (T6), and it is T6's oracle.
ConstraintEvaluation kernel_evaluation(const Model& model, const VecX& q, double t);

/// Checks the kernels' C_q and C_t in `model` at (q, t) against central differences of their C,
/// constraint by constraint and column group by column group (x-y or phi of each body), with the
/// hint of the first row that differs. Returns false if any differs.
bool check_model_derivatives(const Model& model, const VecX& q, double t);

/// Checks the kernels' C(q, t) = 0 constraint by constraint, with the constraint's hint.
bool check_model_closes(const Model& model, const VecX& q, double t, Tolerance tol = kGeometry);

/// Checks the student's assembly (M01T6) into `out`, whatever it held, against the kernels'
/// blocks stacked by the test (kernel_evaluation) and its C_q and C_t against central differences
/// of the student's own assembled C, naming the likely mistake (a row or column offset, the
/// ground's columns, a block added twice or with its sign flipped, entries of an earlier call).
/// `label` says which model and state. Returns false if anything differs.
bool check_assembly(const Model& model, const VecX& q, double t, ConstraintEvaluation& out, const std::string& label);

/// A rigid-body model with every constraint type, three bodies and the ground on both sides of a
/// joint, that is attached to body 0 by none of its ground joints: the assembly tests' model.
Model assembly_model();

// ---- closed-form configurations ------------------------------------------------------------

/// Coordinates (9) of the four-bar at crank angle theta on the open branch, from the closed-form
/// position of joint C; the crank angle is theta itself (not wrapped), as its driver prescribes.
/// The links have their centroids at mid-length and their body x axes from end to end (the
/// convention of examples_given.cpp).
VecX four_bar_configuration(const examples::FourBarParameters& p, double theta);

/// Body coordinates that put the body-fixed point s_bar at the global position r with angle phi.
Vec3 place(const Vec2& r, const Vec2& s_bar, double phi);

/// Independent A(phi) (no student code) for building geometry.
Mat2 rot(double phi);

}  // namespace fmbd::m01
