// Module 7, tasks T4 and T6 through whole models (hidden tests). The oracles: the FE kinetic
// energy 1/2 w^T M_FE w of a free-free body at any frame angle, and the static Ritz solution of a
// beam clamped at its far end in the body's own free-free basis.
#include <cmath>
#include <string>

#include "fmbd/fe_assembly.hpp"
#include "fmbd/intuitive_flexible.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/mass_matrix.hpp"
#include "fmbd/statics.hpp"
#include "flexible_checks.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m07;

GRADED_TEST("add_intuitive_mass at any frame angle: the system's T is the FE kinetic energy of a free-free body",
            "[M07][T4][points=2]") {
  // A free-free basis is M-orthogonal to the rigid motions, so at q_f = 0 the constant M_bar is
  // the exact kinetic energy at every frame angle theta: T = 1/2 w^T M_FE w, w the nodal
  // velocities in frame j (A^T r_k_dot, phi_k_dot) of the velocity field Phi q_dot.
  Random rnd(7491);
  const double L = 0.9, side = 0.012;
  for (MassMatrixType type : {MassMatrixType::consistent, MassMatrixType::lumped}) {
    const FeModel fe = straight_beam(L, 9, steel(side), Vec2(0.2, 0.5), 0.7);
    const auto data = std::make_shared<const FlexibleBodyData>(flexible_body_data(fe, type, 3));
    Model model;
    const BodyId crank = model.add_body("crank", 0.7, 0.02, Vec3(0.1, 0.2, 0.3));
    const BodyId beam = model.add_flexible_body("beam", make_intuitive_body(data), Vec3(0.4, -0.3, 1.2));
    const int n = model.num_coordinates(), at = model.offset(beam), n_f = data->num_modes();
    for (int trial = 0; trial < 3; ++trial) {
      VecX q = VecX::Zero(n), qd = rnd.vector(n, -1.0, 1.0);
      q.segment<3>(model.offset(crank)) = rnd.vec3(-1.0, 1.0);
      q.segment<3>(at) = rnd.vec3(-3.0, 3.0);  // any angle, q_f = 0
      const MatX M = mass_matrix(model, q);
      const VecX v = qd.segment(at, 3 + n_f);
      // Nodal velocities in frame j: A^T R_dot + theta_dot I~ x_bar_k + Phi_t,k q_f_dot, and
      // theta_dot + Phi_psi,k q_f_dot.
      VecX w(3 * data->nodes.size());
      for (std::size_t k = 0; k < data->nodes.size(); ++k) {
        const NodeModes& node = data->nodes[k];
        w.segment<2>(3 * k) = rot(q(at + 2)).transpose() * v.head<2>() + v(2) * (tilde() * node.x_bar) +
                              node.Phi_t * v.tail(n_f);
        w(3 * k + 2) = v(2) + node.Phi_psi.row(0).dot(v.tail(n_f));
      }
      const Vec3 c = qd.segment<3>(model.offset(crank));
      const double T_expected = 0.5 * w.dot(data->matrices.M * w) + 0.5 * (0.7 * c.head<2>().squaredNorm() + 0.02 * c(2) * c(2));
      CAPTURE(trial, q(at + 2));
      CHECK_NEAR_NAMED("the kinetic energy of your M", 0.5 * qd.dot(M * qd), T_expected, (Tolerance{0.0, 1e-9}),
                       "M_bar in M: at q_f = 0 the kinetic energy of your M is not the FE kinetic energy at this angle "
                       "(add M_bar at the body's rows and columns, with +=)" +
                           kNeedsT4);
    }
  }
}

GRADED_TEST("lumped beam clamped at its tip sags like its Ritz solution in free-free modes", "[M07][T6][points=2]") {
  const double L = 1.2;
  const int elements = 8;
  const Vec2 g(0.0, -9.81);
  const FeModel fe = straight_beam(L, elements, steel(0.025));
  const auto data = std::make_shared<const FlexibleBodyData>(flexible_body_data(fe, MassMatrixType::lumped, 4));
  const VecX u = ritz_static_clamped(*data, elements, g);
  const double root_sag = u(1);
  CAPTURE(root_sag);

  Model model;
  model.set_gravity(g);
  const BodyId beam = model.add_flexible_body("beam", make_intuitive_body(data),
                                              frame_for_placement(fe, MassMatrixType::lumped, Vec2::Zero(), 0.0));
  model.add_fixed("clamp", model.add_point(ground, Vec2(L, 0.0), "wall"), model.add_node_point(beam, elements, "tip"));

  StaticSolution sol;
  bool converged = true;
  try {
    sol = static_equilibrium(model, model.initial_guess());
  } catch (const KinematicsError& e) {
    converged = false;
    INFO("hint: static equilibrium failed (" << e.what() << "): elastic force sign (-K_bar q) and gravity in add_intuitive_forces"
                                             << kNeedsT4);
    CHECK(converged);
  }
  if (!converged) return;
  const Vec3 root = pose_oracle(data->nodes[0], model.body_state(sol.q, beam));
  CAPTURE(sol.q.transpose(), root.transpose());
  CHECK_NEAR_NAMED(
      "the root's y of your static solution", root(1), root_sag, (Tolerance{0.0, 1e-6}),
      diagnose(as_matrix(root(1)), as_matrix(root_sag),
               {{"elastic force sign: -K_bar q, the beam bends up instead of sagging", as_matrix(-root_sag)},
                {"the elastic force -K_bar q is missing or not at the body's rows", as_matrix(0.0)}},
               "free end sag of the clamped beam: gravity and -K_bar q in add_intuitive_forces" + kNeedsT4,
               Tolerance{1e-3 * std::abs(root_sag), 1e-3}));
}
