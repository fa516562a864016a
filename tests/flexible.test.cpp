// Project tests (not graded) of the given code for flexible bodies (modules 1 to 4 through the
// DeformableBody plug-in, modules 7 and 8): the model's coordinate bookkeeping with rigid and
// flexible bodies mixed, the node markers and the assembly of C, C_q, C_t, gamma, Q_a, the
// energies and the mass matrices through them, flexible_body_data and frame_for_placement, the
// example builders and spin_up_profile, static_equilibrium, and simulate on a flexible model.
//
// The oracles are independent of the marker code: node positions are computed here from the
// centred FE nodes and the rows of Phi_f, derivatives by finite differences, forces by virtual
// work, masses and inertias in closed form. The given code calls exercise functions (node_pose,
// the FFRF mass matrix, the integrators, ...), so this program links the reference stages.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "fmbd/applied_forces.hpp"
#include "fmbd/constraints.hpp"
#include "fmbd/energy.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/fe_assembly.hpp"
#include "fmbd/fe_model.hpp"
#include "fmbd/ffrf.hpp"
#include "fmbd/flexible_body.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/intuitive_flexible.hpp"
#include "fmbd/gamma.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/marker.hpp"
#include "fmbd/mass_matrix.hpp"
#include "fmbd/model.hpp"
#include "fmbd/reduction.hpp"
#include "fmbd/simulation.hpp"
#include "fmbd/statics.hpp"
#include "grading.hpp"

#include "flexible_support.hpp"

using namespace fmbd;
using namespace fmbd::flexible_testing;
using fmbd::testing::Random;
using fmbd::testing::Tolerance;
using fmbd::testing::finite_difference_jacobian;


// ---- the model ---------------------------------------------------------------------------------

TEST_CASE("flexible model: offsets, sizes, initial guess and body states with bodies in any order", "[flexible]") {
  const DataPtr two = beam_data(1.0, 3, MassMatrixType::lumped, 2);
  const DataPtr three = beam_data(0.6, 4, MassMatrixType::consistent, 3);
  Model m;
  const BodyId x = m.add_flexible_body("x", make_intuitive_body(two), Vec3(1, 2, 3));
  const BodyId a = m.add_body("a", 1.0, 0.1, Vec3(4, 5, 6));
  const BodyId rod = m.add_flexible_body("rod", make_ffrf_body(three), Vec3(7, 8, 9));
  const BodyId y = m.add_flexible_body("y", make_intuitive_body(two), Vec3(10, 11, 12));
  const BodyId b = m.add_body("b", 2.0, 0.2, Vec3(13, 14, 15));
  REQUIRE(m.num_bodies() == 5);
  CHECK(m.offset(x) == 0);
  CHECK(m.offset(a) == 5);
  CHECK(m.offset(rod) == 8);
  CHECK(m.offset(y) == 14);
  CHECK(m.offset(b) == 19);
  CHECK(m.num_coordinates() == 22);
  CHECK(m.body(rod).num_coordinates() == 6);
  CHECK(m.body(a).num_coordinates() == 3);
  CHECK(m.body(rod).is_flexible());
  CHECK_FALSE(m.body(b).is_flexible());
  // Mass and inertia of a flexible body come from its data.
  CHECK(m.body(rod).mass == three->mass);
  CHECK(m.body(rod).inertia == three->inertia);

  VecX q0(22);
  q0 << 1, 2, 3, 0, 0, 4, 5, 6, 7, 8, 9, 0, 0, 0, 10, 11, 12, 0, 0, 13, 14, 15;
  CHECK_CLOSE(m.initial_guess(), q0, kTight, "frame q0 at each offset, elastic coordinates zero");

  VecX q(22);
  for (int k = 0; k < 22; ++k) q(k) = 100 + k;
  CHECK_CLOSE(m.body_state(q, rod), (VecX(6) << 108, 109, 110, 111, 112, 113).finished(), kTight, "body_state");
  CHECK_CLOSE(m.body_state(q, b), Vec3(119, 120, 121), kTight, "body_state of a rigid body");
  CHECK_CLOSE(m.body_coordinates(q, y), Vec3(114, 115, 116), kTight, "body_coordinates: the frame");
  CHECK_CLOSE(m.body_coordinates(q, ground), Vec3::Zero(), kTight, "the ground");
  CHECK_THROWS_AS(m.body_state(VecX::Zero(21), rod), std::invalid_argument);
  CHECK_THROWS_AS(m.body_coordinates(VecX::Zero(23), rod), std::invalid_argument);
  CHECK_THROWS_AS(m.body_state(q, ground), std::invalid_argument);

  CHECK(m.describe_coordinate(0) == "x of body 'x'");
  CHECK(m.describe_coordinate(3) == "q_f 1 of body 'x'");
  CHECK(m.describe_coordinate(4) == "q_f 2 of body 'x'");
  CHECK(m.describe_coordinate(7) == "phi of body 'a'");
  CHECK(m.describe_coordinate(10) == "phi of body 'rod'");
  CHECK(m.describe_coordinate(12) == "q_f 2 of body 'rod'");
  CHECK(m.describe_coordinate(13) == "q_f 3 of body 'rod'");
  CHECK(m.describe_coordinate(14) == "x of body 'y'");
  CHECK(m.describe_coordinate(21) == "phi of body 'b'");
  CHECK(m.describe_coordinate(22) == "coordinate 22 (out of range)");
}

