// Module 8, task T5: the body forces Q_v + gravity + elastic, and whole motions (visible tests).
// The oracles: with a lumped mass matrix, gravity and the elastic force are minus the gradient of
// V = -g^T (m R + A S_f q_f) + 1/2 q_f^T K_ff q_f (here from the nodal masses and K_FE), the
// velocity part is Lagrange's (ffrf_checks.hpp); a free flexible pendulum with lumped mass conserves
// its energy, written out from the nodes, to the integrator's tolerance; a free spinning body with
// lumped mass conserves its angular momentum about its mass centre, summed over the nodes.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "ffrf_checks.hpp"
#include "fmbd/energy.hpp"
#include "fmbd/ffrf.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/simulation.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m08;

namespace {

SimulationOptions tight() {
  SimulationOptions o;
  o.integrator = Integrator::dormand_prince;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  o.step = 1e-4;
  o.max_step = 5e-3;
  return o;
}

// -dV/dq by central differences of the potential written out in ffrf_checks.hpp.
VecX minus_gradient(const FlexibleBodyData& data, const VecX& q, const Vec2& g) {
  return -finite_difference_jacobian(
              [&](const VecX& x) { return VecX::Constant(1, fe_potential_energy(data, x, g)); }, q, 1e-6)
              .row(0)
              .transpose();
}

}  // namespace

GRADED_TEST("ffrf_body_forces lumped mass gravity and elastic forces at rest and Q_v in motion",
            "[M08][T5][points=2]") {
  Random rnd(8501);
  const FlexibleBodyData beam = flexible_body_data(
      straight_beam(1.0, 8, square_section(5e8, 1200.0, 0.02), Vec2(0.5, 0.1), 0.2), MassMatrixType::lumped, 4);
  const FlexibleBodyData frame = flexible_body_data(l_frame(), MassMatrixType::lumped, 5);
  for (const FlexibleBodyData* data : {&beam, &frame}) {
    REQUIRE(isotropic_lumped(data->matrices.M));
    const int n_f = data->num_modes();
    for (int trial = 0; trial < 3; ++trial) {
      const VecX q = random_q(rnd, n_f, modal_scale(*data, 0.05));
      const Vec2 g = Vec2(rnd.uniform(-3, 3), -kG);
      const VecX zero = VecX::Zero(3 + n_f);
      CAPTURE(q.transpose(), g.transpose());
      const VecX Q = ffrf_body_forces(*data, q, zero, g);
      const VecX expected = minus_gradient(*data, q, g);
      const double scale = expected.cwiseAbs().maxCoeff();
      CHECK_CLOSE_NAMED("your ffrf_body_forces at rest", Q, expected, (Tolerance{1e-6 * scale, 1e-6}),
                        rest_force_hint(Q, expected, *data, q, g));

      VecX qd = rnd.vector(3 + n_f, -1.0, 1.0);
      qd(2) = rnd.uniform(1.0, 4.0);
      qd.tail(n_f) *= modal_scale(*data, 0.5);
      CAPTURE(qd.transpose());
      const VecX moving = ffrf_body_forces(*data, q, qd, g) - Q;
      const VecX Qv = lagrangian_qv(*data, q, qd);
      const double qv_scale = Qv.cwiseAbs().maxCoeff();
      CHECK_CLOSE_NAMED(
          "the part of your ffrf_body_forces the velocities add (Q_v)", moving, Qv, (Tolerance{1e-6 * qv_scale, 1e-6}),
          diagnose(moving, Qv, {{"Q_v missing in the body forces: ffrf_body_forces = Q_v + gravity + elastic", zero}},
                   qv_hint(moving, Qv, *data, q, qd)));
    }
  }
}

GRADED_TEST("ffrf_body_forces free flexible pendulum with lumped mass conserves energy", "[M08][T5][points=2]") {
  FlexiblePendulumParameters p;
  p.E = 5e8;
  p.rho = 1200.0;
  p.side = 0.02;
  p.mass_type = MassMatrixType::lumped;
  const FlexibleExample ex = flexible_pendulum(p, make_ffrf_body);
  const FlexibleBodyData& data = *ex.data;
  REQUIRE(isotropic_lumped(data.matrices.M));
  const int offset = ex.model.offset(ex.flexible), n = 3 + data.num_modes();
  const Vec2 g = ex.model.gravity();
  auto energy = [&](const VecX& q, const VecX& qd) {
    const VecX qb = q.segment(offset, n), qdb = qd.segment(offset, n);
    return fe_kinetic_energy(data, qb, qdb) + fe_potential_energy(data, qb, g);
  };
  const Trajectory s = simulate(ex.model, ex.q0, ex.qd0, 0.0, 1.0, tight());
  REQUIRE(s.t.back() == Approx(1.0));
  const double scale = data.mass * kG * p.length;  // the energy the swing turns over
  const double E0 = energy(s.q.front(), s.qd.front());
  double worst = 0, worst_reported = 0, bend = 0;
  const NodeModes& tip = data.nodes.back();
  for (std::size_t i = 0; i < s.q.size(); ++i) {
    worst = std::max(worst, std::abs(energy(s.q[i], s.qd[i]) - E0));
    worst_reported = std::max(worst_reported, std::abs(s.energy[i] - s.energy.front()));
    bend = std::max(bend, std::abs((tip.Phi_t * s.q[i].segment(offset + 3, data.num_modes()))(1)));
  }
  const std::string relative_error = sci(worst / scale), reported_error = sci(worst_reported / scale);
  CAPTURE(relative_error, reported_error, bend, s.steps);
  // The beam really bends (more than 1 mm at the tip), so the elastic terms matter.
  REQUIRE(bend > 1e-3 * p.length);
  CHECK_NEAR_NAMED("the largest change of T + V in your run, relative", worst / scale, 0.0, (Tolerance{1e-8, 0.0}),
                   "a free flexible pendulum with lumped mass conserves T + V to the integrator's tolerance: with "
                   "M(q) = L^T M_FE L, Q_v = -L^T M_FE b, module 7's gravity and -K_bar q: the nodal form is "
                   "Lagrange's; check the T3 and T4 tests first");
  CHECK_NEAR_NAMED("the largest change of the energy your simulate reports, relative", worst_reported / scale, 0.0,
                   (Tolerance{1e-8, 0.0}),
                   "Trajectory::energy (1/2 q_dot^T M(q) q_dot + V) must stay constant: M(q) = L^T M_FE L");
}

