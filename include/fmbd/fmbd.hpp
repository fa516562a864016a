#pragma once
// The engine's umbrella header: every public header of the eight modules, and Eigen's dense
// module, so that a program outside the course needs one include for models, kinematics,
// dynamics, integration, FE models, reduction and flexible bodies, and can use Eigen's
// decompositions (.ldlt(), .eigenvalues(), ...) on the engine's matrices. The extras have headers
// of their own (extras/NAME/README.md), linked through fmbd::NAME.
//
//   #include <fmbd/fmbd.hpp>
//   const fmbd::Model crank = fmbd::examples::slider_crank();   // examples/ has whole programs

#include <Eigen/Dense>

#include "fmbd/planar.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/model.hpp"
#include "fmbd/constraint_block.hpp"
#include "fmbd/constraints.hpp"
#include "fmbd/deformable.hpp"
#include "fmbd/marker.hpp"
#include "fmbd/joints.hpp"
#include "fmbd/drivers.hpp"
#include "fmbd/drive_function.hpp"
#include "fmbd/dof.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/linear_solve.hpp"
#include "fmbd/newton_raphson.hpp"
#include "fmbd/velocity_acceleration.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/gamma.hpp"
#include "fmbd/kinematic_analysis.hpp"
#include "fmbd/mass_matrix.hpp"
#include "fmbd/applied_forces.hpp"
#include "fmbd/inverse_dynamics.hpp"
#include "fmbd/reactions.hpp"
#include "fmbd/energy.hpp"
#include "fmbd/forward_dynamics.hpp"
#include "fmbd/integrators.hpp"
#include "fmbd/projection.hpp"
#include "fmbd/simulation.hpp"
#include "fmbd/fe_model.hpp"
#include "fmbd/beam_element.hpp"
#include "fmbd/fe_assembly.hpp"
#include "fmbd/supports.hpp"
#include "fmbd/modal.hpp"
#include "fmbd/reduction.hpp"
#include "fmbd/flexible_body.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/intuitive_flexible.hpp"
#include "fmbd/statics.hpp"
#include "fmbd/ffrf.hpp"
