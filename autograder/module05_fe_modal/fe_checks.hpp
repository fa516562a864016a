#pragma once
// Shared helpers of the module 5 graded tests: element matrices integrated from the shape
// functions by Gauss quadrature, exact displacement fields and their energies, the matrices of a
// straight beam built as a chain in its own axes, the rigid motions of a frame, the
// Euler-Bernoulli frequency tables, random frames and sections, and hints that name the likely
// mistake (the mistake catalogue's `expect:` phrases open these hints; Catch wraps long lines, so
// each phrase stays within the first ~100 characters of its hint). The oracles that restate
// an exercise (a general assembly, the free list of any supports) are hidden, in
// hidden/fe_oracles.hpp. What stays here of T4 is its definition as index arithmetic
// (rows_cols, expand_by_hand: A_ff(r, c) = A(free[r], free[c]), u(free[r]) = u_free(r)), which
// the visible tests check entry by entry.
//
// Every oracle here is independent of the student's module 5 code: the element matrices come from
// integrals of the shape functions (not from the closed-form matrices of the exercise), the
// element axes from the node coordinates, the eigenvalues for hints and for the T1-T4 tests from
// Eigen's own generalised eigensolver, and the expected frequencies from published tables and
// closed forms. Given code (FeModel, straight_beam, square_section, static_solve) is used to build
// and solve models.
//
// The definitions are in fe_checks.cpp, compiled once for all the module's test files.

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "fmbd/beam_element.hpp"
#include "fmbd/fe_assembly.hpp"
#include "fmbd/fe_model.hpp"
#include "fmbd/modal.hpp"
#include "fmbd/supports.hpp"
#include "grading.hpp"

