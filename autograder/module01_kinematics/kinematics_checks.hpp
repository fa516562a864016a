#pragma once
// Shared helpers of the module-1 graded tests: finite-difference oracles for one
// ConstraintBlock and for a whole model, closed-form configurations, and the hints that
// name the likely mistake (the mistake catalogue's `expect:` phrases live in the words of these
// hints, never in their formulas, which a student sees only at the ladder's last level).
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
// A Hint prints its text after "hint: ": the student's quantity that is wrong and the likely
// mistake, in words; its formula only once the student has opened the task's last hint level
// (testing::with_formula, hint_gate.hpp), else a pointer to ./workbook hint. Nearly every formula of
// the module goes through rotation(): while rotation() is not A(phi), a wrong A makes correct code
// fail as well, so such a hint first sends the student to the rotation tests (rotation_is_right).
// The hints of the rotation tests themselves and of the rank, which does not use A, do not.
struct Hint {
  const char* text;
  const char* formula = "";
  bool builds_on_rotation = true;
};
std::ostream& operator<<(std::ostream& out, const Hint& hint);
/// Whether rotation() gives A(phi) = [[cos, -sin], [sin, cos]] (false while it throws).
bool rotation_is_right();
namespace hint {
// T1
inline constexpr Hint rotation_orthonormal{"your A(phi) is not a rotation: its columns must be unit vectors at right angles, "
    "det A = +1", "A = [[cos, -sin], [sin, cos]]", false};
inline constexpr Hint rotation_group{"your A(a) A(b) differs from A(a + b): are sin and cos of the same angle?", "", false};
inline constexpr Hint rotation_transposed{"your A(pi/2) does not turn (1, 0) into (0, 1): is A transposed (sign of sin "
    "swapped)?", "", false};
inline constexpr Hint rotation_derivative{"your dA/dphi differs from finite differences of your A: differentiate each entry "
    "of A", "dA/dphi = A I~ = [[-sin, -cos], [cos, -sin]]"};
inline constexpr Hint point_position{"your r_P is off: did you add R_i and turn s_bar by A(phi_i)?",
    "r_P = R_i + A(phi_i) s_bar"};
inline constexpr Hint jacobian_translation{"the x and y columns of your dr_P/dq_i are wrong: r_P moves one to one with R_i",
    "those columns are I_2"};
inline constexpr Hint jacobian_rotation{"the phi column of your dr_P/dq_i: did you use A where A*I~ belongs? It is the "
    "derivative of A s_bar, not A s_bar", "d(A s_bar)/dphi = A I~ s_bar"};
// T2
inline constexpr Hint revolute_closed{"your revolute C does not vanish where the two joint points coincide: C is the "
    "difference of the two points in global coordinates", "C = R_i + A_i s_i - R_j - A_j s_j"};
inline constexpr Hint revolute_gap{"your revolute C has the wrong sign: moving body j by delta must change C by -delta; "
    "are the points swapped?", "C = r_Pi - r_Pj"};
inline constexpr Hint revolute_Cq_i_translation{"the x and y columns of your C_q_i are wrong: C grows one to one with R_i",
    "those columns are +I_2"};
inline constexpr Hint revolute_Cq_j_translation{"did you forget the minus sign of body j? Your C_q_j must carry the sign "
    "that r_Pj carries in C", "C_q_j = -dr_Pj/dq_j"};
inline constexpr Hint revolute_Cq_phi{"did you use A where A*I~ belongs? The phi column of your C_q is the derivative of "
    "A s with respect to phi, with the sign of its point in C", "+-A I~ s (minus for body j)"};
inline constexpr Hint joint_Ct{"your joint's C_t is not zero: a joint does not depend on time (start from "
    "ConstraintBlock::zero)", ""};
// T3
inline constexpr Hint translational_on_line{"your translational C_1 does not vanish when P_j is on the sliding line: it is "
    "the offset of P_j from the line along its normal n_i", "C_1 = n_i^T (r_Pj - r_Pi), n_i = A_i I~ axis"};
inline constexpr Hint translational_offset{"your translational C_1 does not grow by +delta when P_j moves by delta along "
    "the normal n_i: check n_i and the direction of d", "n_i = A_i I~ axis, d = r_Pj - r_Pi"};
inline constexpr Hint angle_row{"your angle row: did you write phi_i - phi_j or drop phi0?", "C = phi_j - phi_i - phi0"};
inline constexpr Hint translational_Cq_translation{"the x and y columns of your translational C_q are wrong: check the "
    "normal n_i and the direction of d", "dC_1/dR_i = -n_i^T, dC_1/dR_j = +n_i^T"};
inline constexpr Hint translational_Cq_phi_i{"did you forget that the normal n_i turns with body i? Your dC_1/dphi_i "
    "has a term from d and one from n_i", "dC_1/dphi_i = -(A_i axis)^T d - n_i^T A_i I~ s_i"};
inline constexpr Hint translational_Cq_phi_j{"your dC_1/dphi_j: did you use A where A*I~ belongs?",
    "dC_1/dphi_j = n_i^T A_j I~ s_j"};
inline constexpr Hint angle_row_Cq{"the angle row of your C_q disagrees with finite differences of your own C: check the "
    "sign of C as well as C_q", "C = phi_j - phi_i - phi0: -1 in column phi_i, +1 in column phi_j"};
// T4
inline constexpr Hint fixed_closed{"your fixed joint's C does not vanish on a welded pair: rows 1-2 are the revolute "
    "rows, row 3 the angle row", "rows 1-2 r_Pi - r_Pj, row 3 phi_j - phi_i - phi0"};
// T5
inline constexpr Hint driver_Ct{"is C_t missing or its sign flipped? Your driver's C_t must be the time derivative of "
    "its C", "for C = (quantity) - f(t), C_t = -f'(t)"};
inline constexpr Hint driver_C{"your driver's C is off: it is the measured quantity minus f(t); check the quantity and "
    "the sign of f", ""};
inline constexpr Hint absolute_Cq{"your absolute-angle driver's C_q_i is wrong: C depends on phi_i only",
    "C_q_i = [0, 0, 1]"};
inline constexpr Hint relative_Cq{"your relative-angle driver's C_q is wrong: C grows with phi_j and falls with phi_i",
    "C_q_i = [0, 0, -1], C_q_j = [0, 0, +1]"};
inline constexpr Hint coordinate_Cq{"your point-coordinate driver's C_q_i is wrong: it is row k of dr_P/dq_i (k = 0 "
    "for x, 1 for y); did you use A where A*I~ belongs?", "dr_P/dq_i = [I_2 | A I~ s]"};
inline constexpr Hint distance_Cq{"your distance driver's C_q: check the factor 1/2 and the sign of body i",
    "C_q_i = -d^T dr_Pi/dq_i, C_q_j = +d^T dr_Pj/dq_j"};
inline constexpr Hint distance_C{"your distance driver's C is off: half the difference of the squared distance and f^2",
    "C = 1/2 (d^T d - f^2), d = r_Pj - r_Pi"};
inline constexpr Hint distance_Ct{"your distance driver's C_t: is the factor f missing? Use the chain rule on the f(t) "
    "term", "C_t = -f f'"};
// T6
inline constexpr Hint assembly_rows{"your assembled C or C_t differs in a constraint's rows: does each constraint fill its "
    "own rows first_row .. first_row + rows - 1, and every one of them?"};
inline constexpr Hint assembly_Cq_rows{"a constraint's rows of your C_q are empty: are its blocks placed at its own rows, "
    "from first_row?"};
inline constexpr Hint assembly_columns{"a block of your C_q is not in its own body's columns: body i's block goes to the 3 "
    "columns of body i (from its marker's offset), body j's to body j's"};
inline constexpr Hint assembly_ground{"the ground has no columns: your C_q adds the ground's block to the first body's "
    "columns; drop it instead"};
inline constexpr Hint assembly_twice{"an entry of your C_q is twice the right one: is a block added twice?"};
inline constexpr Hint assembly_sign{"a block of your C_q has the wrong sign: add each block as its kernel returns it"};
inline constexpr Hint assembly_stale{"your assembly kept entries of an earlier call: out holds old values, so clear C_q "
    "before adding the blocks and set every row of C and C_t"};
inline constexpr Hint assembly_consistent{"your C_q differs from finite differences of your own assembled C: are the rows "
    "of C and of C_q placed alike?"};
// T7
inline constexpr Hint rank_relative{"your rank's threshold must be relative to the largest singular value, not absolute",
    "count sigma_k > rank_tolerance * sigma_max", false};
inline constexpr Hint rank_empty{"your rank of an empty matrix (no constraints) is not 0", "", false};
inline constexpr Hint rank_value{"your jacobian_rank miscounts: count the singular values above a threshold relative to "
    "the largest", "sigma_k > rank_tolerance * sigma_max", false};
inline constexpr Hint dof_rank{"your DOF must subtract the rank of C_q, not the number of rows: redundant rows remove "
    "no freedom; a wrong C_q also changes the rank, so fix failing joint tests first", "DOF = n - rank C_q"};
inline constexpr Hint dof_coordinates{"your DOF counts the coordinates wrong: 3 per rigid body but 3 + n_f for a flexible "
    "body (model.num_coordinates())", "DOF = n - rank C_q, n = model.num_coordinates()"};
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
