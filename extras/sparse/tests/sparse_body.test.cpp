// Project tests (not graded) of the flexible body made from an imported FE model
// (fmbd/sparse_body.hpp, module 8 extra): make_sparse_modal_ffrf_body, sparse_ffrf_basis,
// sparse_rigid_body_modes, frame_for_placement of a SparseFeModel, and the sparse constructor of
// FfrfInvariants.
//
// Oracles, none of them numbers printed by the code under test:
//  - a beam of module 5 written to Matrix Market files and read back is the same body as the
//    dense route of modules 6-8 (flexible_body_data of the FeModel, ModalFfrfBody and the nodal
//    FfrfBody) given the same basis: mass matrix, body forces, energies and node markers at random
//    states to round-off, also with the DOFs numbered in a shuffled order and with an extra node
//    that has no DOF in the matrices; its centroid and mass in closed form;
//  - a frame lattice of a few thousand DOFs (lumped mass, for which the FFRF is exactly
//    Lagrangian, module 8 README section 2), simulated free in space: the linear and angular
//    momentum and the FE energy 1/2 w^T M w + 1/2 u^T K u, all computed here from the nodal
//    velocities and the sparse M and K, stay constant to the integrator's error; hinged at a
//    corner node under gravity, the FE energy with the gravity potential of the nodal masses stays
//    constant and the hinge holds;
//  - every argument fault throws std::invalid_argument naming it.
// The dense route calls the exercise functions (reference), so this program links the reference
// stages.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

#include "fmbd/fe_assembly.hpp"
#include "fmbd/ffrf.hpp"
#include "fmbd/ffrf_invariants.hpp"
#include "fmbd/flexible_body.hpp"
#include "fmbd/matrix_market.hpp"
#include "fmbd/reduction.hpp"
#include "fmbd/simulation.hpp"
#include "fmbd/sparse_body.hpp"
#include "fmbd/sparse_modal.hpp"
#include "fmbd/sparse_reduction.hpp"
#include "grading.hpp"
#include "random_states.hpp"

using namespace fmbd;
using fmbd::testing::Random;
using fmbd::testing::random_state;
using fmbd::testing::reach;
using fmbd::testing::largest_translation;
using fmbd::testing::Tolerance;

