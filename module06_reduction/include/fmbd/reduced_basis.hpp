#pragma once
// Model order reduction of one flexible body (module 6), reduction (5) of the course:
//
//   u = Phi_f q_f;   a whole basis:   u = Phi q,   M_bar = Phi^T M_FE Phi,   K_bar = Phi^T K_FE Phi,
//
// u the nodal DOFs of the FE model (size n = 3 N, fe_model.hpp), q the coordinates of the basis
// Phi (size() of them, far fewer than n). In an FFRF basis Phi = [Phi_r, Phi_f], q = (q_r, q_f):
// the three rigid coordinates, then the flexible ones. Every basis here keeps its matrices
// together in a ReducedBasis.

#include "fmbd/modal.hpp"

namespace fmbd {

/// A reduction basis with its reduced matrices.
struct ReducedBasis {
  MatX Phi;           ///< n x size() basis, columns are displacement fields of the FE model
  MatX M_bar;         ///< Phi^T M Phi (size() x size())
  MatX K_bar;         ///< Phi^T K Phi (size() x size())
  int num_rigid = 0;  ///< leading columns that are the rigid-body modes Phi_r (3 in an FFRF basis, else 0)
  int size() const { return static_cast<int>(Phi.cols()); }
  int num_elastic() const { return size() - num_rigid; }
};

}  // namespace fmbd
