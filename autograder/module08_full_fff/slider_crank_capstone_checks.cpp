// Definitions of the flexible capstone's checks (see slider_crank_capstone_checks.hpp), compiled
// once per build.
#include "slider_crank_capstone_checks.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>

#include "fmbd/constraints.hpp"
#include "fmbd/dof.hpp"
#include "fmbd/simulation.hpp"
#include "grading.hpp"

namespace fmbd::testing::m08 {

namespace s = fmbd::simeon;

namespace {

// The named body, or -1 with a failure that says what the grader reads.
int body_named(const Model& model, const std::string& name) {
  for (int k = 0; k < model.num_bodies(); ++k)
    if (model.bodies()[k].name == name) return k;
  FAIL_CHECK("the model has no body named \"" << name
                                              << "\": the grader finds the bodies by their names crank, rod and "
                                                 "slider (slider_crank_capstone.hpp)");
  return -1;
}

double rod_length(const FlexibleExample& ex) {
  const DeformableBody& rod = *ex.model.body(ex.flexible).deformable;
  return (rod.node_position(rod.num_nodes() - 1) - rod.node_position(0)).norm();
}

// True when node 0 of the rod is its crank end: at t = 0 the crank pin is at (L1, 0).
bool node0_at_crank(const FlexibleExample& ex) {
  const Vec2 pin(s::crank_length, 0.0);
  return (beam_point(ex, ex.q0, 0.0) - pin).norm() <= (beam_point(ex, ex.q0, rod_length(ex)) - pin).norm();
}

Trajectory capstone_run(const FlexibleExample& ex, double output_interval) {
  SimulationOptions o;
  o.integrator = Integrator::rk4;
  o.step = capstone_step(ex);
  o.stabilisation = Stabilisation::projection;
  o.output_interval = output_interval;
  return simulate(ex.model, ex.q0, ex.qd0, 0.0, s::t_end, o);
}

const char* const kMotion =
    "the motion differs from the published reference: the rod's section, E or rho, the slider's mass, the rod "
    "pinned at other nodes than its ends, the initial state, or a basis too poor for the rod's pinned-pinned "
    "bending (Craig-Bampton on both end nodes holds it)";

}  // namespace

CapstoneState capstone_state(const FlexibleExample& ex, const VecX& q) {
  const double L = rod_length(ex);
  const bool forward = node0_at_crank(ex);
  const Vec2 a = beam_point(ex, q, forward ? 0.0 : L), b = beam_point(ex, q, forward ? L : 0.0);
  CapstoneState st;
  st.phi1 = q(ex.model.offset(ex.model.find_body("crank")) + 2);
  st.phi2 = std::atan2(b.y() - a.y(), b.x() - a.x());
  st.x3 = b.x();
  st.y3 = b.y();
  st.w_mid = (forward ? 1.0 : -1.0) * deflection_at(ex, q, L / 2);
  return st;
}

CapstoneState capstone_rates(const FlexibleExample& ex, const VecX& q, const VecX& qd) {
  const double e = 1e-7;  // [s]
  const CapstoneState p = capstone_state(ex, q + e * qd), m = capstone_state(ex, q - e * qd);
  CapstoneState r;
  r.phi1 = (p.phi1 - m.phi1) / (2 * e);
  r.phi2 = (p.phi2 - m.phi2) / (2 * e);
  r.x3 = (p.x3 - m.x3) / (2 * e);
  r.y3 = (p.y3 - m.y3) / (2 * e);
  r.w_mid = (p.w_mid - m.w_mid) / (2 * e);
  return r;
}

double capstone_step(const FlexibleExample& ex) {
  double omega_max = 0;
  if (ex.data && ex.data->num_modes() > 0) {
    const Eigen::GeneralizedSelfAdjointEigenSolver<MatX> modes(ex.data->K_ff, ex.data->M_ff, Eigen::EigenvaluesOnly);
    omega_max = std::sqrt(std::max(0.0, modes.eigenvalues().maxCoeff()));
  }
  const double h = std::min(5e-5, omega_max > 0 ? 2.0 / omega_max : 5e-5);
  return s::t_end / std::ceil(s::t_end / h - 1e-9);
}

bool check_capstone_structure(const FlexibleExample& ex) {
  const Model& model = ex.model;
  const int crank = body_named(model, "crank"), rod = body_named(model, "rod"), slider = body_named(model, "slider");
  if (crank < 0 || rod < 0 || slider < 0) return false;
  {
    INFO("hint: the rod is the FlexibleExample's flexible body (ex.flexible = the id add_flexible_body returned, "
         "ex.data = its data)");
    CHECK(ex.flexible.index == rod);
    CHECK(model.bodies()[rod].is_flexible());
    CHECK(ex.data != nullptr);
    if (ex.flexible.index != rod || !model.bodies()[rod].is_flexible() || ex.data == nullptr) return false;
    CHECK(ex.data->num_modes() == model.bodies()[rod].deformable->num_modes());
    if (ex.data->num_modes() != model.bodies()[rod].deformable->num_modes()) return false;
  }
  const int n = model.num_coordinates();
  {
    INFO("hint: q0 and qd0 have one entry per coordinate, every one finite");
    CHECK(ex.q0.size() == n);
    CHECK(ex.qd0.size() == n);
    if (ex.q0.size() != n || ex.qd0.size() != n || !ex.q0.allFinite() || !ex.qd0.allFinite()) return false;
  }
  const DeformableBody& beam = *model.bodies()[rod].deformable;
  const Body& c = model.bodies()[crank];
  CHECK_NEAR_NAMED("your crank's mass", c.mass, s::crank_mass, (Tolerance{0, 1e-12}),
                   "the crank's mass: simeon::crank_mass");
  const Vec2 R = ex.q0.segment<2>(model.offset(BodyId{crank}));
  CHECK_NEAR_NAMED(
      "your crank's inertia about O", c.inertia + c.mass * R.squaredNorm(), s::crank_inertia, (Tolerance{0, 1e-9}),
      "the crank's inertia about O (its pivot at the origin): simeon::crank_inertia is J1 about O; a body's "
      "inertia is about its frame's origin, so J1 with the frame at O, J1 - m1 d^2 with it d from O");
  CHECK_NEAR_NAMED("your slider's mass", model.bodies()[slider].mass, s::slider_mass, (Tolerance{0, 1e-12}),
                   "the slider's mass: simeon::slider_mass");
  CHECK_NEAR_NAMED("your rod's mass", beam.mass(), s::rod_mass, (Tolerance{0, 1e-9}),
                   "the rod's mass rho b h L2: its section (b x h), rho or its length");
  CHECK_NEAR_NAMED("your rod's length", rod_length(ex), s::rod_length, (Tolerance{1e-12, 0}),
                   "the rod's length from its first to its last node: simeon::rod_length");
  {
    // The full FFRF's mass matrix depends on the deformation; module 7's does not.
    const VecX q_body = model.body_state(ex.q0, BodyId{rod});
    const int n_f = beam.num_modes();
    VecX bent = q_body;
    if (n_f > 0) {
      const VecX v = VecX::Ones(n_f);
      const double scale = (ex.data->Phi_f * v).cwiseAbs().maxCoeff();
      if (scale > 0) bent.tail(n_f) += (1e-3 * s::rod_length / scale) * v;
    }
    const MatX M0 = beam.mass_matrix(q_body), M1 = beam.mass_matrix(bent);
    INFO("hint: the rod's mass matrix does not change with its deformation: the rod must be a body of the full FFRF "
         "(make_ffrf_body of module 8), not module 7's intuitive body with its constant M_bar");
    CHECK((M1 - M0).cwiseAbs().maxCoeff() > 1e-9 * M0.cwiseAbs().maxCoeff());
  }
  CHECK_CLOSE_NAMED("your model's gravity", model.gravity(), Vec2(Vec2::Zero()), (Tolerance{0, 0}),
                    "Simeon's mechanism moves without gravity");
  // With the driver only the rod's elastic coordinates are free.
  const int dof = degrees_of_freedom(model, ex.q0, 0.0), n_f = beam.num_modes();
  {
    INFO("hint: with the crank's driver the mechanism has no degree of freedom but the rod's elastic coordinates "
         "(3 bodies, 9 frame coordinates; the equations: pins at O, at the crank tip and at the wrist pin, the "
         "slider on the x axis by a translational joint, the crank's angle driven)");
    CAPTURE(n_f);
    CHECK(dof == n_f);
  }
  if (dof != n_f) return false;
  const ConstraintEvaluation e = evaluate_constraints(model, ex.q0, 0.0);
  CHECK_NEAR_NAMED("|C| at your q0", e.C.norm(), 0.0, (Tolerance{1e-10, 0}),
                   "q0 must satisfy every joint: the rod's frame placed so that its deformed end nodes meet the crank "
                   "pin and the slider");
  CHECK_NEAR_NAMED("the velocity equation's residual at your qd0", VecX(e.Cq * ex.qd0 + e.Ct).norm(), 0.0,
                   (Tolerance{1e-8, 0}),
                   "qd0 must satisfy the velocity equation (the frames' rates solved with the rod's elastic rates as "
                   "fitted)");
  return true;
}

void check_capstone_start(const FlexibleExample& ex) {
  const CapstoneState st = capstone_state(ex, ex.q0), rate = capstone_rates(ex, ex.q0, ex.qd0);
  CHECK_NEAR(st.phi2, s::q0[1], (Tolerance{1e-9, 0}), "the rod's chord at t = 0 lies on the x axis (phi2 = 0)");
  CHECK_NEAR(st.x3, s::q0[2], (Tolerance{5e-6, 0}),
             "x3 at t = 0 is L1 + L2 + q4: the rod's published axial state (q3, q4) is missing from its elastic "
             "coordinates, or the basis cannot stretch the rod");
  CHECK_NEAR(st.w_mid, 0.0, (Tolerance{1e-8, 0}),
             "the rod starts straight (q1 = q2 = 0): no deflection at mid-span at t = 0");
  CHECK_NEAR_NAMED("your phi1_dot at t = 0", rate.phi1, s::qd0[0], (Tolerance{0, 1e-9}),
                   "the crank turns at omega = simeon::crank_speed");
  CHECK_NEAR_NAMED(
      "your phi2_dot at t = 0", rate.phi2, s::qd0[1], (Tolerance{0, 1e-4}),
      "the chord's rate at t = 0: the rigid rates solved from the velocity equation with the crank at omega");
  CHECK_NEAR_NAMED(
      "your mid-span deflection rate at t = 0", rate.w_mid, s::qd0[3], (Tolerance{0, 1e-2}),
      "the rate of the mid-span deflection at t = 0 is the published q1_dot: the rod's elastic rates must carry "
      "the published w_dot (fit them like the positions), not start at zero");
}

void check_capstone_motion(const FlexibleExample& ex) {
  const Trajectory run = capstone_run(ex, s::t_end);
  REQUIRE(run.t.size() >= 2);
  const VecX& q = run.q.back();
  const CapstoneState start = capstone_state(ex, ex.q0), st = capstone_state(ex, q),
                      rate = capstone_rates(ex, q, run.qd.back());
  CHECK_NEAR_NAMED("your crank's turn in 0.1 s", st.phi1 - start.phi1, s::q_end[0], (Tolerance{1e-9, 0}),
                   "the crank's turn in 0.1 s: its driver, phi1 = omega t");
  CHECK_NEAR(st.phi2, s::q_end[1], (Tolerance{1e-4, 0}), std::string("phi2 at t = 0.1 s: ") + kMotion);
  CHECK_NEAR(st.x3, s::q_end[2], (Tolerance{1e-5, 0}), std::string("x3 at t = 0.1 s: ") + kMotion);
  CHECK_NEAR(st.w_mid, s::q_end[3], (Tolerance{0, 0.02}),
             std::string("the mid-span deflection (q1) at t = 0.1 s: ") + kMotion);
  CHECK_NEAR_NAMED("your phi2_dot at t = 0.1 s", rate.phi2, s::qd_end[1], (Tolerance{0, 1e-3}),
                   std::string("phi2_dot at t = 0.1 s: ") + kMotion);
  CHECK_NEAR_NAMED("your x3_dot at t = 0.1 s", rate.x3, s::qd_end[2], (Tolerance{0, 1e-3}),
                   std::string("x3_dot at t = 0.1 s: ") + kMotion);
  CHECK_NEAR_NAMED("your mid-span deflection rate at t = 0.1 s", rate.w_mid, s::qd_end[3], (Tolerance{0, 0.15}),
                   std::string("the rate of the mid-span deflection at t = 0.1 s: ") + kMotion);
}

void check_capstone_energy(const FlexibleExample& ex) {
  const Trajectory run = capstone_run(ex, 0.005);
  REQUIRE(run.t.size() >= 2);
  REQUIRE(run.work_done.size() == run.t.size());
  // The consistent mass matrix's small power error (module 8 README, section 2) stays below
  // 4e-3 J on meshes of 4 or more elements; 2e-4 of the crank's energy is 6e-3 J.
  const double tolerance = 2e-4 * 0.5 * s::crank_inertia * s::crank_speed * s::crank_speed;
  double worst = 0;
  std::size_t at = 0;
  for (std::size_t k = 0; k < run.t.size(); ++k) {
    const double error = std::abs(run.energy[k] - run.energy.front() - run.work_done[k]);
    if (error > worst) {
      worst = error;
      at = k;
    }
  }
  CAPTURE(run.t[at]);
  CHECK_NEAR_NAMED("the energy your run gained", run.energy[at] - run.energy.front(), run.work_done[at],
                   (Tolerance{tolerance, 0}),
                   "energy balance: T + V gained equals the driver's work (no damper, gravity or other force belongs "
                   "in Simeon's model)");
}

}  // namespace fmbd::testing::m08