TEST_CASE("flexible model: points on flexible bodies sit at nodes, and the builder says why it refuses", "[flexible]") {
  const DataPtr data = beam_data(1.0, 3, MassMatrixType::lumped, 2);
  Model m;
  const BodyId a = m.add_body("crank", 1.0, 0.1);
  const BodyId rod = m.add_flexible_body("rod", make_intuitive_body(data));
  const PointId end = m.add_node_point(rod, 3, "rod end");
  CHECK(m.point(end).node == 3);
  CHECK(m.point(end).body == rod);
  CHECK_CLOSE(m.point(end).s_bar, Vec2(0.5, 0.0), kTight, "a node point's s_bar is the centred node position");
  CHECK(m.point(m.add_point(a, Vec2(0.1, 0), "crank tip")).node == -1);

  CHECK_THROWS_MENTIONING(m.add_point(rod, Vec2(0.1, 0.0), "loose"), ModelError,
                          "point 'loose': body 'rod' is flexible; attach points to its FE nodes with add_node_point");
  CHECK_THROWS_MENTIONING(m.add_node_point(a, 0, "bad"), ModelError,
                          "point 'bad': body 'crank' is not flexible; use add_point");
  CHECK_THROWS_MENTIONING(m.add_node_point(ground, 0, "bad"), ModelError, "body 'ground' is not flexible");
  CHECK_THROWS_MENTIONING(m.add_node_point(rod, 4, "bad"), ModelError, "body 'rod' has no node 4 (nodes 0 .. 3)");
  CHECK_THROWS_MENTIONING(m.add_node_point(rod, -1, "bad"), ModelError, "has no node -1");
  CHECK_THROWS_MENTIONING(m.add_node_point(BodyId{7}, 0, "bad"), ModelError, "body 7 does not exist");
  CHECK_THROWS_MENTIONING(m.add_node_point(rod, 0, "rod end"), ModelError, "duplicate point name 'rod end'");
  CHECK_THROWS_MENTIONING(m.add_flexible_body("empty", nullptr), ModelError,
                          "flexible body 'empty': no deformable part given");
  CHECK_THROWS_MENTIONING(m.add_flexible_body("rod", make_intuitive_body(data)), ModelError,
                          "duplicate body name 'rod'");
  CHECK_THROWS_MENTIONING(m.add_flexible_body("nan", make_intuitive_body(data), Vec3(0, std::nan(""), 0)),
                          ModelError, "initial guess q0 is not finite");
  // Nothing was added by the refused calls.
  CHECK(m.num_bodies() == 2);
  CHECK(m.points().size() == 2);
  CHECK(m.num_coordinates() == 3 + 5);
}

// ---- markers -------------------------------------------------------------------------------

