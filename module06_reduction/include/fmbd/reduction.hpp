#pragma once
// Model order reduction of one flexible body (module 6), reduction (5) of the course:
//
//   u = Phi p,     M_bar = Phi^T M_FE Phi,     K_bar = Phi^T K_FE Phi,
//
// u the nodal DOFs of the FE model (size n = 3 N, fe_model.hpp), p the reduced coordinates
// (size m << n). Every basis here keeps its matrices together in a ReducedBasis.
//
// This header includes every header of the module: reduced_basis.hpp (the ReducedBasis),
// rigid_body_modes.hpp (T1), modal_truncation.hpp (T2) and craig_bampton.hpp (T3, T4 and their
// given helpers).

#include "fmbd/craig_bampton.hpp"
#include "fmbd/modal_truncation.hpp"
#include "fmbd/reduced_basis.hpp"
#include "fmbd/rigid_body_modes.hpp"