namespace fmbd::testing::m05 {

inline constexpr double kPi = 3.14159265358979323846;

// ---- small helpers ------------------------------------------------------------------------

inline VecX as_vec(const std::vector<int>& v) {
  VecX out(static_cast<Eigen::Index>(v.size()));
  for (std::size_t k = 0; k < v.size(); ++k) out(static_cast<Eigen::Index>(k)) = v[k];
  return out;
}
inline Vec2 perp(const Vec2& v) { return Vec2(-v.y(), v.x()); }
inline double max_abs(const MatX& A) { return A.size() == 0 ? 0.0 : A.cwiseAbs().maxCoeff(); }

/// Entrywise tolerance relative to the largest entry of `scale_of` (round-off of sums of large
/// terms that cancel) plus a relative part.
inline Tolerance scaled(const MatX& scale_of, double rel) { return Tolerance{rel * max_abs(scale_of), rel}; }

/// A random section with independent A and I (so that EA and EI cannot be confused).
Section random_section(Random& rnd);
/// A random slender square section for frequency tests: side / length below 1/40, so that the
/// lowest modes are bending modes.
Section random_slender_section(Random& rnd, double length);

// ---- shape functions and Gauss quadrature ---------------------------------------------------

using Vec6 = Eigen::Matrix<double, 6, 1>;

/// k_e = integral of EA B_u^T B_u + EI B_v^T B_v dx.
Mat6 stiffness_by_quadrature(const Section& s, double L);
/// HRZ lumping: the diagonal of the consistent matrix, scaled per displacement field (u, and v
/// with its rotations) so that each field carries the element mass.
Mat6 hrz_lumped_mass(const Section& s, double L);
Mat6 mass_by_quadrature(const Section& s, double L, MassMatrixType type);

// ---- exact fields and their energies ------------------------------------------------------

/// u(x) = a0 + a1 x, v(x) = b0 + b1 x + b2 x^2 + b3 x^3: a field the element reproduces exactly.
struct Field {
  double a0 = 0, a1 = 0, b0 = 0, b1 = 0, b2 = 0, b3 = 0;
  double u(double x) const { return a0 + a1 * x; }
  double du(double) const { return a1; }
  double v(double x) const { return b0 + x * (b1 + x * (b2 + x * b3)); }
  double dv(double x) const { return b1 + x * (2 * b2 + 3 * x * b3); }
  double ddv(double x) const { return 2 * b2 + 6 * b3 * x; }
  /// Nodal values (u_a, v_a, psi_a, u_b, v_b, psi_b), psi = v'.
  Vec6 nodal(double L) const {
    Vec6 q;
    q << u(0), v(0), dv(0), u(L), v(L), dv(L);
    return q;
  }
};
/// Random field with coefficients scaled so that every term is of order `size` over the element.
Field random_field(Random& rnd, double L, double size = 1e-3, bool axial = true, bool bending = true);
/// Bilinear strain energy form: integral of EA u1' u2' + EI v1'' v2'' (U = half of it for f1 = f2).
double strain_product(const Section& s, double L, const Field& f1, const Field& f2);
/// Bilinear kinetic energy form of velocity fields: integral of rho A (u1 u2 + v1 v2).
double inertia_product(const Section& s, double L, const Field& f1, const Field& f2);

// ---- element hints: which slip of the closed-form matrices reproduces the answer -------------
/// The element's rotation, behind the hint gate (with_formula): shown at the last hint level only.
inline constexpr const char* kTransformationFormula =
    "R = [[c, s, 0], [-s, c, 0], [0, 0, 1]] per node, T = blockdiag(R, R), c = cos(alpha), s = sin(alpha)";

/// The likely mistake behind a wrong beam_stiffness, from its matrix.
std::string stiffness_hint(const Mat6& actual, const Section& s, double L);

/// The likely mistake behind a wrong beam_mass, from its matrix.
std::string mass_hint(const Mat6& actual, const Section& s, double L, MassMatrixType type);

// ---- geometry: element axes, rigid motions, frames -------------------------------------------

/// T (6x6) with u_local = T u_global for an element with axis e = (x_b - x_a)/L: R on each node,
/// local axial = e . u, local transverse = n . u with n = perp(e), psi unchanged.
Mat6 element_rotation(const Vec2& e);
/// The unit axis (x_b - x_a)/L of element e.
Vec2 axis_of(const FeModel& fe, int e);

/// Rigid motions of the model's nodes as columns (3N x 3): translation x, translation y, and the
/// rotation about `centre` (node k moves by perp(x_k - centre) and turns by 1).
MatX rigid_motions(const FeModel& fe, const Vec2& centre = Vec2::Zero());

/// "beam_stiffness is wrong (fix the T1 tests first). " and the like when the student's element
/// functions (beam_stiffness, beam_mass, beam_transformation) disagree with the quadrature matrices
/// and the element axes on the elements of `fe`; empty when they agree.
std::string element_upstream_hint(const FeModel& fe, MassMatrixType type);

/// The hint of a visible assembly check: the upstream hint if an element function is wrong, else
/// the rule of the assembly. (The hidden tests name the slip itself: hidden/fe_oracles.hpp.)
std::string assembly_rule_hint(const FeModel& fe, MassMatrixType type);

/// An L-shaped frame: a column from `base` up by h, then a beam along x by w (the whole frame
/// tilted a little), `per_member` elements each; nodes numbered in a scrambled order (so that node b
/// is not node a + 1). *foot receives the node number of the column's foot.
FeModel l_frame(Random& rnd, int per_member, const Section& column, const Section& beam, int* foot = nullptr);

/// A triangle with random corners (angles above ~20 degrees), `per_member` elements per side,
/// elements oriented in both directions; nodes in a scrambled order.
FeModel triangle_frame(Random& rnd, int per_member, const Section& s);

// ---- supports and eigenvalues, written out ----------------------------------------------------

/// A(idx, idx): the rows and columns idx of A (Eigen's indexing).
MatX rows_cols(const MatX& A, const std::vector<int>& idx);

/// "node 0 clamped, node 2 hinged" for CAPTURE.
std::string describe(const std::vector<NodeSupport>& supports);

/// A DofMap of `num_nodes` nodes with a random set of fixed DOFs, at least one free and never the
/// first ones only (DOF n % 3 of node 0 is always fixed).
DofMap random_map(Random& rnd, int num_nodes);

VecX expand_by_hand(const VecX& u_free, const DofMap& map);

std::string reduce_matrix_hint(const MatX& A, const DofMap& map, const MatX& actual);
std::string reduce_vector_hint(const VecX& F, const DofMap& map, const VecX& actual);
std::string expand_hint(const VecX& u_free, const DofMap& map, const VecX& actual);

/// All eigenvalues lambda of K phi = lambda M phi, ascending (Eigen's generalised solver).
VecX eigenvalues_by_hand(const MatX& K, const MatX& M);
VecX omegas_of(const VecX& lambda);

/// The likely mistake behind wrong frequencies of modal_analysis(K, M, count).
std::string omega_hint(const VecX& actual, const MatX& K, const MatX& M, int count);

/// The likely mistake behind wrongly scaled shapes.
std::string shapes_hint(const MatX& shapes, const MatX& M);

// ---- Euler-Bernoulli beams: tables and models ---------------------------------------------------

/// End conditions of a single-span beam (first end at node 0, second at the last node).
enum class Ends { clamped_free, pinned_pinned, free_free, clamped_clamped, clamped_pinned };

/// beta_i L of the first four bending modes of a uniform slender Euler-Bernoulli beam, from
/// R. D. Blevins, Formulas for Natural Frequency and Mode Shape (Van Nostrand Reinhold, 1979;
/// Krieger reprint 2001), table 8-1 ("lambda_i"): omega_i = (beta_i L)^2 / L^2 sqrt(E I / (rho A)).
/// Free-free lists the elastic modes only (the beam also has rigid-body modes at zero).
std::array<double, 4> beta_L(Ends e);
double bending_omega(double betaL, const Section& s, double L);

/// A beam model with its supported matrices, all built here (the student's code is not used): the
/// quadrature element matrices of consecutive elements overlap in a chain along the beam's own
/// axis, the chain is turned by `angle` as a whole (K = R^T K_axis R, R the node rotation on every
/// node), and the supported DOFs of the ends are removed.
struct BeamProblem {
  FeModel fe;
  Section section;
  double L = 0, angle = 0;
  std::vector<int> free;
  MatX K, M;  ///< K_ff, M_ff
};
BeamProblem beam_problem(double L, double angle, const Section& s, int elements, Ends ends, MassMatrixType type,
                         const Vec2& start = Vec2::Zero());

}  // namespace fmbd::testing::m05