TEST_CASE("markers: a node marker is the node's pose, G its Jacobian and c its convective acceleration", "[flexible]") {
  for (const BodyFactory& make_body : {BodyFactory(make_intuitive_body), BodyFactory(make_ffrf_body)}) {
    Mixed x(make_body, MassMatrixType::consistent);
    Random rnd(11);
    const int n = x.m.num_coordinates();
    const VecX q = random_state(x.m, rnd, 0.3, 0.03), qd = rnd.vector(n, -2, 2), qdd = rnd.vector(n, -3, 3);
    const PointId P = x.m.find_point("rod 4");
    const Marker mk = point_marker(x.m, P, q, qd);
    const MatX G = mk.node_kinematics().G;  // the node's kept marker: the finite differences below replace it
    const int at = x.m.offset(x.rod), nb = 3 + 4;
    CHECK(mk.body == x.rod);
    CHECK(mk.offset == at);
    CHECK_CLOSE(mk.s_bar, Vec2::Zero(), kTight, "a node is a point at s_bar = 0 of its marker");
    auto pose = [&](const VecX& qq) {
      const Pose p = point_pose(x.m, P, qq);
      return VecX(Vec3(p.r.x(), p.r.y(), p.phi));
    };
    CHECK_CLOSE(mk.q, pose(q), kTight, "the marker's q is the node pose");
    const MatX G_fd = finite_difference_jacobian(pose, q).middleCols(at, nb);
    CHECK_CLOSE(G, G_fd, (Tolerance{1e-8, 1e-8}), "G = dp/dq_body");
    CHECK_CLOSE(mk.qd, VecX(G_fd * qd.segment(at, nb)), (Tolerance{1e-8, 1e-8}), "qd = G q_body_dot");
    const VecX pdd =
        second_derivative([&](double t) { return pose(VecX(q + qd * t + 0.5 * qdd * t * t)); }, 0.0);
    CHECK_CLOSE(mk.convective, VecX(pdd - G_fd * qdd.segment(at, nb)), (Tolerance{1e-6, 1e-6}),
                "c = p_ddot - G q_ddot");

    const Marker frame = body_marker(x.m, x.rod, q, qd);
    CHECK_CLOSE(frame.q, VecX(q.segment<3>(at)), kTight, "a body marker of a flexible body is its frame");
    CHECK_FALSE(frame.on_node());  // its block takes the frame's 3 columns: G = [I 0], implied
    CHECK(frame.kinematics == nullptr);
    CHECK_CLOSE(frame.convective, Vec3::Zero(), kTight, "frame marker: no convective term");

    const Marker g = point_marker(x.m, x.m.find_point("O2"), q, qd);
    CHECK(g.body.is_ground());
    CHECK_CLOSE(g.s_bar, Vec2(2.0, -1.0), kTight, "a ground point's s_bar is its global position");

    VecX target = VecX::Zero(n);
    add_generalised_force(target, mk, Vec3(1.0, -2.0, 0.5));
    VecX expected = VecX::Zero(n);
    expected.segment(at, nb) = G_fd.transpose() * Vec3(1.0, -2.0, 0.5);
    CHECK_CLOSE(target, expected, (Tolerance{1e-8, 1e-8}), "G^T Q in the columns of the body");
    add_generalised_force(target, g, Vec3(5.0, 5.0, 5.0));
    CHECK_CLOSE(target, expected, (Tolerance{1e-8, 1e-8}), "nothing on the ground");
  }
}

// ---- assembly of C, C_q, C_t and gamma ----------------------------------------------------

TEST_CASE("assembly on a mixed model (intuitive bodies): C, C_q, C_t and gamma through node markers", "[flexible]") {
  check_mixed_assembly(make_intuitive_body, MassMatrixType::consistent, 21);
  check_mixed_assembly(make_intuitive_body, MassMatrixType::lumped, 22);
}

TEST_CASE("assembly on a mixed model (FFRF bodies): C, C_q, C_t and gamma through node markers", "[flexible]") {
  check_mixed_assembly(make_ffrf_body, MassMatrixType::consistent, 23);
  check_mixed_assembly(make_ffrf_body, MassMatrixType::lumped, 24);
}

TEST_CASE("assembly on the flexible slider-crank: C, C_q, C_t and gamma for both formulations", "[flexible]") {
  check_slider_crank_assembly(make_intuitive_body, 31);
  check_slider_crank_assembly(make_ffrf_body, 32);
}

// ---- applied forces and energies --------------------------------------------------------------

TEST_CASE("applied_forces: point forces, torques and spring-dampers at nodes do their virtual work", "[flexible]") {
  for (const BodyFactory& make_body : {BodyFactory(make_intuitive_body), BodyFactory(make_ffrf_body)}) {
    Mixed x(make_body, MassMatrixType::consistent);
    Model& m = x.m;
    m.add_point_force("push", m.find_point("rod 2"), Vec2(3.0, -2.0));
    m.add_point_force("follower", m.find_point("rod 5"), Vec2(1.0, 4.0), Frame::body);
    m.add_point_force("bar follower", m.find_point("bar 3"), Vec2(-2.0, 0.5), Frame::body);
    m.add_point_force("rigid follower", m.find_point("B pin"), Vec2(0.5, 1.0), Frame::body);
    m.add_tsda("coil", m.find_point("A tip"), m.find_point("rod 4"), 50.0, 0.3, 2.0,
               DriveFunction::harmonic(0.5, 1.0, 2.0));
    m.add_tsda("link", m.find_point("rod 6"), m.find_point("bar 1"), 20.0, 0.1, 1.5);
    m.add_tsda("tether", m.find_point("O"), m.find_point("bar 2"), 10.0, 0.5, 0.7);
    m.add_rsda("twist", x.A, x.rod, 5.0, 0.1, 0.5, DriveFunction::constant(0.2));
    m.add_rsda("root", ground, x.bar, 3.0, -0.2, 0.4);
    m.add_torque("motor", x.bar, DriveFunction::linear(1.0, 2.0));
    Random rnd(41);
    const int n = m.num_coordinates();
    for (int trial = 0; trial < 3; ++trial) {
      CAPTURE(trial);
      const VecX q = random_state(m, rnd, 0.3, 0.03), qd = rnd.vector(n, -2.0, 2.0);
      const double t = rnd.uniform(0.0, 1.0);
      const VecX Q = applied_forces(m, q, qd, t) - own_body_forces(m, q, qd);
      CHECK_CLOSE(Q, forces_by_virtual_work(m, q, qd, t), (Tolerance{1e-7, 1e-7}),
                  "a force element on a node must act through G^T (virtual work of the physical force)");
    }
  }
}

