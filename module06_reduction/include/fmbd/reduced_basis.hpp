#pragma once
// Model order reduction of one flexible body (module 6), reduction (5) of the course:
//
//   u = Phi p,     M_bar = Phi^T M_FE Phi,     K_bar = Phi^T K_FE Phi,
//
// u the nodal DOFs of the FE model (size n = 3 N, fe_model.hpp), p the reduced coordinates
// (size m << n). Every basis here keeps its matrices together in a ReducedBasis.

#include "fmbd/modal.hpp"

namespace fmbd {

/// A reduction basis with its reduced matrices.
struct ReducedBasis {
  MatX Phi;           ///< n x m basis, columns are displacement fields of the FE model
  MatX M_bar;         ///< Phi^T M Phi (m x m)
  MatX K_bar;         ///< Phi^T K Phi (m x m)
  int num_rigid = 0;  ///< leading columns that are the rigid-body modes Phi_r (3 in an FFRF basis, else 0)
  int size() const { return static_cast<int>(Phi.cols()); }
  int num_elastic() const { return size() - num_rigid; }
};

}  // namespace fmbd
