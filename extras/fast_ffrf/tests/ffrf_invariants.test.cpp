// Project tests (not graded) of the fast full FFRF body (fmbd/ffrf_invariants.hpp): the
// invariant form against the nodal FfrfBody at random states (lumped and consistent mass, modal
// truncation, Craig-Bampton, a bent frame with a basis that is not M-orthogonal, and that frame
// with a random symmetric M_FE, for which no identity of beam elements holds), its kinetic
// energy against the FE kinetic energy of finite-difference nodal velocities, its quadratic
// velocity vector against Lagrange's equations where they hold (lumped mass), a whole
// slider-crank simulation against the nodal body, and no heap allocation in the evaluations into
// caller-provided storage and in the body's add_mass and add_forces. Also the allocation-free RK4 step loop of the benchmarks
// (bench/workspace): against module 4's forward dynamics and simulate, energy conservation, no
// allocation per step.
//
// The nodal FfrfBody is the reference implementation of module 8 (graded against finite
// differences and energy conservation); this program links the reference stages.
//
// Allocations are counted by replacing the global operator new/delete, and, with glibc, malloc,
// calloc and realloc as well: Eigen's dynamic matrices take their memory from std::malloc, not
// from operator new. The malloc wrappers forward to glibc's own allocator. Under AddressSanitizer,
// which supplies its own malloc, only operator new is counted.
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <limits>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "fmbd/fe_assembly.hpp"
#include "fmbd/fe_model.hpp"
#include "fmbd/ffrf.hpp"
#include "fmbd/energy.hpp"
#include "fmbd/ffrf_invariants.hpp"
#include "fmbd/flexible_body.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/forward_dynamics.hpp"
#include "fmbd/reduction.hpp"
#include "fmbd/simulation.hpp"
#include "grading.hpp"
#include "random_states.hpp"
#include "fmbd/workspace_rk4.hpp"

// ---- counting allocators -----------------------------------------------------------------------

namespace {
bool g_counting = false;
long g_news = 0;
long g_mallocs = 0;
void* volatile g_sink = nullptr;  // keeps the probe allocation of the test observable
}  // namespace

#if defined(__SANITIZE_ADDRESS__)
#define FMBD_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FMBD_TEST_ASAN 1
#endif
#endif