TEST_CASE("potential_energy: its gradient is -Q_a at rest for conservative forces on flexible bodies", "[flexible]") {
  // Exact for both bodies with either mass matrix: module 8 keeps module 7's gravity, the exact
  // gradient of -g^T (m R + A S_f q_f) (the FE load L^T M_FE g^j is not, with a consistent M_FE).
  const DataPtr lumped = beam_data(1.0, 6, MassMatrixType::lumped, 4);
  const DataPtr consistent = beam_data(1.0, 6, MassMatrixType::consistent, 4);
  const DataPtr skewed_lumped = skewed_beam_data(MassMatrixType::lumped);
  const DataPtr skewed_consistent = skewed_beam_data(MassMatrixType::consistent);
  REQUIRE(skewed_lumped->S_f.norm() > 0.01);  // gravity couples to q_f in these
  REQUIRE(skewed_consistent->S_f.norm() > 0.01);
  SECTION("intuitive") {
    check_potential_gradient(make_intuitive_body, lumped, 51);
    check_potential_gradient(make_intuitive_body, consistent, 52);
    // The intuitive form refuses a basis with S_f != 0, and says what to use instead.
    for (const DataPtr& skewed : {skewed_lumped, skewed_consistent})
      CHECK_THROWS_MENTIONING(make_intuitive_body(skewed), IntuitiveBasisError, "M-orthogonal");
    CHECK_THROWS_MENTIONING(make_intuitive_body(skewed_lumped), IntuitiveBasisError, "make_ffrf_body");
  }
  SECTION("FFRF: gravity is module 7's, for any basis and either mass matrix") {
    check_potential_gradient(make_ffrf_body, lumped, 55);
    check_potential_gradient(make_ffrf_body, skewed_lumped, 56);
    check_potential_gradient(make_ffrf_body, consistent, 53);
    check_potential_gradient(make_ffrf_body, skewed_consistent, 54);
  }
}

TEST_CASE("potential_energy of a flexible body with lumped mass: gravity on the nodal masses and strain energy", "[flexible]") {
  for (const DataPtr& data : {beam_data(1.0, 6, MassMatrixType::lumped, 4), skewed_beam_data(MassMatrixType::lumped)}) {
    Model m;
    const Vec2 g(0.7, -9.81);
    m.set_gravity(g);
    const BodyId rod = m.add_flexible_body("rod", make_ffrf_body(data), Vec3(0.5, 0.1, 0.2));
    Random rnd(57);
    const VecX q = random_state(m, rnd, 0.5, 0.01);
    // -g^T sum_k m_k r_k over the lumped nodal masses, plus 1/2 u^T K_FE u with u = Phi_f q_f.
    double V = 0;
    for (int k = 0; k < data->fe.num_nodes(); ++k) {
      const PointId P = m.add_node_point(rod, k, "n" + std::to_string(k));
      V -= data->matrices.M.coeff(3 * k, 3 * k) * g.dot(point_pose(m, P, q).r);
    }
    const VecX u = data->Phi_f * q.tail(data->num_modes());
    V += 0.5 * u.dot(data->matrices.K * u);
    CHECK_NEAR(potential_energy(m, q), V, (Tolerance{1e-10, 1e-10}), "V of a flexible body");
  }
}

