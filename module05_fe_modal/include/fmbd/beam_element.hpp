#pragma once
// The planar Euler-Bernoulli frame element (module 5, tasks T1 to T3).
//
// Local element frame: x along the element from node a to node b, y turned +90 degrees.
// Local degrees of freedom, in this order:
//
//   u_e = (u_a, v_a, psi_a, u_b, v_b, psi_b)
//
// u axial and v transverse displacements, psi = dv/dx the section rotation. Axial motion uses
// linear shape functions, bending cubic Hermite ones; the two are uncoupled in the local frame.

#include <Eigen/Core>

#include "fmbd/fe_model.hpp"

namespace fmbd {

using Mat6 = Eigen::Matrix<double, 6, 6>;

/// M05T1. Local element stiffness matrix k_e (6x6, symmetric, the DOF order above) of an element
/// of length L: the matrix of the strain energy 1/2 int (EA u'^2 + EI v''^2) dx with the shape
/// functions above (README section 2). Axial and bending DOFs do not couple; the rigid motions
/// of the element are its null space.
Mat6 beam_stiffness(const Section& section, double L);

/// M05T2. Local element mass matrix m_e (6x6, symmetric, the DOF order above) of an element of
/// length L and mass m = rho A L (README section 2). consistent: the matrix of the kinetic energy
/// 1/2 int rho A (u_dot^2 + v_dot^2) dx with the shape functions above; lumped: diagonal, the
/// consistent diagonal scaled to the element mass (HRZ), with the same translational mass on u
/// and v.
Mat6 beam_mass(const Section& section, double L, MassMatrixType type);

/// M05T3. Transformation T (6x6) from global to local element DOFs, u_local = T u_global, for an
/// element at angle alpha: T = blockdiag(R, R), R = [[c, s, 0], [-s, c, 0], [0, 0, 1]]. Global
/// element matrices are T^T k_e T and T^T m_e T.
Mat6 beam_transformation(double alpha);

}  // namespace fmbd
