#pragma once
// Model order reduction of one flexible body (module 6), reduction (5) of the course:
//
//   u = Phi_f q_f;   a whole basis:   u = Phi q,   M_bar = Phi^T M_FE Phi,   K_bar = Phi^T K_FE Phi,
//
// u the nodal DOFs of the FE model (size n = 3 N, fe_model.hpp), q the coordinates of the basis
// Phi (size() of them, far fewer than n). In an FFRF basis Phi = [Phi_r, Phi_f], q = (q_r, q_f):
// the three rigid coordinates, then the flexible ones. Every basis here keeps its matrices
// together in a ReducedBasis.
//
// This header includes every header of the module: reduced_basis.hpp (the ReducedBasis),
// rigid_body_modes.hpp (T1), modal_truncation.hpp (T2) and craig_bampton.hpp (T3, T4 and their
// given helpers).

#include "fmbd/craig_bampton.hpp"
#include "fmbd/modal_truncation.hpp"
#include "fmbd/reduced_basis.hpp"
#include "fmbd/rigid_body_modes.hpp"