TEST_CASE("mass matrices and kinetic energies: constant for intuitive bodies, M(q) for FFRF bodies", "[flexible]") {
  Random rnd(61);
  SECTION("intuitive") {
    Mixed x(make_intuitive_body, MassMatrixType::consistent);
    const int n = x.m.num_coordinates();
    const VecX q = random_state(x.m, rnd, 0.3, 0.03), qd = rnd.vector(n, -2, 2);
    const MatX M = mass_matrix(x.m, VecX::Zero(n));
    CHECK_CLOSE(mass_matrix(x.m, q), M, kTight, "the intuitive M_bar does not depend on q");
    const int at = x.m.offset(x.rod);
    CHECK_CLOSE(MatX(M.block(at, at, 7, 7)), x.rod_data->basis.M_bar, kTight, "the body's block is M_bar");
    CHECK_CLOSE(Vec3(M.diagonal().segment<3>(x.m.offset(x.B))), Vec3(1.5, 1.5, 0.2), kTight, "rigid block");
    CHECK_THROWS_MENTIONING(mass_matrix(x.m), std::invalid_argument, "mass_matrix(model, q)");
    CHECK_NEAR(kinetic_energy(x.m, q, qd), 0.5 * qd.dot(M * qd), kTight, "T = 1/2 qd^T M qd");
    CHECK_THROWS_MENTIONING(kinetic_energy(x.m, qd), std::invalid_argument, "kinetic_energy(model, q, q_dot)");
  }
  SECTION("FFRF") {
    Mixed x(make_ffrf_body, MassMatrixType::consistent);
    const int n = x.m.num_coordinates();
    VecX q = random_state(x.m, rnd, 0.3, 0.0);
    const VecX qd = rnd.vector(n, -2, 2);
    Mixed intuitive(make_intuitive_body, MassMatrixType::consistent);
    const MatX M = mass_matrix(intuitive.m, q);
    CHECK_CLOSE(mass_matrix(x.m, q), M, (Tolerance{1e-9, 1e-9}), "at q_f = 0 M(q) = M_bar");
    CHECK_NEAR(kinetic_energy(x.m, q, qd), kinetic_energy(intuitive.m, q, qd), (Tolerance{1e-9, 1e-9}), "at q_f = 0");
    q = random_state(x.m, rnd, 0.3, 0.05);
    const MatX Mq = mass_matrix(x.m, q);
    CHECK((Mq - M).norm() > 1e-3 * M.norm());
    CHECK_CLOSE(Mq, MatX(Mq.transpose()), kTight, "M(q) is symmetric");
    CHECK_CLOSE(MatX(Mq.block(x.m.offset(x.B), x.m.offset(x.B), 3, 3)), MatX(Vec3(1.5, 1.5, 0.2).asDiagonal()),
                kTight, "rigid blocks stay");
    CHECK_NEAR(kinetic_energy(x.m, q, qd), 0.5 * qd.dot(Mq * qd), (Tolerance{1e-10, 1e-10}), "T = 1/2 qd^T M(q) qd");
    CHECK_NEAR(kinetic_energy(intuitive.m, q, qd), 0.5 * qd.dot(M * qd), (Tolerance{1e-10, 1e-10}), "T with M_bar");
    CHECK(std::abs(kinetic_energy(x.m, q, qd) - kinetic_energy(intuitive.m, q, qd)) > 1e-6);
    // Against the FE kinetic energy of the absolute nodal velocities.
    auto rigid = [&](BodyId b, double m, double J) {
      const Vec3 v = qd.segment<3>(x.m.offset(b));
      return 0.5 * (m * v.head<2>().squaredNorm() + J * v(2) * v(2));
    };
    const double T = rigid(x.A, 2.0, 0.3) + rigid(x.B, 1.5, 0.2) + fe_kinetic_energy(x.m, x.rod, q, qd) +
                     fe_kinetic_energy(x.m, x.bar, q, qd);
    CHECK_NEAR(kinetic_energy(x.m, q, qd), T, (Tolerance{1e-8, 1e-8}), "the FE kinetic energy of the nodes");
  }
}

