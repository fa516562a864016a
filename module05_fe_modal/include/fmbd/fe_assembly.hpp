#pragma once
// Assembly of the global FE matrices (module 5, task T3). Model (4) of the course:
//
//   M_FE u_ddot + K_FE u = F          u: nodal DOFs of fe_model.hpp, size 3 N.

#include <Eigen/SparseCore>

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

/// A sparse matrix: column-major, int indices.
using SparseMat = Eigen::SparseMatrix<double>;

/// M_FE and K_FE as sparse matrices (3N x 3N). Each element couples only its two nodes, so both
/// are banded: a product with a 3N-vector costs O(N), not O(N^2). A flexible body keeps its
/// matrices so (module 8's nodal products), and the sparse extra assembles them so directly.
struct SparseFeMatrices {
  SparseMat M;  ///< M_FE, positive definite
  SparseMat K;  ///< K_FE, positive semi-definite
};

/// The same matrices without their entries that are exactly zero.
inline SparseFeMatrices to_sparse(const FeMatrices& matrices) {
  return {matrices.M.sparseView(), matrices.K.sparseView()};
}

}  // namespace fmbd