namespace {

namespace fs = std::filesystem;

const Section kSteel = square_section(210e9, 7850.0, 0.01);
const Section kPolymer = square_section(2e9, 1200.0, 0.01);

Mat2 rot(double a) { return (Mat2() << std::cos(a), -std::sin(a), std::sin(a), std::cos(a)).finished(); }
Mat2 tilde() { return (Mat2() << 0.0, -1.0, 1.0, 0.0).finished(); }
double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// A directory of its own under the system's temporary directory, removed at the end.
class ScratchDir {
 public:
  ScratchDir() {
    static std::atomic<int> serial{0};
    const std::string name = "fmbd-sparse-body-" + std::to_string(::getpid()) + "-" + std::to_string(serial++);
    root_ = fs::temp_directory_path() / name;
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    fs::remove_all(root_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  std::string operator/(const std::string& name) const { return (root_ / name).string(); }

 private:
  fs::path root_;
};

// Writes M and K of `fe` with row r holding DOF order[r] of the FE model (3k + d), and the node
// table with `extra` nodes after the model's that have no DOF in the matrices; reads them back.
SparseFeModel export_and_import(const FeModel& fe, MassMatrixType type, const std::vector<int>& order,
                                const std::vector<Vec2>& extra = {}) {
  const SparseFeMatrices full = sparse_fe_matrices(fe, type);
  const int n = fe.num_dofs();
  REQUIRE(static_cast<int>(order.size()) == n);
  NodeTable table;
  table.nodes = fe.nodes();
  table.dofs.assign(fe.num_nodes(), NodeDofNumbers{-1, -1, -1});
  for (int r = 0; r < n; ++r) table.dofs[order[r] / 3][order[r] % 3] = r;
  for (const Vec2& x : extra) {
    table.nodes.push_back(x);
    table.dofs.push_back({-1, -1, -1});
  }
  ScratchDir dir;
  write_matrix_market(dir / "M.mtx", sparse_block(full.M, order, order));
  write_matrix_market(dir / "K.mtx", sparse_block(full.K, order, order));
  write_node_table(dir / "nodes.txt", table);
  return load_sparse_fe_model(dir / "M.mtx", dir / "K.mtx", dir / "nodes.txt");
}

std::vector<int> identity_order(int n) {
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  return order;
}

std::vector<int> shuffled_order(int n, unsigned seed) {
  std::vector<int> order = identity_order(n);
  std::shuffle(order.begin(), order.end(), std::mt19937(seed));
  return order;
}

// The basis with its rows in the file's order: row r is row order[r] of `basis`.
ReducedBasis reordered(const ReducedBasis& basis, const std::vector<int>& order) {
  ReducedBasis out = basis;
  for (std::size_t r = 0; r < order.size(); ++r) out.Phi.row(static_cast<Eigen::Index>(r)) = basis.Phi.row(order[r]);
  return out;
}

Tolerance relative_to(const MatX& expected, double rel = 1e-10) {
  return Tolerance{rel * std::max(expected.cwiseAbs().maxCoeff(), 1e-300), rel};
}

void check_same_marker(const NodeMarker& a, const NodeMarker& b, const std::string& what) {
  CHECK_CLOSE(a.pose, b.pose, relative_to(b.pose), what + ": node pose (joints attach here)");
  CHECK_CLOSE(a.velocity, b.velocity, relative_to(b.velocity), what + ": node velocity");
  CHECK_CLOSE(a.G, b.G, relative_to(b.G), what + ": node Jacobian G_k");
  CHECK_CLOSE(a.convective, b.convective, relative_to(b.convective), what + ": convective acceleration");
}

// Compares the imported body with a reference body of the same nodes (the first `nodes` ones)
// at random states.
void check_same_body(const DeformableBody& imported, const DeformableBody& reference, const ModalBodyData& d,
                     int nodes, unsigned seed, const std::string& what) {
  Random rnd(seed);
  REQUIRE(imported.num_modes() == reference.num_modes());
  CHECK_NEAR(imported.mass(), reference.mass(), (Tolerance{0.0, 1e-12}), what + ": mass");
  CHECK_NEAR(imported.inertia(), reference.inertia(), (Tolerance{0.0, 1e-12}), what + ": inertia about the centroid");
  const VecX rest = VecX::Zero(3 + reference.num_modes());
  const MatX M_bar = reference.mass_matrix(rest);
  CHECK_CLOSE(imported.mass_matrix(rest), M_bar, relative_to(M_bar), what + ": M_bar");
  for (int k = 0; k < nodes; ++k)
    CHECK_CLOSE(imported.node_position(k), reference.node_position(k), (Tolerance{1e-14, 1e-12}),
                what + ": x_bar_k, the node shifted by the centroid");
  for (int trial = 0; trial < 4; ++trial) {
    CAPTURE(trial);
    VecX q, qd;
    random_state(d, rnd, q, qd);
    const Vec2 g = rnd.vec2(-10.0, 10.0);
    const MatX M = reference.mass_matrix(q);
    CHECK_CLOSE(imported.mass_matrix(q), M, relative_to(M), what + ": M(q)");
    const VecX Q = reference.body_forces(q, qd, g);
    CHECK_CLOSE(imported.body_forces(q, qd, g), Q, relative_to(Q), what + ": body forces");
    CHECK_NEAR(imported.kinetic_energy(q, qd), reference.kinetic_energy(q, qd), (Tolerance{0.0, 1e-10}),
               what + ": kinetic energy");
    const double V_scale = reference.mass() * g.norm() * (q.head<2>().norm() + reach(d));
    CHECK_NEAR(imported.potential_energy(q, g), reference.potential_energy(q, g), (Tolerance{1e-10 * V_scale, 1e-10}),
               what + ": potential energy");
    for (int k = 0; k < nodes; ++k) {
      CAPTURE(k);
      check_same_marker(imported.node_marker(k, q, qd), reference.node_marker(k, q, qd), what);
    }
  }
}

// A beam off the origin and turned, so that the centroid shift matters; Craig-Bampton on both
// end nodes made FFRF-ready by module 6's ffrf_basis (reference), as module 7's examples do.
struct Beam {
  FeModel fe = straight_beam(1.2, 10, kSteel, Vec2(0.3, -0.2), 0.4);
  FeMatrices matrices = assemble(fe, MassMatrixType::consistent);
  ReducedBasis cb = craig_bampton(matrices.K, matrices.M, node_dofs({0, 10}), 3);
  ReducedBasis basis = ffrf_basis(fe, matrices, cb);
  std::shared_ptr<const FlexibleBodyData> dense =
      std::make_shared<const FlexibleBodyData>(flexible_body_data(fe, MassMatrixType::consistent, basis));
};

}  // namespace

// ---- 1. the same body as the dense route ------------------------------------------------------------

TEST_CASE("sparse body: a beam through Matrix Market files is the dense route's body", "[sparse_body]") {
  const Beam beam;
  const SparseFeModel model =
      export_and_import(beam.fe, MassMatrixType::consistent, identity_order(beam.fe.num_dofs()));
  const auto body = make_sparse_modal_ffrf_body(model, beam.basis);
  const ModalBodyData& d = body->data();
  const int N = beam.fe.num_nodes();
  REQUIRE(body->num_nodes() == N);
  REQUIRE(body->num_modes() == beam.dense->num_modes());

  // Closed forms: the mass rho A L, the centroid at mid-span.
  const double m = kSteel.rho * kSteel.A * 1.2;
  const Vec2 centre = Vec2(0.3, -0.2) + 0.6 * Vec2(std::cos(0.4), std::sin(0.4));
  CHECK_NEAR(d.mass, m, (Tolerance{0.0, 1e-12}), "m = t_x^T M t_x = rho A L");
  CHECK_CLOSE(sparse_rigid_body_modes(model).centroid, centre, (Tolerance{1e-14, 0}), "centroid at mid-span");
  for (int k = 0; k < N; ++k)
    CHECK_CLOSE(d.nodes[k].x_bar, Vec2(beam.fe.nodes()[k] - centre), (Tolerance{1e-14, 0}),
                "x_bar_k = x_k - c: the nodes are shifted to the centroid");
  CHECK_CLOSE(frame_for_placement(model, Vec2(1.0, 2.0), 0.7),
              frame_for_placement(beam.fe, MassMatrixType::consistent, Vec2(1.0, 2.0), 0.7), (Tolerance{1e-14, 1e-14}),
              "frame_for_placement as module 7's");

  // The data of the dense route.
  const FlexibleBodyData& e = *beam.dense;
  CHECK_NEAR(d.inertia, e.inertia, (Tolerance{0.0, 1e-12}), "J");
  CHECK_CLOSE(d.basis.Phi, e.basis.Phi, relative_to(e.basis.Phi, 1e-12), "the basis with the rigid modes about c");
  CHECK_CLOSE(d.basis.M_bar, e.basis.M_bar, relative_to(e.basis.M_bar), "M_bar = Phi^T M Phi");
  CHECK_CLOSE(d.basis.K_bar, e.basis.K_bar, relative_to(e.basis.K_bar), "K_bar = Phi^T K Phi");
  CHECK_CLOSE(d.M_ff, e.M_ff, relative_to(e.M_ff), "M_ff");
  CHECK_CLOSE(d.K_ff, e.K_ff, relative_to(e.K_ff), "K_ff");
  CHECK_CLOSE(d.S_f, e.S_f, (Tolerance{1e-12 * m, 0.0}), "S_f");

  // The invariants of the dense body, from the sparse M.
  const ModalFfrfBody dense_fast(beam.dense);
  const FfrfInvariants& ours = body->invariants();
  const FfrfInvariants& theirs = dense_fast.invariants();
  CHECK_NEAR(ours.J_0(), theirs.J_0(), (Tolerance{0.0, 1e-12}), "J_0");
  CHECK_CLOSE(ours.P_1(), theirs.P_1(), relative_to(theirs.P_1()), "P_1");
  CHECK_CLOSE(ours.H_1(), theirs.H_1(), relative_to(theirs.H_1()), "H_1");

  const FfrfBody nodal(beam.dense);
  check_same_body(*body, dense_fast, d, N, 11, "against the dense ModalFfrfBody");
  check_same_body(*body, nodal, d, N, 12, "against the nodal FfrfBody");
  // Module 7's intuitive body works on the imported data too.
  const auto data = std::make_shared<const ImportedBodyData>(imported_body_data(model, beam.basis));
  CHECK(data->dofs == model.table.dofs);
  check_same_body(IntuitiveBody(data), *make_intuitive_body(beam.dense), d, N, 13,
                  "intuitive body of the imported data");
}

TEST_CASE("sparse body: shuffled DOF numbers and a node without DOFs", "[sparse_body]") {
  const Beam beam;
  const int n = beam.fe.num_dofs(), N = beam.fe.num_nodes();
  const std::vector<int> order = shuffled_order(n, 77);
  const Vec2 marker(0.9, 0.6);  // a point with no DOF in the matrices: it moves with the frame
  const SparseFeModel model = export_and_import(beam.fe, MassMatrixType::consistent, order, {marker});
  REQUIRE(model.num_nodes() == N + 1);
  const auto body = make_sparse_modal_ffrf_body(model, reordered(beam.basis, order));
  REQUIRE(body->num_nodes() == N + 1);
  check_same_body(*body, ModalFfrfBody(beam.dense), body->data(), N, 21, "shuffled, against ModalFfrfBody");
  check_same_body(*body, FfrfBody(beam.dense), body->data(), N, 22, "shuffled, against FfrfBody");

  // The extra node: zero elastic rows, so it is the rigid point x_bar = x - c of the frame.
  const Vec2 centre = Vec2(0.3, -0.2) + 0.6 * Vec2(std::cos(0.4), std::sin(0.4));
  const Vec2 x_bar = marker - centre;
  CHECK_CLOSE(body->node_position(N), x_bar, (Tolerance{1e-14, 0}), "x_bar of the extra node");
  CHECK(body->data().nodes[N].Phi_t.isZero(0.0));
  CHECK(body->data().nodes[N].Phi_psi.isZero(0.0));
  Random rnd(23);
  VecX q, qd;
  random_state(body->data(), rnd, q, qd);
  const NodeMarker p = body->node_marker(N, q, qd);
  const Mat2 A = rot(q(2));
  CHECK_CLOSE(p.pose, Vec3((q.head<2>() + A * x_bar).x(), (q.head<2>() + A * x_bar).y(), q(2)), (Tolerance{1e-13, 0}),
              "r = R + A x_bar, phi = theta");
  const Vec2 v = qd.head<2>() + qd(2) * A * tilde() * x_bar;
  CHECK_CLOSE(p.velocity, Vec3(v.x(), v.y(), qd(2)), (Tolerance{1e-12, 0}), "rigid velocity of the frame point");
  CHECK(p.G.rightCols(body->num_modes()).isZero(0.0));

  // The basis of the sparse route in the file's order is the dense one reordered.
  const ReducedBasis cb = reordered(beam.cb, order);
  const ReducedBasis ours = sparse_ffrf_basis(model, cb);
  const ReducedBasis theirs = reordered(beam.basis, order);
  REQUIRE(ours.size() == theirs.size());
  CHECK(ours.num_rigid == 3);
  CHECK_CLOSE(VecX(ours.K_bar.diagonal()), VecX(theirs.K_bar.diagonal()),
              (Tolerance{1e-9 * theirs.K_bar.diagonal().maxCoeff(), 1e-9}), "the same elastic frequencies");
  const MatX M_bar_expected = theirs.M_bar.diagonal().asDiagonal();
  CHECK_CLOSE(ours.M_bar, M_bar_expected, (Tolerance{1e-10 * theirs.M_bar.maxCoeff(), 0}), "diag(m, m, J, 1, ...)");
  const MatX overlap = ours.Phi.rightCols(ours.num_elastic()).transpose() *
                       (model.M * theirs.Phi.rightCols(theirs.num_elastic()));
  CHECK_CLOSE(MatX(overlap.cwiseAbs()), MatX::Identity(overlap.rows(), overlap.cols()), (Tolerance{1e-8, 0}),
              "the same elastic shapes up to sign");
}

// ---- 2. physics of a large imported body in a Model ------------------------------------------------

namespace {

// A lumped-mass polymer lattice (E = 2 GPa, 1200 kg/m^3) 4 m x 2 m of 40 x 20 cells (2583 DOFs),
// exported and imported, Craig-Bampton on its four corner nodes with 6 fixed-interface modes,
// made FFRF-ready: n_f = 15, omega_max about 4600 rad/s, so that RK4 takes steps of 1e-5 s.
struct Lattice {
  static constexpr int cx = 40, cy = 20;
  SparseFeModel model;
  ReducedBasis basis;
  std::shared_ptr<const ModalFfrfBody> body;
  Vec2 centre;            // sum m_k x_k / m from the nodal masses (lumped M is diagonal)
  double mass = 0.0;
  double omega_max = 0.0;  // highest frequency of the reduced body
  Lattice() {
    const FeModel fe = frame_lattice(cx, cy, 0.1, 0.1, kPolymer);
    model = export_and_import(fe, MassMatrixType::lumped, identity_order(fe.num_dofs()));
    const int corners[4] = {0, cx, cy * (cx + 1), cy * (cx + 1) + cx};
    std::vector<int> interface;
    for (int k : corners)
      for (int d = 0; d < 3; ++d) interface.push_back(model.dof(k, static_cast<NodeDof>(d)));
    basis = sparse_ffrf_basis(model, sparse_craig_bampton(model.K, model.M, interface, 6));
    body = make_sparse_modal_ffrf_body(model, basis);
    Vec2 first = Vec2::Zero();
    for (int k = 0; k < model.num_nodes(); ++k) {
      const double m_k = model.M.coeff(model.dof(k, NodeDof::ux), model.dof(k, NodeDof::ux));
      mass += m_k;
      first += m_k * model.table.nodes[k];
    }
    centre = first / mass;
    omega_max = std::sqrt(basis.K_bar.diagonal().maxCoeff());
  }
};

const Lattice& lattice() {
  static const Lattice instance;
  return instance;
}

// FE quantities of the body at (q_j, q_j_dot), from the nodes, the basis and the sparse M and K:
// w = the nodal velocities in frame j, then T = 1/2 w^T M w, the strain energy 1/2 u^T K u, the
// momentum conjugate to R (global) and the angular momentum about the global origin.
struct FeState {
  double kinetic = 0, strain = 0, gravity_potential = 0;
  Vec2 momentum = Vec2::Zero();
  double angular_momentum = 0;
};

FeState fe_state(const Lattice& L, const VecX& q, const VecX& qd, const Vec2& g) {
  const int n_f = L.basis.num_elastic(), n = L.model.num_dofs();
  const MatX Phi_f = L.basis.Phi.rightCols(n_f);
  const VecX u = Phi_f * q.tail(n_f), u_dot = Phi_f * qd.tail(n_f);
  const Mat2 A = rot(q(2));
  const Vec2 v_j = A.transpose() * qd.head<2>();
  const double w = qd(2);
  // The nodal velocities w, the rotation field (I~ x, 1) and the translation fields t_x, t_y.
  VecX vel = VecX::Zero(n), spin = VecX::Zero(n), t_x = VecX::Zero(n), t_y = VecX::Zero(n);
  FeState s;
  for (int k = 0; k < L.model.num_nodes(); ++k) {
    const int ix = L.model.dof(k, NodeDof::ux), iy = L.model.dof(k, NodeDof::uy), ip = L.model.dof(k, NodeDof::psi);
    const Vec2 x = L.model.table.nodes[k] - L.centre + Vec2(u(ix), u(iy));
    const Vec2 rate = v_j + w * tilde() * x + Vec2(u_dot(ix), u_dot(iy));
    vel(ix) = rate.x();
    vel(iy) = rate.y();
    vel(ip) = w + u_dot(ip);
    spin(ix) = -x.y();
    spin(iy) = x.x();
    spin(ip) = 1.0;
    t_x(ix) = 1.0;
    t_y(iy) = 1.0;
    const Vec2 r = q.head<2>() + A * x;
    s.gravity_potential -= L.model.M.coeff(ix, ix) * g.dot(r);  // lumped: diagonal nodal masses
  }
  const VecX Mw = L.model.M * vel;
  s.kinetic = 0.5 * vel.dot(Mw);
  s.strain = 0.5 * u.dot(L.model.K * u);
  s.momentum = A * Vec2(t_x.dot(Mw), t_y.dot(Mw));
  s.angular_momentum = spin.dot(Mw) + cross(q.head<2>(), s.momentum);
  return s;
}

}  // namespace

TEST_CASE("sparse body: a free imported lattice keeps its momentum and energy", "[sparse_body][physics]") {
  const Lattice& L = lattice();
  REQUIRE(L.model.num_dofs() == 3 * (Lattice::cx + 1) * (Lattice::cy + 1));
  const int n_f = L.body->num_modes();
  INFO(L.model.num_dofs() << " DOFs, n_f = " << n_f << ", omega_max = " << L.omega_max
                          << " rad/s, omega_1 = " << std::sqrt(L.basis.K_bar(3, 3)) << " rad/s");
  CHECK(n_f == 4 * 3 + 6 - 3);
  CHECK_NEAR(L.body->mass(), L.mass, (Tolerance{0.0, 1e-12}), "m: the sum of the nodal masses");
  CHECK_CLOSE(sparse_rigid_body_modes(L.model).centroid, L.centre, (Tolerance{1e-13, 0}), "centroid");

  Model m;
  const BodyId b = m.add_flexible_body("lattice", L.body, frame_for_placement(L.model, Vec2(0.5, -0.3), 0.2));
  // Spinning at 10 rad/s, drifting, with every elastic coordinate moving (nodal rates ~0.05 m/s).
  VecX q0 = m.initial_guess(), qd0 = VecX::Zero(m.num_coordinates());
  qd0.head<3>() << 0.3, -0.2, 10.0;
  Random rnd(31);
  const VecX f = rnd.vector(n_f, -1.0, 1.0);
  qd0.tail(n_f) = f * (0.05 / largest_translation(L.body->data(), f));
  REQUIRE(m.offset(b) == 0);

  // RK4 at h omega_max = 0.05: far inside its stability limit (2.8), and it takes (h omega)^6 / 72
  // of a mode's energy per step, at most 2e-10 (the stiffest mode) and 1e-16 for the lowest one.
  SimulationOptions o;
  o.integrator = Integrator::rk4;
  o.step = 0.05 / L.omega_max;
  o.output_interval = 1e-3;
  const double t_end = 0.1;
  const Trajectory tr = simulate(m, q0, qd0, 0.0, t_end, o);
  REQUIRE(tr.t.size() > 50);

  const Vec2 g = Vec2::Zero();
  const FeState s0 = fe_state(L, tr.q.front(), tr.qd.front(), g);
  const double E0 = s0.kinetic + s0.strain;
  const double size = reach(L.body->data());
  const double p_scale = L.mass * (qd0.head<2>().norm() + qd0(2) * size), h_scale = p_scale * size;
  double drift_E = 0, drift_p = 0, drift_h = 0, elastic = 0;
  for (std::size_t i = 0; i < tr.t.size(); ++i) {
    const FeState s = fe_state(L, tr.q[i], tr.qd[i], g);
    CHECK_NEAR(tr.energy[i], s.kinetic + s.strain, (Tolerance{1e-10 * E0, 0.0}),
               "the Model's energy is the FE energy 1/2 w^T M w + 1/2 u^T K u");
    drift_E = std::max(drift_E, std::abs(s.kinetic + s.strain - E0));
    drift_p = std::max(drift_p, (s.momentum - s0.momentum).norm());
    drift_h = std::max(drift_h, std::abs(s.angular_momentum - s0.angular_momentum));
    elastic = std::max(elastic, s.strain);
  }
  INFO("energy " << E0 << " J, drift " << drift_E << " J; momentum drift " << drift_p << ", angular " << drift_h
                 << "; largest strain energy " << elastic << " J over " << tr.steps << " steps");
  CHECK(elastic > 1e-4 * E0);  // the lattice does deform
  // The elastic energy (at most twice the largest strain energy) losing (h omega_max)^6 / 72 per
  // step bounds the integrator's share; the rigid motion (h theta_dot = 1e-4) adds nothing visible.
  const double bound = tr.steps * std::pow(o.step * L.omega_max, 6) / 72 * 2 * elastic + 1e-12 * E0;
  CHECK(drift_E < bound);
  CHECK(drift_p < 1e-10 * p_scale);
  CHECK(drift_h < 1e-10 * h_scale);
}

TEST_CASE("sparse body: an imported lattice hinged at a corner node swings with constant energy",
          "[sparse_body][physics]") {
  const Lattice& L = lattice();
  Model m;
  const Vec2 gravity(0.0, -9.81);
  m.set_gravity(gravity);
  // The lattice's own coordinates in place: node 0 (a corner) at the origin, hinged there.
  const BodyId b = m.add_flexible_body("lattice", L.body, frame_for_placement(L.model, Vec2::Zero(), 0.0));
  m.add_revolute("hinge", m.add_point(ground, Vec2::Zero(), "O"), m.add_node_point(b, 0, "corner"));
  const VecX q0 = m.initial_guess(), qd0 = VecX::Zero(m.num_coordinates());
  CHECK_CLOSE(L.body->node_marker(0, q0, qd0).pose, Vec3::Zero(), (Tolerance{1e-14, 0}), "node 0 at the hinge");

  SimulationOptions o;
  o.integrator = Integrator::rk4;
  o.step = 0.05 / L.omega_max;
  o.stabilisation = Stabilisation::none;
  o.output_interval = 1e-3;
  const double t_end = 0.1;
  const Trajectory tr = simulate(m, q0, qd0, 0.0, t_end, o);
  const FeState s0 = fe_state(L, tr.q.front(), tr.qd.front(), gravity);
  const double scale = L.mass * 9.81 * reach(L.body->data());  // m g times the size of the body
  double drift = 0, worst_c = 0, fall = 0, elastic = 0;
  for (std::size_t i = 0; i < tr.t.size(); ++i) {
    const FeState s = fe_state(L, tr.q[i], tr.qd[i], gravity);
    const double E = s.kinetic + s.strain + s.gravity_potential;
    CHECK_NEAR(tr.energy[i] - tr.energy.front(), E - (s0.kinetic + s0.strain + s0.gravity_potential),
               (Tolerance{1e-10 * scale, 0.0}), "the Model's energy change is the FE energy change");
    drift = std::max(drift, std::abs(E - (s0.kinetic + s0.strain + s0.gravity_potential)));
    worst_c = std::max(worst_c, tr.position_drift[i]);
    fall = std::max(fall, s.kinetic);
    elastic = std::max(elastic, s.strain);
  }
  INFO("kinetic energy reached " << fall << " J, strain energy " << elastic << " J; energy drift " << drift
                                 << " J; worst |C| " << worst_c << " m; " << tr.steps << " steps of " << o.step
                                 << " s");
  CHECK(fall > 5e-3 * scale);     // it does swing
  CHECK(elastic > 1e-6 * scale);  // and bend
  // RK4's loss as in the free case.
  CHECK(drift < tr.steps * std::pow(o.step * L.omega_max, 6) / 72 * 2 * elastic + 1e-12 * scale);
  CHECK(worst_c < 1e-9);
}

// ---- 3. argument checks ------------------------------------------------------------------------------

TEST_CASE("sparse body: faults of the model and the basis are named", "[sparse_body]") {
  const Beam beam;
  const int n = beam.fe.num_dofs();
  const SparseFeModel model = export_and_import(beam.fe, MassMatrixType::consistent, identity_order(n));

  ReducedBasis no_rigid = beam.cb;  // sparse_craig_bampton's basis has num_rigid = 0
  CHECK_THROWS_MENTIONING(make_sparse_modal_ffrf_body(model, no_rigid), std::invalid_argument, "num_rigid = 3");
  ReducedBasis short_rows = beam.basis;
  short_rows.Phi.conservativeResize(n - 1, Eigen::NoChange);
  CHECK_THROWS_MENTIONING(make_sparse_modal_ffrf_body(model, short_rows), std::invalid_argument, "32 rows");
  CHECK_THROWS_MENTIONING(sparse_ffrf_basis(model, short_rows), std::invalid_argument, "the basis has 32 rows");
  ReducedBasis two_columns = beam.basis;
  two_columns.Phi = beam.basis.Phi.leftCols(2);
  CHECK_THROWS_MENTIONING(make_sparse_modal_ffrf_body(model, two_columns), std::invalid_argument, "2 columns");
  ReducedBasis zero_column = beam.basis;
  zero_column.Phi.conservativeResize(Eigen::NoChange, beam.basis.size() + 1);
  zero_column.Phi.rightCols(1).setZero();
  CHECK_THROWS_MENTIONING(make_sparse_modal_ffrf_body(model, zero_column), std::invalid_argument, "no M-norm");
  ReducedBasis repeated = zero_column;
  repeated.Phi.rightCols(1) = beam.basis.Phi.col(4);
  CHECK_THROWS_MENTIONING(make_sparse_modal_ffrf_body(model, repeated), std::invalid_argument, "linearly dependent");

  SparseFeModel bad = model;
  bad.K = sparse_block(model.K, identity_order(n - 1), identity_order(n - 1));
  CHECK_THROWS_MENTIONING(make_sparse_modal_ffrf_body(bad, beam.basis), std::invalid_argument,
                          "M is 33 x 33 and K is 32 x 32");
  bad = model;
  bad.table.dofs.pop_back();
  CHECK_THROWS_MENTIONING(make_sparse_modal_ffrf_body(bad, beam.basis), std::invalid_argument,
                          "11 coordinates but 10 sets");
  bad = model;
  bad.table.dofs[4][1] = n;
  CHECK_THROWS_MENTIONING(make_sparse_modal_ffrf_body(bad, beam.basis), std::invalid_argument,
                          "node 4: the DOF number 33 of u_y is outside -1 .. 32");
  bad = model;
  bad.table.dofs[5][2] = bad.table.dofs[2][0];
  CHECK_THROWS_MENTIONING(make_sparse_modal_ffrf_body(bad, beam.basis), std::invalid_argument,
                          "row 6 is named twice in the node table (node 2 u_x and node 5 psi)");
  bad = model;
  bad.table.dofs[3][2] = -1;
  CHECK_THROWS_MENTIONING(make_sparse_modal_ffrf_body(bad, beam.basis), std::invalid_argument,
                          "row 11 of M and K belongs to no node");
  bad = model;
  bad.table.nodes[7].x() = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_MENTIONING(frame_for_placement(bad, Vec2::Zero(), 0.0), std::invalid_argument,
                          "node 7 has coordinates that are not finite");
  bad = model;
  bad.table = NodeTable{};
  CHECK_THROWS_MENTIONING(sparse_rigid_body_modes(bad), std::invalid_argument, "no nodes");

  // Node 3 without u_x in the matrices (as after a roller support): the translational masses differ.
  std::vector<int> keep;
  for (int r = 0; r < n; ++r)
    if (r != 9) keep.push_back(r);
  SparseFeModel roller;
  roller.M = sparse_block(model.M, keep, keep);
  roller.K = sparse_block(model.K, keep, keep);
  roller.table.nodes = model.table.nodes;
  for (int k = 0; k < model.num_nodes(); ++k) {
    NodeDofNumbers d = model.table.dofs[k];
    for (int& r : d) r = r == 9 ? -1 : (r > 9 ? r - 1 : r);
    roller.table.dofs.push_back(d);
  }
  CHECK_THROWS_MENTIONING(sparse_rigid_body_modes(roller), std::invalid_argument, "translational masses differ");
}

TEST_CASE("sparse body: the sparse constructor of the invariants checks its DOF numbers", "[sparse_body]") {
  const Beam beam;
  const SparseFeModel model =
      export_and_import(beam.fe, MassMatrixType::consistent, identity_order(beam.fe.num_dofs()));
  const auto data = std::make_shared<const ImportedBodyData>(imported_body_data(model, beam.basis));
  // The DOF numbers must match the node rows of the data.
  std::vector<NodeDofNumbers> dofs = model.table.dofs;
  dofs[6][2] = -1;
  CHECK_THROWS_MENTIONING(FfrfInvariants(model.M, dofs, *data), std::invalid_argument,
                          "row 20 of M_FE belongs to no node");
  dofs = model.table.dofs;
  dofs.pop_back();
  CHECK_THROWS_MENTIONING(FfrfInvariants(model.M, dofs, *data), std::invalid_argument,
                          "10 sets of DOF numbers for 11 nodes");
  // A DOF without a row in M must not move elastically.
  const std::vector<int> keep = [] {
    std::vector<int> k;
    for (int r = 0; r < 33; ++r)
      if (r != 20) k.push_back(r);
    return k;
  }();
  dofs = model.table.dofs;
  dofs[6][2] = -1;
  for (auto& d : dofs)
    for (int& r : d)
      if (r > 20) --r;
  CHECK_THROWS_MENTIONING(FfrfInvariants(sparse_block(model.M, keep, keep), dofs, *data), std::invalid_argument,
                          "node 6 has a non-zero elastic row for psi");
}