// Module 8 README section 2 shows the change from module 7 as a diff; its claims hold.
TEST_CASE("module 8's node rows are module 7's marker in frame j, and L is Phi at the reference state", "[flexible]") {
  Random rnd(62);
  const FeModel fe = straight_beam(0.9, 5, square_section(7e10, 2700, 0.02), Vec2(0.3, -0.1), 0.4);
  const FlexibleBodyData d = flexible_body_data(fe, MassMatrixType::consistent, 3);
  const int n = 3 + d.num_modes();
  VecX q = rnd.vector(n, -1, 1), qd = rnd.vector(n, -2, 2);
  MatX turn = MatX::Identity(3, 3);  // diag(A^T, 1)
  turn.topLeftCorner(2, 2) = rotation(q(2)).transpose();
  for (const NodeModes& node : d.nodes) {
    CHECK_CLOSE(node_acceleration_map(node, q), MatX(turn * node_jacobian(node, q)), kTight, "L_k = diag(A^T, 1) G_k");
    CHECK_CLOSE(node_acceleration_bias(node, q, qd), Vec3(turn * node_convective_acceleration(node, q, qd)), kTight,
                "b_k = diag(A^T, 1) c_k");
  }
  const VecX rest = VecX::Zero(n);
  CHECK_CLOSE(stacked_map(d, rest), d.basis.Phi, kTight, "L = Phi at theta = 0 and q_f = 0");
  CHECK_CLOSE(ffrf_mass_matrix(d, rest), MatX(d.basis.Phi.transpose() * d.matrices.M * d.basis.Phi),
              (Tolerance{1e-12, 1e-12}), "M(q) = M_bar at theta = 0 and q_f = 0");
}

// ---- flexible_body_data, frame_for_placement ---------------------------------------------------

TEST_CASE("flexible_body_data: centred nodes, mass and inertia of a straight beam at any placement", "[flexible]") {
  const Section s{70e9, 2700.0, 4e-4, 2e-8};
  const double L = 2.0;
  const int N = 5;
  const double h = L / N, m = s.rho * s.A * L;
  const Vec2 start(1.3, -0.7);
  const double angle = 0.9;
  const Vec2 mid = start + 0.5 * L * Vec2(std::cos(angle), std::sin(angle));
  for (MassMatrixType type : {MassMatrixType::consistent, MassMatrixType::lumped}) {
    CAPTURE(type == MassMatrixType::lumped);
    const FeModel fe = straight_beam(L, N, s, start, angle);
    const FlexibleBodyData d = flexible_body_data(fe, type, 4);
    REQUIRE(d.fe.num_nodes() == N + 1);
    REQUIRE(d.fe.num_elements() == N);
    for (int k = 0; k <= N; ++k) {
      CAPTURE(k);
      CHECK_CLOSE(d.fe.nodes()[k], Vec2(fe.nodes()[k] - mid), kTight, "nodes moved so that the centroid is the origin");
      CHECK_CLOSE(d.nodes[k].x_bar, d.fe.nodes()[k], kTight, "x_bar is the centred node");
      CHECK_CLOSE(d.nodes[k].Phi_t, MatX(d.Phi_f.middleRows(3 * k, 2)), kTight, "Phi_t rows");
      CHECK_CLOSE(d.nodes[k].Phi_psi, MatX(d.Phi_f.middleRows(3 * k + 2, 1)), kTight, "Phi_psi row");
    }
    // First moments of the mass about the new origin vanish: t^T M r_o = 0 for both translations.
    const int n = d.fe.num_dofs();
    MatX T = MatX::Zero(n, 3);  // t_x, t_y, unit rotation about the origin
    for (int k = 0; k <= N; ++k) {
      T(3 * k, 0) = 1.0;
      T(3 * k + 1, 1) = 1.0;
      T.block<3, 1>(3 * k, 2) << -d.fe.nodes()[k].y(), d.fe.nodes()[k].x(), 1.0;
    }
    const MatX rigid = T.transpose() * d.matrices.M * T;
    CHECK_NEAR(rigid(0, 2), 0.0, (Tolerance{1e-12 * m * L, 0}), "sum of m_k y_k");
    CHECK_NEAR(rigid(1, 2), 0.0, (Tolerance{1e-12 * m * L, 0}), "sum of m_k x_k");
    CHECK_NEAR(d.mass, m, (Tolerance{0, 1e-12}), "m = rho A L");
    const double J = type == MassMatrixType::consistent
                         ? m * L * L / 12
                         : [&] {
                             double sum = 2 * N * (s.rho * s.A * h) * h * h / 78;  // rotary terms
                             for (int k = 0; k <= N; ++k) {
                               const double mk = s.rho * s.A * h * ((k == 0 || k == N) ? 0.5 : 1.0);
                               sum += mk * std::pow(k * h - L / 2, 2);
                             }
                             return sum;
                           }();
    CHECK_NEAR(d.inertia, J, (Tolerance{0, 1e-11}), "J about the centroid");
    // The elastic columns: mass-normalised, M-orthogonal to the rigid modes, matrices that match.
    CHECK(d.num_modes() == 4);
    CHECK_CLOSE(MatX(T.transpose() * d.matrices.M * d.Phi_f), MatX::Zero(3, 4), (Tolerance{1e-9, 0}),
                "Phi_f is M-orthogonal to the rigid modes");
    CHECK_CLOSE(d.M_ff, MatX::Identity(4, 4), (Tolerance{1e-10, 1e-10}), "M_ff = I (mass-normalised modes)");
    CHECK_CLOSE(d.K_ff, MatX(d.Phi_f.transpose() * d.matrices.K * d.Phi_f), kTight, "K_ff = Phi_f^T K Phi_f");
    CHECK_CLOSE(d.S_f, MatX::Zero(2, 4), (Tolerance{1e-9, 0}), "S_f = 0");
    CHECK_CLOSE(MatX(d.K_ff - MatX(d.K_ff.diagonal().asDiagonal())), MatX::Zero(4, 4), (Tolerance{1e-9 * d.K_ff.norm(), 0}),
                "K_ff diagonal");
    CHECK(d.K_ff(0, 0) > 1.0);
    CHECK_CLOSE(MatX(d.basis.Phi.rightCols(4)), d.Phi_f, kTight, "Phi_f: the elastic columns of the basis");
    CHECK(d.basis.num_rigid == 3);
    const IntuitiveBody body(std::make_shared<const FlexibleBodyData>(d));
    CHECK(body.num_nodes() == N + 1);
    CHECK(body.num_modes() == 4);
    CHECK(body.mass() == d.mass);
    CHECK(body.inertia() == d.inertia);
    MatX M_bar = MatX::Identity(7, 7);
    M_bar.diagonal().head<3>() << m, m, J;
    CHECK_CLOSE(body.mass_matrix(VecX::Zero(7)), M_bar, (Tolerance{1e-9, 1e-9}), "M_bar = diag(m, m, J, I)");
  }
}

