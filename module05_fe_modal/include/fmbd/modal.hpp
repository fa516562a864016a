#pragma once
// Modal analysis and static solution of a (supported) FE model (module 5, task T5).
//
// Free vibration u = phi sin(omega t) of M u_ddot + K u = 0 gives the generalised symmetric
// eigenproblem K phi = omega^2 M phi, with M positive definite and K positive semi-definite.

#include <stdexcept>
#include <string>

#include "fmbd/fe_assembly.hpp"
#include "fmbd/supports.hpp"

namespace fmbd {

/// The lowest modes of an FE model.
struct Modes {
  VecX omega;      ///< angular frequencies omega_i [rad/s], ascending; rigid-body modes give 0
  MatX shapes;     ///< mode shapes phi_i as columns (n x count), mass-normalised: phi_i^T M phi_j = delta_ij
  VecX hertz() const { return omega / (2.0 * 3.14159265358979323846); }  ///< f_i = omega_i / (2 pi) [Hz]
};

/// M05T5. The `count` lowest modes of K phi = omega^2 M phi (K, M: n x n symmetric, M positive
/// definite; 1 <= count <= n), by a symmetric generalised eigensolver, never by inverting M.
/// omega_i = sqrt(lambda_i), with round-off negatives of the zero eigenvalues of rigid-body modes
/// clamped to 0. The sign of each shape is not specified. A free-free planar body has three zero
/// modes (two translations and a rotation). Throws std::invalid_argument for sizes that do not
/// match, a count out of range, a matrix that is not symmetric or not finite, or an M that is not
/// positive definite, and std::runtime_error if the eigensolver does not converge.
Modes modal_analysis(const MatX& K, const MatX& M, int count);

/// The supports leave the structure free to move without strain, so K_ff is singular.
class SingularStiffness : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Static solution of K u = F (given code). F_full are nodal loads (F_x, F_y, moment) in the full
/// DOF order (size 3 N); the result is the full displacement vector u with zeros at the supports.
/// Solves K_ff u_f = F_f by Cholesky. Throws SingularStiffness if the supports leave rigid-body
/// motions free; the message names them (for example "translation x, rotation about (0, 0)").
VecX static_solve(const FeModel& fe, const FeMatrices& matrices, const DofMap& map, const VecX& F_full);

}  // namespace fmbd
