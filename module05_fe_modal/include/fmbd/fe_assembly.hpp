#pragma once
// Assembly of the global FE matrices (module 5, task T3). Model (4) of the course:
//
//   M_FE u_ddot + K_FE u = F          u: nodal DOFs of fe_model.hpp, size 3 N.

#include "fmbd/beam_element.hpp"

namespace fmbd {

/// Mass and stiffness matrices of a whole FE model (3N x 3N, symmetric).
struct FeMatrices {
  MatX M;  ///< M_FE, positive definite
  MatX K;  ///< K_FE, positive semi-definite; its null space holds the rigid-body motions
};

/// M05T3. Assembles M_FE and K_FE: for every element e from node a to node b, the global element
/// matrices T^T k_e T and T^T m_e T (beam_transformation of the element angle) are added to the
/// rows and columns (3a .. 3a+2, 3b .. 3b+2). Throws ModelError (FeModel::validate) for a model
/// without elements or with a node that belongs to no element.
FeMatrices assemble(const FeModel& fe, MassMatrixType type);

}  // namespace fmbd