GRADED_TEST("ffrf_body_forces free spinning body with lumped mass conserves angular momentum and energy",
            "[M08][T5][points=2]") {
  Random rnd(8503);
  const auto data = shared(flexible_body_data(l_frame(), MassMatrixType::lumped, 5));
  REQUIRE(isotropic_lumped(data->matrices.M));
  const int n_f = data->num_modes();
  Model model;
  model.add_flexible_body("frame", make_ffrf_body(data), Vec3(0.4, -0.2, 0.5));
  VecX q0 = VecX::Zero(3 + n_f), qd0 = VecX::Zero(3 + n_f);
  q0.head<3>() = Vec3(0.4, -0.2, 0.5);
  qd0.head<3>() = Vec3(0.3, -0.5, 6.0);
  qd0.tail(n_f) = rnd.vector(n_f, -1.0, 1.0) * modal_scale(*data, 2.0);
  const Trajectory s = simulate(model, q0, qd0, 0.0, 1.0, tight());
  REQUIRE(s.t.back() == Approx(1.0));
  const Vec2 no_gravity = Vec2::Zero();
  const double H0 = lumped_angular_momentum(*data, s.q.front(), s.qd.front());
  const double E0 = fe_kinetic_energy(*data, s.q.front(), s.qd.front()) +
                    fe_potential_energy(*data, s.q.front(), no_gravity);
  double worst_H = 0, worst_E = 0, bend = 0;
  for (std::size_t i = 0; i < s.q.size(); ++i) {
    worst_H = std::max(worst_H, std::abs(lumped_angular_momentum(*data, s.q[i], s.qd[i]) - H0));
    worst_E = std::max(worst_E, std::abs(fe_kinetic_energy(*data, s.q[i], s.qd[i]) +
                                         fe_potential_energy(*data, s.q[i], no_gravity) - E0));
    bend = std::max(bend, s.q[i].tail(n_f).norm());
  }
  const std::string H_error = sci(worst_H / std::abs(H0)), E_error = sci(worst_E / E0);
  CAPTURE(H0, E0, H_error, E_error, bend, s.steps);
  REQUIRE(bend > modal_scale(*data, 0.01));
  CHECK_NEAR_NAMED("the largest relative change of the angular momentum in your run", worst_H / std::abs(H0), 0.0,
                   (Tolerance{1e-8, 0.0}),
                   "a free flexible body keeps its angular momentum sum m_k (r_k - r_c) x v_k + J_k phi_dot_k: the "
                   "centrifugal and Coriolis forces in Q_v = -L^T M_FE b (Coriolis factor 2, centripetal sign) and "
                   "M(q) = L^T M_FE L exchange it between rotation and deformation");
  CHECK_NEAR_NAMED("the largest relative change of the energy in your run", worst_E / E0, 0.0, (Tolerance{1e-8, 0.0}),
                   "a free flexible body with lumped mass conserves its kinetic plus strain energy: M(q) = L^T M_FE L, "
                   "Q_v = -L^T M_FE b and -K_ff q_f");
}

GRADED_TEST("add_ffrf_forces adds the body's forces of its own coordinates at rows at .. at + 3 + n_f only",
            "[M08][T5][points=1]") {
  Random rnd(8503);
  const FlexibleBodyData data = flexible_body_data(l_frame(Vec2(0.1, 0.2)), MassMatrixType::lumped, 3);
  const int n = 3 + data.num_modes(), at = 2, size = n + 4;
  const VecX q_j = random_q(rnd, data.num_modes(), modal_scale(data, 0.05));
  const VecX qd_j = rnd.vector(n, -1.0, 1.0);
  VecX q = rnd.vector(size, -1.0, 1.0), qd = rnd.vector(size, -1.0, 1.0);
  q.segment(at, n) = q_j;
  qd.segment(at, n) = qd_j;
  const Vec2 g(0.3, -9.81);
  const VecX before = rnd.vector(size, -1.0, 1.0);
  VecX Q_a = before;
  add_ffrf_forces(data, q, qd, g, at, Q_a);
  VecX others = Q_a - before;
  others.segment(at, n).setZero();
  CHECK_CLOSE_NAMED("what your add_ffrf_forces adds outside the body's rows", others, VecX(VecX::Zero(size)),
                    (Tolerance{0.0, 0.0}), "add_ffrf_forces adds to the body's rows at .. at + 3 + n_f only, with +=");
  // Lumped mass: Q_v is Lagrange's, and gravity and the elastic force are minus the gradient of V.
  const VecX added = (Q_a - before).segment(at, n);
  const VecX expected = lagrangian_qv(data, q_j, qd_j) + minus_gradient(data, q_j, g);
  CHECK_CLOSE_NAMED("what your add_ffrf_forces adds at the body's rows", added, expected,
                    (Tolerance{1e-6 * expected.cwiseAbs().maxCoeff(), 1e-8}),
                    "the forces of the body's own q_j = q.segment(at, 3 + n_f) and q_dot_j, not of q's first entries");
}