[[gnu::noinline]] void* operator new(std::size_t size) {
  if (g_counting) ++g_news;
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
[[gnu::noinline]] void* operator new[](std::size_t size) { return ::operator new(size); }
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete[](void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

#if defined(__GLIBC__) && !defined(FMBD_TEST_ASAN)
constexpr bool kCountsMalloc = true;
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void* malloc(std::size_t size) noexcept {
  if (g_counting) ++g_mallocs;
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) noexcept {
  if (g_counting) ++g_mallocs;
  return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) noexcept {
  if (g_counting) ++g_mallocs;
  return __libc_realloc(p, size);
}
}
#else
constexpr bool kCountsMalloc = false;
#endif

using namespace fmbd;
using fmbd::testing::Random;
using fmbd::testing::random_state;
using fmbd::testing::reach;
using fmbd::testing::largest_translation;
using fmbd::testing::Tolerance;

namespace {

using DataPtr = std::shared_ptr<const FlexibleBodyData>;
const Section kSteel = square_section(210e9, 7850.0, 0.01);

Mat2 rot(double a) { return (Mat2() << std::cos(a), -std::sin(a), std::sin(a), std::cos(a)).finished(); }

// ---- bodies --------------------------------------------------------------------------------------

struct Case {
  std::string name;
  DataPtr data;
  bool beam_mass = true;  // M_FE of beam elements (false: a random symmetric one)
};

DataPtr truncation(MassMatrixType type) {
  return std::make_shared<const FlexibleBodyData>(
      flexible_body_data(straight_beam(1.2, 10, kSteel, Vec2(0.3, -0.2), 0.4), type, 4));
}

DataPtr craig_bampton_body(MassMatrixType type) {
  const FeModel fe = straight_beam(0.8, 12, kSteel, Vec2(-0.1, 0.2), -0.7);
  const FeMatrices m = assemble(fe, type);
  const ReducedBasis cb = craig_bampton(m.K, m.M, node_dofs({0, 12}), 3);
  return std::make_shared<const FlexibleBodyData>(flexible_body_data(fe, type, ffrf_basis(fe, m, cb)));
}

// An L-shaped frame (nodes off any line, elements at two angles) with random elastic columns:
// S_f != 0, M_ff != I, K_ff full.
DataPtr bent_frame(MassMatrixType type, unsigned seed) {
  FeModel fe;
  for (int k = 0; k <= 4; ++k) fe.add_node(Vec2(0.15 * k, 0.02 * k));
  for (int k = 1; k <= 3; ++k) fe.add_node(Vec2(0.6 - 0.05 * k, 0.08 + 0.14 * k));
  for (int k = 0; k < 7; ++k) fe.add_element(k, k + 1, kSteel);
  Random rnd(seed);
  ReducedBasis b;
  b.num_rigid = 3;
  b.Phi = MatX::Zero(fe.num_dofs(), 3 + 5);
  b.Phi.rightCols(5) = MatX::NullaryExpr(fe.num_dofs(), 5, [&]() { return rnd.uniform(-0.1, 0.1); });
  return std::make_shared<const FlexibleBodyData>(flexible_body_data(fe, type, b));
}

// The same body with M_FE replaced by a random symmetric positive definite matrix, which couples
// every DOF: no identity of beam elements (isotropy, exact rigid and radial fields) holds, so
// every invariant is non-zero. The nodal form and the invariants must still agree.
DataPtr random_mass(const DataPtr& base, unsigned seed) {
  FlexibleBodyData d = *base;
  const int n = d.fe.num_dofs();
  Random rnd(seed);
  const MatX B = MatX::NullaryExpr(n, n, [&]() { return rnd.uniform(-1.0, 1.0); });
  d.matrices.M = MatX(d.mass / n * (B * B.transpose() / n + MatX::Identity(n, n))).sparseView();
  d.basis.M_bar = d.basis.Phi.transpose() * d.matrices.M * d.basis.Phi;
  d.M_ff = d.Phi_f.transpose() * d.matrices.M * d.Phi_f;
  d.S_f = d.basis.Phi.leftCols(2).transpose() * d.matrices.M * d.Phi_f;
  return std::make_shared<const FlexibleBodyData>(std::move(d));
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (MassMatrixType type : {MassMatrixType::lumped, MassMatrixType::consistent}) {
    const std::string mass = type == MassMatrixType::lumped ? "lumped" : "consistent";
    out.push_back({"truncation, " + mass, truncation(type)});
    out.push_back({"Craig-Bampton, " + mass, craig_bampton_body(type)});
    out.push_back({"bent frame with a skew basis, " + mass, bent_frame(type, type == MassMatrixType::lumped ? 5 : 6)});
  }
  out.push_back({"bent frame with a random symmetric M_FE", random_mass(bent_frame(MassMatrixType::consistent, 4), 12), false});
  return out;
}

Tolerance relative_to(const Eigen::MatrixXd& expected, double rel = 1e-10) {
  return Tolerance{rel * std::max(expected.cwiseAbs().maxCoeff(), 1e-300), rel};
}

// ---- independent kinematics --------------------------------------------------------------------

// Absolute nodal velocities in frame j, (A^T r_k_dot, phi_k_dot), from fourth-order central
// differences of the node poses r_k = R + A (x_k + u_k), phi_k = theta + psi_k along q + s q_dot,
// with x_k the centred FE node and (u_k, psi_k) the rows of Phi_f q_f.
VecX nodal_velocities(const FlexibleBodyData& d, const VecX& q, const VecX& qd) {
  const int N = d.fe.num_nodes(), n_f = d.num_modes();
  auto poses = [&](double s) {
    const VecX x = q + s * qd;
    const VecX u = d.Phi_f * x.tail(n_f);
    VecX p(3 * N);
    for (int k = 0; k < N; ++k) {
      p.segment<2>(3 * k) = x.head<2>() + rot(x(2)) * (d.fe.nodes()[k] + u.segment<2>(3 * k));
      p(3 * k + 2) = x(2) + u(3 * k + 2);
    }
    return p;
  };
  const double h = 1e-4;
  VecX w = (-poses(2 * h) + 8 * poses(h) - 8 * poses(-h) + poses(-2 * h)) / (12 * h);
  const Mat2 At = rot(q(2)).transpose();
  for (int k = 0; k < N; ++k) w.segment<2>(3 * k) = At * w.segment<2>(3 * k);
  return w;
}

}  // namespace

// ---- against the nodal form ----------------------------------------------------------------------

TEST_CASE("ffrf invariants: M(q), Q_v, body forces and T equal the nodal FfrfBody at random states",
          "[ffrf_invariants]") {
  Random rnd(2024);
  for (const Case& c : cases()) {
    CAPTURE(c.name);
    const FfrfBody nodal(c.data);
    const ModalFfrfBody fast(c.data);
    const FfrfInvariants& inv = fast.invariants();
    REQUIRE(inv.num_modes() == c.data->num_modes());
    REQUIRE(inv.size() == 3 + c.data->num_modes());
    for (int trial = 0; trial < 4; ++trial) {
      CAPTURE(trial);
      VecX q, qd;
      random_state(*c.data, rnd, q, qd);
      const Vec2 g = rnd.vec2(-10.0, 10.0);

      const MatX M = nodal.mass_matrix(q);
      CHECK_CLOSE(fast.mass_matrix(q), M, relative_to(M), "M(q) = L^T M_FE L");
      const MatX Mq = inv.mass_matrix(q);
      CHECK_CLOSE(Mq, MatX(Mq.transpose()), (Tolerance{0.0, 0.0}), "M(q) exactly symmetric");

      const VecX Qv = quadratic_velocity_vector(*c.data, q, qd);
      CHECK_CLOSE(inv.quadratic_velocity_vector(q, qd), Qv, relative_to(Qv), "Q_v = -L^T M_FE b");

      const VecX Q = nodal.body_forces(q, qd, g);
      CHECK_CLOSE(fast.body_forces(q, qd, g), Q, relative_to(Q), "Q_v + gravity - K_ff q_f");
      const VecX no_velocity = VecX::Zero(q.size());
      const VecX Q0 = nodal.body_forces(q, no_velocity, g);
      CHECK_CLOSE(fast.body_forces(q, no_velocity, g), Q0, relative_to(Q0), "gravity and elastic forces at rest");

      const double T = nodal.kinetic_energy(q, qd);
      CHECK_NEAR(fast.kinetic_energy(q, qd), T, (Tolerance{0.0, 1e-10}), "1/2 q_dot^T M(q) q_dot");
      CHECK_NEAR(fast.potential_energy(q, g), nodal.potential_energy(q, g), (Tolerance{0.0, 1e-12}), "V");
    }
  }
}

TEST_CASE("ffrf invariants: at rest in the undeformed state the body is module 7's M_bar", "[ffrf_invariants]") {
  for (const Case& c : cases()) {
    CAPTURE(c.name);
    const FlexibleBodyData& d = *c.data;
    const FfrfInvariants inv(d);
    VecX q = VecX::Zero(3 + d.num_modes());
    q.head<3>() << 0.4, -0.3, 0.0;
    CHECK_CLOSE(inv.mass_matrix(q), d.basis.M_bar, relative_to(d.basis.M_bar), "M(R, 0, 0) = Phi^T M_FE Phi");
    if (c.beam_mass) {
      CHECK_CLOSE(inv.M_tt(), MatX(d.mass * Mat2::Identity()), (Tolerance{1e-12 * d.mass, 0.0}), "T^T M T = m I");
      CHECK_NEAR(inv.J_0(), d.inertia, (Tolerance{0.0, 1e-12}), "c0^T M c0 = J");
    }
    CHECK_CLOSE(MatX(inv.S_f()), d.S_f, (Tolerance{1e-12 * std::max(d.mass, std::sqrt(d.mass)), 1e-10}),
                "S_f of the data");
    CHECK_CLOSE(inv.K_ff(), d.K_ff, (Tolerance{0.0, 0.0}), "K_ff of the data");
  }
}

TEST_CASE("ffrf invariants: sizes are checked", "[ffrf_invariants]") {
  const DataPtr d = truncation(MassMatrixType::lumped);
  const ModalFfrfBody body(d);
  const VecX bad = VecX::Zero(5), good = VecX::Zero(7);
  MatX M;
  VecX Q;
  CHECK_THROWS_MENTIONING(body.invariants().mass_matrix(bad, M), std::invalid_argument,
                          "mass_matrix: q has size 5, expected 7");
  CHECK_THROWS_MENTIONING(body.invariants().body_forces(good, bad, Vec2::Zero(), Q), std::invalid_argument,
                          "q_dot has size 5");
  CHECK_THROWS_MENTIONING(body.invariants().kinetic_energy(bad, good), std::invalid_argument, "q has size 5");
  CHECK_THROWS_MENTIONING(body.mass_matrix(bad), std::invalid_argument, "add_mass");
  CHECK_THROWS_MENTIONING(body.body_forces(good, bad, Vec2::Zero()), std::invalid_argument, "add_forces");
  CHECK_THROWS_AS(ModalFfrfBody(nullptr), std::invalid_argument);
}

// ---- independent checks ---------------------------------------------------------------------------

TEST_CASE("ffrf invariants: the kinetic energy is the FE kinetic energy of the nodal velocities",
          "[ffrf_invariants]") {
  Random rnd(7);
  for (const Case& c : cases()) {
    CAPTURE(c.name);
    const FfrfInvariants inv(*c.data);
    for (int trial = 0; trial < 2; ++trial) {
      CAPTURE(trial);
      VecX q, qd;
      random_state(*c.data, rnd, q, qd);
      const VecX w = nodal_velocities(*c.data, q, qd);
      const double T_fe = 0.5 * w.dot(c.data->matrices.M * w);
      CHECK_NEAR(inv.kinetic_energy(q, qd), T_fe, (Tolerance{0.0, 1e-8}), "T = 1/2 u_dot^T M_FE u_dot");
      CHECK_NEAR(0.5 * qd.dot(inv.mass_matrix(q) * qd), T_fe, (Tolerance{0.0, 1e-8}), "1/2 q_dot^T M(q) q_dot");
    }
  }
}

TEST_CASE("ffrf invariants: with lumped mass Q_v is Lagrange's dT/dq - M_dot q_dot", "[ffrf_invariants]") {
  // Isotropic nodal masses make the nodal form Lagrangian (README of module 8, section 2).
  Random rnd(8);
  for (const DataPtr& d : {truncation(MassMatrixType::lumped), bent_frame(MassMatrixType::lumped, 9)}) {
    const FfrfInvariants inv(*d);
    VecX q, qd;
    random_state(*d, rnd, q, qd);
    const int n = inv.size();
    const double h = 1e-6;
    VecX dT(n);
    for (int k = 0; k < n; ++k) {
      VecX qp = q, qm = q;
      qp(k) += h;
      qm(k) -= h;
      dT(k) = (inv.kinetic_energy(qp, qd) - inv.kinetic_energy(qm, qd)) / (2 * h);
    }
    const MatX M_dot = (inv.mass_matrix(VecX(q + h * qd)) - inv.mass_matrix(VecX(q - h * qd))) / (2 * h);
    const VecX expected = dT - M_dot * qd;
    CHECK_CLOSE(inv.quadratic_velocity_vector(q, qd), expected, relative_to(expected, 1e-6),
                "Q_v = dT/dq - M_dot q_dot");
  }
}

// ---- simulation ------------------------------------------------------------------------------------

TEST_CASE("ffrf invariants: a slider-crank simulation with ModalFfrfBody follows FfrfBody", "[ffrf_invariants]") {
  for (MassMatrixType type : {MassMatrixType::consistent, MassMatrixType::lumped}) {
    CAPTURE(type == MassMatrixType::lumped);
    FlexibleSliderCrankParameters p;
    p.mass_type = type;
    const FlexibleExample nodal = flexible_slider_crank(p, make_ffrf_body);
    const FlexibleExample fast = flexible_slider_crank(p, make_modal_ffrf_body);
    REQUIRE(dynamic_cast<const ModalFfrfBody*>(fast.model.body(fast.flexible).deformable.get()));
    SimulationOptions o;
    o.integrator = Integrator::rk4;
    o.step = 1e-5;
    o.output_interval = 1e-3;
    const double t_end = 0.02;  // about half a crank turn at 150 rad/s
    const Trajectory a = simulate(nodal.model, nodal.q0, nodal.qd0, 0.0, t_end, o);
    const Trajectory b = simulate(fast.model, fast.q0, fast.qd0, 0.0, t_end, o);
    REQUIRE(a.t.size() == b.t.size());
    REQUIRE(a.steps == b.steps);
    const int at = nodal.model.offset(nodal.flexible), n_f = nodal.data->num_modes();
    double deflection = 0;
    for (std::size_t i = 0; i < a.t.size(); ++i) {
      CAPTURE(a.t[i]);
      REQUIRE(a.t[i] == b.t[i]);
      CHECK_CLOSE(b.q[i], a.q[i], relative_to(a.q[i], 1e-9), "q along the run");
      CHECK_CLOSE(b.qd[i], a.qd[i], relative_to(a.qd[i], 1e-9), "q_dot along the run");
      CHECK_NEAR(b.energy[i], a.energy[i], (Tolerance{1e-9 * std::abs(a.energy.front()), 1e-9}), "energy");
      deflection = std::max(deflection, largest_translation(*nodal.data, a.q[i].segment(at, n_f)));
    }
    // The rod did bend: the runs compare real elastic motion.
    INFO("largest elastic displacement " << deflection << " m");
    CHECK(deflection > 1e-5);
  }
}

// ---- allocations -----------------------------------------------------------------------------------

TEST_CASE("ffrf invariants: evaluations into caller-provided storage do not allocate", "[ffrf_invariants]") {
  // The counters see Eigen's heap: a dynamic vector made in the window is counted.
  g_mallocs = g_news = 0;
  g_counting = true;
  {
    const VecX probe = VecX::Ones(1000);
    g_sink = new std::vector<int>(10);
    delete static_cast<std::vector<int>*>(g_sink);
    CHECK(probe.sum() == 1000.0);
  }
  g_counting = false;
  CHECK(g_news >= 1);
  if (kCountsMalloc) {
    CHECK(g_mallocs >= 2);
  } else {
    WARN("malloc is not counted here (AddressSanitizer or not glibc): Eigen's allocations go unseen");
  }

  Random rnd(99);
  for (const DataPtr& d : {craig_bampton_body(MassMatrixType::consistent), bent_frame(MassMatrixType::lumped, 3)}) {
    const FfrfInvariants inv(*d);
    const int n = inv.size();
    VecX q, qd;
    random_state(*d, rnd, q, qd);
    // A state inside a larger system vector, as the Model holds it.
    VecX system(3 + 2 * n);
    system.segment(3, n) = q;
    system.segment(3 + n, n) = qd;
    const Vec2 g(0.0, -9.81);
    MatX M, M_sys = MatX::Zero(3 + n, 3 + n);
    VecX Q, Qv, Q_sys = VecX::Zero(3 + n), q_sys = VecX::Zero(3 + n), qd_sys = q_sys;
    q_sys.tail(n) = q;
    qd_sys.tail(n) = qd;
    double T = 0;
    const ModalFfrfBody body(d);  // its hooks add at rows 3 .. of a system's M and Q_a
    inv.mass_matrix(q, M);  // warm-up: sizes the outputs and the body's per-thread storage
    inv.body_forces(q, qd, g, Q);
    inv.quadratic_velocity_vector(q, qd, Qv);
    body.add_mass(q_sys, 3, M_sys);
    body.add_forces(q_sys, qd_sys, g, 3, Q_sys);

    g_mallocs = g_news = 0;
    g_counting = true;
    for (int k = 0; k < 10; ++k) {
      inv.mass_matrix(q, M);
      inv.quadratic_velocity_vector(q, qd, Qv);
      inv.body_forces(q, qd, g, Q);
      T += inv.kinetic_energy(q, qd);
      inv.mass_matrix(system.segment(3, n), M);
      inv.body_forces(system.segment(3, n), system.segment(3 + n, n), g, Q);
      T += inv.kinetic_energy(system.segment(3, n), system.segment(3 + n, n));
      body.add_mass(q_sys, 3, M_sys);
      body.add_forces(q_sys, qd_sys, g, 3, Q_sys);
    }
    g_counting = false;
    const long news = g_news, mallocs = g_mallocs;
    INFO("operator new: " << news << ", malloc/calloc/realloc: " << mallocs);
    REQUIRE(news == 0);
    REQUIRE(mallocs == 0);
    // And the results are the ones of the value-returning forms.
    CHECK_CLOSE(M, inv.mass_matrix(q), (Tolerance{0.0, 0.0}), "into storage = by value");
    CHECK_CLOSE(Q, inv.body_forces(q, qd, g), (Tolerance{0.0, 0.0}), "into storage = by value");
    CHECK_CLOSE(Qv, inv.quadratic_velocity_vector(q, qd), (Tolerance{0.0, 0.0}), "into storage = by value");
    CHECK_NEAR(T, 20 * inv.kinetic_energy(q, qd), (Tolerance{0.0, 1e-14}), "kinetic energy");
    // The body's hooks added the value forms 11 times at its rows, and nothing elsewhere.
    MatX M_sum = MatX::Zero(3 + n, 3 + n);
    VecX Q_sum = VecX::Zero(3 + n);
    for (int k = 0; k < 11; ++k) {
      M_sum.bottomRightCorner(n, n) += inv.mass_matrix(q);
      Q_sum.tail(n) += inv.body_forces(q, qd, g);
    }
    CHECK_CLOSE(M_sys, M_sum, (Tolerance{0.0, 0.0}), "add_mass = the value form added");
    CHECK_CLOSE(Q_sys, Q_sum, (Tolerance{0.0, 0.0}), "add_forces = the value form added");
  }
}

// ---- the allocation-free step loop (bench/workspace) ---------------------------------------------

namespace {

VecX state_of(const FlexibleExample& ex) {
  VecX y(2 * ex.q0.size());
  y << ex.q0, ex.qd0;
  return y;
}

}  // namespace

TEST_CASE("workspace rk4: its derivative is module 4's forward dynamics, its steps are simulate's",
          "[ffrf_invariants][workspace]") {
  FlexibleSliderCrankParameters p;
  p.elements = 12;
  p.modes = 4;
  const FlexibleExample ex = flexible_slider_crank(p, make_modal_ffrf_body);
  const int n = ex.model.num_coordinates();
  bench::WorkspaceRk4 stepper(ex.model);
  Random rnd(41);
  for (int trial = 0; trial < 5; ++trial) {
    // Any state will do for the equations of motion: C(q, t) = 0 is not needed for M, Q and gamma.
    const VecX q = ex.q0 + 1e-3 * rnd.vector(n, -1, 1);
    const VecX qd = ex.qd0 + rnd.vector(n, -1, 1);
    const double t = 0.01 * trial;
    VecX y(2 * n), dy(2 * n);
    y << q, qd;
    stepper.derivative(t, y, dy);
    const Accelerations a = forward_dynamics(ex.model, q, qd, t);
    CAPTURE(trial);
    CHECK_CLOSE(dy.tail(n), a.qdd, (Tolerance{1e-9 * a.qdd.cwiseAbs().maxCoeff(), 1e-9}),
                "WorkspaceRk4's q_ddot: markers, G, gamma, M(q) or the body forces differ from module 4's");
    CHECK_CLOSE(dy.head(n), qd, (Tolerance{0, 0}), "the first half of y_dot is q_dot");
  }

  SimulationOptions o;
  o.integrator = Integrator::rk4;
  o.step = 2e-5;
  const Trajectory tr = simulate(ex.model, ex.q0, ex.qd0, 0.0, 50 * o.step, o);
  VecX y = state_of(ex);
  for (int s = 0; s < 50; ++s) stepper.step(s * o.step, y, o.step);
  CHECK_CLOSE(y.head(n), tr.q.back(), (Tolerance{1e-10, 1e-9}), "WorkspaceRk4 after 50 steps against simulate (RK4)");
  CHECK_CLOSE(y.tail(n), tr.qd.back(), (Tolerance{1e-8, 1e-8}), "WorkspaceRk4 after 50 steps against simulate (RK4)");
}

TEST_CASE("workspace rk4: a free flexible pendulum with lumped mass keeps its energy", "[ffrf_invariants][workspace]") {
  FlexiblePendulumParameters p;
  p.mass_type = MassMatrixType::lumped;
  const FlexibleExample ex = flexible_pendulum(p, make_modal_ffrf_body);
  bench::WorkspaceRk4 stepper(ex.model);
  const int n = ex.model.num_coordinates();
  VecX y = state_of(ex);
  auto energy = [&] { return kinetic_energy(ex.model, y.head(n), y.tail(n)) + potential_energy(ex.model, y.head(n)); };
  const double E0 = energy(), h = 1e-4;
  double scale = 0.0;
  for (int s = 0; s < 2000; ++s) {
    stepper.step(s * h, y, h);
    scale = std::max(scale, kinetic_energy(ex.model, y.head(n), y.tail(n)));
  }
  REQUIRE(scale > 0.0);
  INFO("energy " << E0 << " -> " << energy() << ", largest kinetic energy " << scale);
  CHECK(std::abs(energy() - E0) < 1e-6 * scale);
}

TEST_CASE("workspace rk4: a step allocates nothing", "[ffrf_invariants][workspace]") {
  FlexibleSliderCrankParameters p;
  p.elements = 20;
  p.modes = 10;
  const FlexibleExample ex = flexible_slider_crank(p, make_modal_ffrf_body);
  bench::WorkspaceRk4 stepper(ex.model);
  VecX y = state_of(ex);
  stepper.step(0.0, y, 1e-6);  // warm-up
  g_mallocs = g_news = 0;
  g_counting = true;
  for (int s = 1; s <= 20; ++s) stepper.step(s * 1e-6, y, 1e-6);
  g_counting = false;
  INFO("operator new: " << g_news << ", malloc/calloc/realloc: " << g_mallocs << " in 20 steps");
  CHECK(g_news == 0);
  CHECK(g_mallocs == 0);
  CHECK(y.allFinite());
}

TEST_CASE("workspace rk4: profiling times each part of a step and changes nothing", "[ffrf_invariants][workspace]") {
  FlexibleSliderCrankParameters p;
  p.elements = 12;
  p.modes = 4;
  const FlexibleExample ex = flexible_slider_crank(p, make_modal_ffrf_body);
  bench::WorkspaceRk4 plain(ex.model), profiled(ex.model);
  const double h = 1e-6;
  VecX y = state_of(ex), z = state_of(ex);
  for (int s = 0; s < 20; ++s) plain.step(s * h, y, h);
  profiled.set_profiling(true);
  const auto start = std::chrono::steady_clock::now();
  for (int s = 0; s < 20; ++s) profiled.step(s * h, z, h);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK_CLOSE(z, y, (Tolerance{0, 0}), "the same steps with profiling on");

  const bench::StepProfile& parts = profiled.profile();
  INFO("M(q) " << parts.mass_matrix << " s, forces " << parts.body_forces << " s, constraints "
               << parts.constraints << " s, solve " << parts.solve << " s, of " << elapsed << " s");
  CHECK(parts.mass_matrix > 0);
  CHECK(parts.body_forces > 0);
  CHECK(parts.constraints > 0);
  CHECK(parts.solve > 0);
  // Disjoint intervals inside the timed loop, read off the same clock.
  CHECK(parts.mass_matrix + parts.body_forces + parts.constraints + parts.solve <= elapsed);
  CHECK(plain.profile().solve == 0);  // off by default
  profiled.set_profiling(false);
  CHECK(profiled.profile().solve == 0);  // switching resets
}

TEST_CASE("workspace rk4: unsupported models and a blown-up state are named errors", "[ffrf_invariants][workspace]") {
  FlexibleSliderCrankParameters p;
  p.elements = 6;
  p.modes = 2;
  const FlexibleExample nodal = flexible_slider_crank(p, make_ffrf_body);
  CHECK_THROWS_MENTIONING(bench::WorkspaceRk4{nodal.model}, std::invalid_argument, "not a ModalFfrfBody");
  FlexibleExample ex = flexible_slider_crank(p, make_modal_ffrf_body);
  bench::WorkspaceRk4 stepper(ex.model);
  VecX y = state_of(ex);
  y(4) = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_MENTIONING(stepper.step(0.0, y, 1e-6), IntegrationError, "NaN or Inf");
}

TEST_CASE("workspace rk4: a parallelogram with a redundant third crank moves as module 4 moves it, through flat positions",
          "[ffrf_invariants][workspace]") {
  // Three cranks of 0.2 m at x = 0, 0.3, 0.6 m under a coupler: C_q has 12 rows of rank 11, so
  // the LU of the augmented matrix fails, and solve_augmented solves each evaluation. Released at
  // 1 rad, the cranks swing through both flat positions, theta = 0 and -pi (C_q loses one more
  // rank at each), to the far end of the swing at -pi - 1 in 0.9 s. (WorkspaceRk4 does not project:
  // on the way back, near -pi, the drift of 1e-9 makes the dependent rows' accelerations
  // contradict each other, and solve_augmented says so, as simulate without stabilisation would.) The parallelogram branch's
  // closed form: theta'' = -G cos(theta) / J.
  const double a = 0.2, d = 0.6, m_crank = 0.6, J_crank = m_crank * a * a / 12, m_coupler = 1.8;
  Model model;
  model.set_gravity(Vec2(0, -9.81));
  const BodyId coupler = model.add_body("coupler", m_coupler, m_coupler * d * d / 12);
  VecX q(12);
  q.head<3>() << d / 2 + a * std::cos(1.0), a * std::sin(1.0), 0.0;
  for (int k = 0; k < 3; ++k) {
    const double x = k * d / 2;
    const BodyId crank = model.add_body("crank " + std::to_string(k), m_crank, J_crank);
    model.add_revolute("pivot " + std::to_string(k), model.add_point(ground, Vec2(x, 0), "ground " + std::to_string(k)),
                       model.add_point(crank, Vec2(-a / 2, 0), "foot " + std::to_string(k)));
    model.add_revolute("top " + std::to_string(k), model.add_point(crank, Vec2(a / 2, 0), "head " + std::to_string(k)),
                       model.add_point(coupler, Vec2(x - d / 2, 0), "coupler at " + std::to_string(k)));
    q.segment<3>(3 + 3 * k) << x + a / 2 * std::cos(1.0), a / 2 * std::sin(1.0), 1.0;
  }
  const double J = 3 * (J_crank + m_crank * a * a / 4) + m_coupler * a * a, G = 9.81 * (3 * m_crank * a / 2 + m_coupler * a);
  const double h = 1e-3;
  const int steps = 900;
  bench::WorkspaceRk4 stepper(model);
  VecX y = VecX::Zero(24);
  y.head(12) = q;
  double theta = 1.0, w = 0.0, lowest = theta, error = 0;
  auto f = [&](double th) { return -G * std::cos(th) / J; };
  for (int s = 0; s < steps; ++s) {
    stepper.step(s * h, y, h);
    const double k1 = f(theta), l1 = w, k2 = f(theta + h / 2 * l1), l2 = w + h / 2 * k1;
    const double k3 = f(theta + h / 2 * l2), l3 = w + h / 2 * k2, k4 = f(theta + h * l3), l4 = w + h * k3;
    theta += h / 6 * (l1 + 2 * l2 + 2 * l3 + l4);
    w += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    lowest = std::min(lowest, theta);
    for (int k = 0; k < 3; ++k) error = std::max(error, std::abs(y(5 + 3 * k) - theta));
  }
  CAPTURE(error, lowest);
  REQUIRE(lowest < -M_PI - 0.9);  // through both flat positions
  CHECK(error <= 1e-7);
}