TEST_CASE("flexible_body_data with a Craig-Bampton basis; bad bases are refused", "[flexible]") {
  const FeModel fe = straight_beam(1.2, 6, kSteel, Vec2(0.5, 0.2), 0.3);
  const FeMatrices mats = assemble(fe, MassMatrixType::consistent);
  const ReducedBasis cb = craig_bampton(mats.K, mats.M, node_dofs({0, 6}), 2);
  const FlexibleBodyData d = flexible_body_data(fe, MassMatrixType::consistent, ffrf_basis(fe, mats, cb));
  CHECK(d.num_modes() == 3 * 2 - 3 + 2);
  MatX T = MatX::Zero(fe.num_dofs(), 3);
  for (int k = 0; k < fe.num_nodes(); ++k) {
    T(3 * k, 0) = 1.0;
    T(3 * k + 1, 1) = 1.0;
    T.block<3, 1>(3 * k, 2) << -d.fe.nodes()[k].y(), d.fe.nodes()[k].x(), 1.0;
  }
  CHECK_CLOSE(MatX(T.transpose() * d.matrices.M * d.Phi_f), MatX::Zero(3, d.num_modes()), (Tolerance{1e-9, 0}),
              "Phi_f M-orthogonal to the rigid modes about the centroid");
  CHECK_CLOSE(d.fe.nodes()[0], Vec2(-0.6 * std::cos(0.3), -0.6 * std::sin(0.3)), kTight, "centred");
  CHECK_CLOSE(MatX(d.basis.Phi.leftCols(3).transpose() * d.matrices.M * d.basis.Phi.leftCols(3)),
              MatX(Vec3(d.mass, d.mass, d.inertia).asDiagonal()), (Tolerance{1e-10, 1e-10}),
              "the rigid columns are re-made about the centroid");

  CHECK_THROWS_MENTIONING(flexible_body_data(fe, MassMatrixType::consistent, cb), std::invalid_argument,
                          "num_rigid = 0");
  const FeModel longer = straight_beam(1.2, 7, kSteel);
  const FeMatrices lm = assemble(longer, MassMatrixType::consistent);
  const ReducedBasis other = modal_truncation(longer, lm, 2);
  CHECK_THROWS_MENTIONING(flexible_body_data(fe, MassMatrixType::consistent, other), std::invalid_argument,
                          "21 rows, got num_rigid = 3 and 24 rows");
}

