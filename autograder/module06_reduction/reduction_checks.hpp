#pragma once
// Shared helpers of the module 6 graded tests: frame builders, the rigid-body properties of a
// frame as closed-form integrals over its elements, the rigid-body columns about a given point,
// generalised eigenvalues by Eigen, Craig-Bampton constraint modes as static solutions, and
// hints that name the likely mistake. The mistake catalogue's `expect:` phrases open these
// hints (Catch wraps long lines, so each phrase stays at the start of its hint).
//
// Every oracle here is independent of the student's module 6 code: closed forms over the
// elements (mass rho A L, centroid, inertia of the consistent or HRZ lumped mass), Eigen's
// generalised symmetric eigensolver and Cholesky factorisations written out in
// reduction_checks.cpp, and the free-free Euler-Bernoulli frequencies of Blevins (table 8-1). The
// FE matrices come from the module 5 assembly (reference stages 1 to 5 under the graded module 6
// targets).
//
// The definitions are in reduction_checks.cpp, compiled once for all the module's test files.

#include <string>
#include <vector>

#include "fmbd/fe_assembly.hpp"
#include "fmbd/fe_model.hpp"
#include "fmbd/reduction.hpp"
#include "grading.hpp"

namespace fmbd::testing::m06 {

inline constexpr double kSteelE = 2.1e11;
inline constexpr double kSteelRho = 7850.0;

/// Free-free Euler-Bernoulli beam, beta_i L of the first elastic modes (Blevins, table 8-1).
inline constexpr double kFreeFreeBetaL[4] = {4.73004074, 7.85320462, 10.99560784, 14.13716549};

inline constexpr Tolerance kExact{1e-12, 1e-12};  ///< sums of a few products

// ---- small helpers ------------------------------------------------------------------------

inline MatX symmetric_part(const MatX& A) { return 0.5 * (A + A.transpose()); }

/// Largest absolute entry (0 for an empty matrix).
inline double max_abs(const MatX& A) { return A.size() == 0 ? 0.0 : A.cwiseAbs().maxCoeff(); }

/// A(rows, cols) for index lists.
MatX pick(const MatX& A, const std::vector<int>& rows, const std::vector<int>& cols);

/// 0 .. n-1 without the listed indices, ascending.
std::vector<int> complement(int n, const std::vector<int>& listed);

/// Rows and columns `first` .. n-1: the matrices of a model with its first node clamped.
inline MatX without_leading(const MatX& A, int first) {
  return A.bottomRightCorner(A.rows() - first, A.cols() - first);
}

// ---- frames -------------------------------------------------------------------------------

/// A steel square section of the given side.
inline Section steel(double side) { return square_section(kSteelE, kSteelRho, side); }

/// A random triangle frame: three corners, random sections and element counts per side.
FeModel random_triangle(Random& rnd);

/// The L-shaped frame of the tests: (0.4, 0.3) -> (2.4, 0.3) in 4 elements of a 40 mm steel
/// square, then up to (2.4, 1.8) in 3 elements of an aluminium 30 mm square.
FeModel l_frame();

// ---- rigid-body properties as integrals over the elements --------------------------------

struct RigidOracle {
  double mass = 0.0;
  Vec2 centroid = Vec2::Zero();
  double inertia = 0.0;  ///< about the centroid
};

/// m = sum rho A L_e; c = sum m_e x_mid / m. consistent mass: J = sum m_e (|x_mid - c|^2 + L_e^2 / 12),
/// the exact integral of rho A |x - c|^2 (the rigid field is linear along each element);
/// lumped (HRZ): m_e / 2 at both element nodes and a rotary m_e L_e^2 / 78 at both element ends.
RigidOracle rigid_oracle(const FeModel& fe, MassMatrixType type);

/// The n x 3 rigid-body columns about point p: node k gets (1, 0, 0), (0, 1, 0), (-(y_k - p_y), x_k - p_x, 1).
MatX rigid_columns(const FeModel& fe, const Vec2& p, double psi = 1.0);

/// Largest node distance from the origin, at least 1: the scale of the rigid columns.
double position_scale(const FeModel& fe);

// ---- hints for rigid_body_modes ----------------------------------------------------------

/// The likely mistake behind a wrong centroid, from the oracle `o`.
std::string centroid_hint(const Vec2& got, const RigidOracle& o);

/// The likely mistake behind a wrong inertia J about the centroid, from the oracle `o`.
std::string inertia_hint(double got, const RigidOracle& o);

/// The likely mistake behind wrong rigid-body columns Phi_r, from the oracle `o`.
std::string phi_r_hint(const FeModel& fe, const MatX& Phi_r, const RigidOracle& o);

/// Checks rigid_body_modes' result `rb` on `fe` against the oracle `o`: m, c, J about c and the
/// columns Phi_r, each with the hint above.
void check_rigid_body_modes(const FeModel& fe, const RigidBodyModes& rb, const RigidOracle& o);

// ---- eigenvalues --------------------------------------------------------------------------

/// Eigenvalues of K phi = lambda M phi, ascending (Eigen's generalised symmetric solver).
VecX eigenvalues(const MatX& K, const MatX& M);

/// sqrt of the eigenvalues, negatives (round-off) taken as 0.
VecX frequencies(const MatX& K, const MatX& M);

/// The lowest `count` modes of (K, M), mass-normalised, by Eigen.
MatX mode_shapes(const MatX& K, const MatX& M, int count);

/// omega_i = (beta_i L)^2 sqrt(E I / (rho A L^4)) of a uniform free-free beam.
VecX free_free_omegas(const Section& s, double L, int count);

/// Diagonal entries sqrt(max(0, K_bar_ii)) of the elastic part (from index `first`).
VecX diagonal_frequencies(const MatX& K_bar, int first);

// ---- Craig-Bampton oracles ----------------------------------------------------------------

/// Constraint modes by their definition: column r is the static displacement with a unit value
/// at interface[r], zero at the other interface DOFs and no load on the interior DOFs, i.e. the
/// interior part solves K_ii u_i = -K_ib e_r (Cholesky of the test). `sign` -1 gives the slip
/// K_ii u_i = +K_ib e_r.
MatX constraint_modes(const MatX& K, const std::vector<int>& interface, double sign = 1.0);

/// Hint for wrong constraint-mode columns (the first n_b columns of a Craig-Bampton basis).
std::string constraint_hint(const MatX& K, const std::vector<int>& interface, const MatX& columns);

/// A Craig-Bampton basis built here: the constraint modes above and the lowest `k` modes of
/// (K_ii, M_ii) by Eigen, zero on the interface rows. The input of the ffrf_basis tests, so that
/// they do not depend on the student's craig_bampton.
ReducedBasis craig_bampton_oracle(const MatX& K, const MatX& M, const std::vector<int>& interface, int k);

/// Squared M-norm of what is left of the columns of A after the M-orthogonal projection onto the
/// span of B, relative to the squared M-norm of A: 0 when span(A) lies in span(B).
double outside_span(const MatX& A, const MatX& B, const MatX& M);

}  // namespace fmbd::testing::m06