TEST_CASE("clamped_frame_body_data: the node stays on the frame, the modes are the cantilever's", "[flexible]") {
  // A cantilever of length L: omega_i = (beta_i L)^2 sqrt(EI / (rho A L^4)), beta_1 L = 1.8751041,
  // beta_2 L = 4.6940911 (the roots of cos x cosh x = -1).
  const double L = 1.5;
  for (const int node : {0, 12}) {
    const FeModel fe = straight_beam(L, 12, kSteel, Vec2(0.2, -0.1), 0.4);
    const FlexibleBodyData d = clamped_frame_body_data(fe, MassMatrixType::consistent, node, 2);
    REQUIRE(d.num_modes() == 2);
    CHECK_CLOSE(d.Phi_f.middleRows(3 * node, 3), MatX::Zero(3, 2), (Tolerance{1e-12, 0}),
                "the clamped node moves and turns with the frame");
    Eigen::GeneralizedSelfAdjointEigenSolver<MatX> eig(d.K_ff, d.M_ff);
    const double unit = std::sqrt(kSteel.E * kSteel.I / (kSteel.rho * kSteel.A * std::pow(L, 4)));
    CHECK_CLOSE(Vec2(eig.eigenvalues().cwiseSqrt()), Vec2(unit * Vec2(1.8751041, 4.6940911).cwiseAbs2()),
                (Tolerance{0, 1e-4}), "the cantilever frequencies");
    CHECK(d.S_f.norm() > 1e-3);  // not M-orthogonal to the rigid motions, unlike free-free modes
    CHECK_NEAR(d.mass, kSteel.rho * kSteel.A * L, (Tolerance{0, 1e-12}), "the mass");
  }
  const FeModel fe = straight_beam(L, 4, kSteel);
  CHECK_THROWS_MENTIONING(clamped_frame_body_data(fe, MassMatrixType::lumped, 5, 2), std::invalid_argument,
                          "node 5 is not a node of the model (0 .. 4)");
}

TEST_CASE("a pendulum with its frame clamped at the hinge conserves energy and turns like the centroid frame's",
          "[flexible]") {
  // The same soft pendulum with the frame at the centroid (free-free modes) and clamped at the hinge
  // node (cantilever modes): with lumped mass the full FFRF conserves energy in both frames, and the
  // tip, whose motion is dominated by the rigid swing, follows the same path to within the
  // small share of the elastic motion that the two bases represent differently.
  const auto run = [](BodyBasis basis) {
    FlexiblePendulumParameters p;
    p.elements = 8;
    p.modes = 3;
    p.basis = basis;
    p.mass_type = MassMatrixType::lumped;
    p.E = 20e9;
    const FlexibleExample ex = flexible_pendulum(p, make_ffrf_body);
    SimulationOptions o;
    o.integrator = Integrator::dormand_prince;
    o.rtol = 1e-9;
    o.atol = 1e-11;
    o.step = 1e-4;
    o.max_step = 0.005;
    const Trajectory tr = simulate(ex.model, ex.q0, ex.qd0, 0.0, 0.4, o);
    double drift = 0;
    for (double e : tr.energy) drift = std::max(drift, std::abs(e - tr.energy.front()));
    CHECK_NEAR(drift / (ex.data->mass * p.gravity * p.length), 0.0, (Tolerance{1e-7, 0}),
               "energy is conserved in either frame");
    return point_position(ex.model, ex.model.find_point("beam tip"), tr.q.back());
  };
  const Vec2 centroid_frame = run(BodyBasis::free_free_modes), clamped_frame = run(BodyBasis::clamped_frame);
  CHECK_CLOSE(clamped_frame, centroid_frame, (Tolerance{2e-3, 0}), "the tip after 0.4 s, both frames");
  CHECK(clamped_frame.y() < -0.5);  // it has swung down
}

TEST_CASE("frame_for_placement puts the FE model's node 0 where asked", "[flexible]") {
  Random rnd(71);
  for (MassMatrixType type : {MassMatrixType::consistent, MassMatrixType::lumped}) {
    for (const Vec2& start : {Vec2(0.0, 0.0), Vec2(0.3, -0.1)}) {
      const FeModel fe = straight_beam(1.5, 5, kSteel, start);
      const FlexibleBodyData d = flexible_body_data(fe, type, 2);
      const Vec2 origin = rnd.vec2(-2, 2);
      const double angle = rnd.uniform(-3, 3);
      const Vec3 frame = frame_for_placement(fe, type, origin, angle);
      CHECK(frame(2) == angle);
      CHECK_CLOSE(undeformed_node_position(d, 0, frame), Vec2(origin + rot(angle) * start), (Tolerance{1e-12, 1e-12}),
                  "node 0 at origin + A(angle) x_0");
      CHECK_CLOSE(undeformed_node_position(d, 5, frame),
                  Vec2(origin + rot(angle) * (start + Vec2(1.5, 0.0))), (Tolerance{1e-12, 1e-12}), "the last node");
      CHECK_CLOSE(Vec2(frame.head<2>()), Vec2(origin + rot(angle) * (start + Vec2(0.75, 0.0))),
                  (Tolerance{1e-12, 1e-12}), "R at the centroid");
    }
  }
}
