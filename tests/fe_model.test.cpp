// Project tests (not graded) of the given code of module 5: the FE model builder's checks and
// messages, straight_beam and square_section, static_solve with its diagnosis of supports that leave
// rigid-body motions free, and the argument checks that the exercise files of module 5 keep outside
// the student's part (reduce, expand, apply_supports, modal_analysis). static_solve calls reduce
// and expand (exercise functions), so this program links the reference stages.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "fmbd/errors.hpp"
#include "fmbd/fe_assembly.hpp"
#include "fmbd/fe_model.hpp"
#include "fmbd/modal.hpp"
#include "fmbd/supports.hpp"
#include "grading.hpp"

using namespace fmbd;
using fmbd::testing::Tolerance;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr Tolerance kTight{1e-12, 1e-12};

const Section kSteel{2.1e11, 7850.0, 1e-3, 1e-7};

VecX vec(std::initializer_list<double> values) {
  VecX v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index k = 0;
  for (double x : values) v(k++) = x;
  return v;
}

// A DofMap with the given free DOFs, written by hand (not by apply_supports).
DofMap map_with(int num_dofs, std::vector<int> free) {
  DofMap m;
  m.num_dofs = num_dofs;
  m.free = std::move(free);
  return m;
}

// Every DOF except those listed.
DofMap map_without(int num_dofs, const std::vector<int>& fixed) {
  std::vector<int> free;
  for (int i = 0; i < num_dofs; ++i) {
    bool is_fixed = false;
    for (int f : fixed) is_fixed = is_fixed || f == i;
    if (!is_fixed) free.push_back(i);
  }
  return map_with(num_dofs, free);
}

}  // namespace

// ---- FeModel --------------------------------------------------------------------------------

TEST_CASE("FeModel: add_node numbers the nodes and refuses coordinates that are not finite", "[fe]") {
  FeModel fe;
  CHECK(fe.add_node(Vec2(0, 0)) == 0);
  CHECK(fe.add_node(Vec2(1, 0)) == 1);
  CHECK_THROWS_MENTIONING(fe.add_node(Vec2(kNaN, 0)), ModelError, "node 2: coordinates are not finite");
  CHECK_THROWS_MENTIONING(fe.add_node(Vec2(0, kInf)), ModelError, "node 2: coordinates are not finite");
  CHECK(fe.num_nodes() == 2);
  CHECK(fe.num_dofs() == 6);
  CHECK(dof_index(1, NodeDof::ux) == 3);
  CHECK(dof_index(1, NodeDof::uy) == 4);
  CHECK(dof_index(2, NodeDof::psi) == 8);
}

TEST_CASE("FeModel: add_element names the element and the offending value", "[fe]") {
  FeModel fe;
  fe.add_node(Vec2(0, 0));
  fe.add_node(Vec2(1, 0));
  fe.add_node(Vec2(0, 0));
  CHECK_THROWS_MENTIONING(fe.add_element(0, 5, kSteel), ModelError,
                          "element 0 (nodes 0-5): node 5 does not exist (the model has 3 nodes, 0 .. 2)");
  CHECK_THROWS_MENTIONING(fe.add_element(-1, 1, kSteel), ModelError, "node -1 does not exist");
  CHECK_THROWS_MENTIONING(fe.add_element(0, 2, kSteel), ModelError,
                          "element 0 (nodes 0-2): the nodes coincide, so the length is zero");
  CHECK_THROWS_MENTIONING(fe.add_element(0, 0, kSteel), ModelError, "the nodes coincide");
  Section s = kSteel;
  s.E = 0;
  CHECK_THROWS_MENTIONING(fe.add_element(0, 1, s), ModelError,
                          "element 0 (nodes 0-1): Young's modulus E must be positive and finite, got 0");
  s = kSteel;
  s.rho = -1;
  CHECK_THROWS_MENTIONING(fe.add_element(0, 1, s), ModelError, "density rho must be positive and finite, got -1");
  s = kSteel;
  s.A = kNaN;
  CHECK_THROWS_MENTIONING(fe.add_element(0, 1, s), ModelError, "cross-section area A must be positive and finite");
  s = kSteel;
  s.I = kInf;
  CHECK_THROWS_MENTIONING(fe.add_element(0, 1, s), ModelError, "second moment of area I must be positive and finite");
  CHECK(fe.num_elements() == 0);  // nothing was added by the failed calls
  CHECK(fe.add_element(0, 1, kSteel) == 0);
  CHECK(fe.add_element(1, 2, kSteel) == 1);
  CHECK_THROWS_MENTIONING(fe.add_element(2, 7, kSteel), ModelError, "element 2 (nodes 2-7)");
  CHECK(fe.elements()[1].node_a == 1);
  CHECK(fe.elements()[1].node_b == 2);
  CHECK(fe.elements()[1].section.I == kSteel.I);
}

TEST_CASE("FeModel: length and angle of elements in every quadrant", "[fe]") {
  FeModel fe;
  fe.add_node(Vec2(1, 1));
  const Vec2 to[4] = {Vec2(4, 5), Vec2(-2, 5), Vec2(-2, -3), Vec2(4, -3)};
  for (const Vec2& x : to) fe.add_element(0, fe.add_node(x), kSteel);
  for (int e = 0; e < 4; ++e) {
    CAPTURE(e);
    CHECK(std::abs(fe.length(e) - 5.0) < 1e-14);
    const Vec2 d = to[e] - Vec2(1, 1);
    CHECK(std::abs(fe.angle(e) - std::atan2(d.y(), d.x())) < 1e-14);
  }
  CHECK(std::abs(fe.angle(0) - std::atan2(4.0, 3.0)) < 1e-14);
  CHECK(fe.angle(1) > kPi / 2);
  CHECK(fe.angle(2) < -kPi / 2);
}

TEST_CASE("FeModel: validate refuses models without elements and nodes without elements", "[fe]") {
  FeModel fe;
  CHECK_THROWS_MENTIONING(fe.validate(), ModelError, "FE model: it has no elements");
  fe.add_node(Vec2(0, 0));
  fe.add_node(Vec2(1, 0));
  fe.add_node(Vec2(2, 0));
  CHECK_THROWS_MENTIONING(fe.validate(), ModelError, "it has no elements");
  fe.add_element(0, 1, kSteel);
  CHECK_THROWS_MENTIONING(fe.validate(), ModelError,
                          "FE model: node 2 belongs to no element, so it has neither mass nor stiffness");
  fe.add_element(2, 1, kSteel);
  CHECK_NOTHROW(fe.validate());
  CHECK_THROWS_MENTIONING(fe.check_node(3, "load 1"), ModelError,
                          "load 1: node 3 does not exist (the model has 3 nodes, 0 .. 2)");
  CHECK_NOTHROW(fe.check_node(2, "load 1"));
}

TEST_CASE("straight_beam: equal elements from start along the angle", "[fe]") {
  const Vec2 start(0.5, -1.0);
  const double angle = 2.0, L = 3.0;
  const FeModel fe = straight_beam(L, 6, kSteel, start, angle);
  CHECK(fe.num_nodes() == 7);
  CHECK(fe.num_elements() == 6);
  for (int k = 0; k <= 6; ++k) {
    CAPTURE(k);
    CHECK_CLOSE(fe.nodes()[k], Vec2(start + 0.5 * k * Vec2(std::cos(angle), std::sin(angle))), kTight,
                "node k at start + k L / n (cos, sin)");
  }
  for (int e = 0; e < 6; ++e) {
    CAPTURE(e);
    CHECK(fe.elements()[e].node_a == e);
    CHECK(fe.elements()[e].node_b == e + 1);
    CHECK(std::abs(fe.length(e) - 0.5) < 1e-14);
    CHECK(std::abs(fe.angle(e) - angle) < 1e-14);
    CHECK(fe.elements()[e].section.A == kSteel.A);
  }
  const FeModel along_x = straight_beam(2.0, 1, kSteel);
  CHECK(along_x.nodes()[0] == Vec2(0, 0));
  CHECK(along_x.nodes()[1] == Vec2(2, 0));
  CHECK_THROWS_MENTIONING(straight_beam(0.0, 3, kSteel), ModelError,
                          "straight_beam: the length must be positive and finite");
  CHECK_THROWS_MENTIONING(straight_beam(kNaN, 3, kSteel), ModelError, "the length must be positive and finite");
  CHECK_THROWS_MENTIONING(straight_beam(1.0, 0, kSteel), ModelError,
                          "straight_beam: at least one element is needed, got 0");
  Section bad = kSteel;
  bad.rho = 0;
  CHECK_THROWS_MENTIONING(straight_beam(1.0, 2, bad), ModelError, "element 0 (nodes 0-1): density rho");
}

TEST_CASE("square_section: A = a^2 and I = a^4 / 12", "[fe]") {
  const Section s = square_section(7e10, 2700, 0.02);
  CHECK(s.E == 7e10);
  CHECK(s.rho == 2700);
  CHECK(std::abs(s.A - 4e-4) < 1e-18);
  CHECK(std::abs(s.I - 1.6e-7 / 12) < 1e-22);
}

// ---- static_solve ----------------------------------------------------------------------------

TEST_CASE("static_solve: inclined cantilever tip deflection P L^3 / 3EI", "[fe]") {
  const double L = 2.0, angle = 0.7, P = 150.0, N = 2e4;
  const FeModel fe = straight_beam(L, 4, kSteel, Vec2(1, 2), angle);
  const FeMatrices mats = assemble(fe, MassMatrixType::consistent);
  const DofMap map = apply_supports(fe, {{0, Support::clamped}});
  const Vec2 e(std::cos(angle), std::sin(angle)), n(-std::sin(angle), std::cos(angle));
  VecX F = VecX::Zero(fe.num_dofs());
  F.segment<2>(12) = P * n + N * e;
  const VecX u = static_solve(fe, mats, map, F);
  const double EI = kSteel.E * kSteel.I, EA = kSteel.E * kSteel.A;
  CHECK_CLOSE(u.head<3>(), Vec3::Zero(), (Tolerance{1e-300, 0}), "the clamped node does not move: zeros from expand");
  CHECK(std::abs(n.dot(u.segment<2>(12)) - P * L * L * L / (3 * EI)) < 1e-9 * P * L * L * L / (3 * EI));
  CHECK(std::abs(e.dot(u.segment<2>(12)) - N * L / EA) < 1e-8 * N * L / EA);
  CHECK(std::abs(u(14) - P * L * L / (2 * EI)) < 1e-9 * P * L * L / (2 * EI));
}

TEST_CASE("static_solve: SingularStiffness names the rigid-body motions left free", "[fe]") {
  const FeModel fe = straight_beam(2.0, 2, kSteel);  // nodes at x = 0, 1, 2 on the x axis
  const FeMatrices mats = assemble(fe, MassMatrixType::consistent);
  const VecX F = VecX::Ones(fe.num_dofs());
  CHECK_THROWS_MENTIONING(static_solve(fe, mats, apply_supports(fe, {}), F), SingularStiffness,
                          "static_solve: K is singular: the supports leave 3 rigid-body motions free (translation x, "
                          "translation y, rotation); clamp or hinge more nodes");
  CHECK_THROWS_MENTIONING(static_solve(fe, mats, apply_supports(fe, {{1, Support::hinged}}), F), SingularStiffness,
                          "the supports leave 1 rigid-body motion free (rotation about (1, 0)); clamp or hinge");
  CHECK_THROWS_MENTIONING(static_solve(fe, mats, apply_supports(fe, {{2, Support::free}}), F), SingularStiffness,
                          "3 rigid-body motions free");
  // u_y fixed at both ends only: the beam can slide along x.
  CHECK_THROWS_MENTIONING(static_solve(fe, mats, map_without(9, {1, 7}), F), SingularStiffness,
                          "1 rigid-body motion free (translation x)");
  // u_x fixed at one node only: it can move along y and turn about that node.
  CHECK_THROWS_MENTIONING(static_solve(fe, mats, map_without(9, {3}), F), SingularStiffness,
                          "2 rigid-body motions free (");
  // Two hinges, or one clamp, hold the beam.
  CHECK_NOTHROW(static_solve(fe, mats, apply_supports(fe, {{0, Support::hinged}, {2, Support::hinged}}), F));
  CHECK_NOTHROW(static_solve(fe, mats, apply_supports(fe, {{1, Support::clamped}}), F));

  // A vertical beam with u_x fixed at both ends slides along y.
  const FeModel up = straight_beam(1.0, 1, kSteel, Vec2(3, 0), kPi / 2);
  CHECK_THROWS_MENTIONING(static_solve(up, assemble(up, MassMatrixType::lumped), map_without(6, {0, 3}),
                                       VecX::Zero(6)),
                          SingularStiffness, "1 rigid-body motion free (translation y)");
  // A hinge away from the origin names its point.
  const FeModel off = straight_beam(1.0, 2, kSteel, Vec2(1.5, -2.0));
  CHECK_THROWS_MENTIONING(static_solve(off, assemble(off, MassMatrixType::consistent),
                                       apply_supports(off, {{0, Support::hinged}}), VecX::Zero(9)),
                          SingularStiffness, "rotation about (1.5, -2)");
}

TEST_CASE("static_solve: a frame in two pieces is singular although the supports hold the whole", "[fe]") {
  FeModel fe;
  for (const Vec2& x : {Vec2(0, 0), Vec2(1, 0), Vec2(3, 0), Vec2(4, 0)}) fe.add_node(x);
  fe.add_element(0, 1, kSteel);
  fe.add_element(2, 3, kSteel);
  const FeMatrices mats = assemble(fe, MassMatrixType::consistent);
  CHECK_THROWS_MENTIONING(static_solve(fe, mats, apply_supports(fe, {{0, Support::clamped}}), VecX::Ones(12)),
                          SingularStiffness,
                          "static_solve: K_ff is not positive definite although the supports fix every rigid motion; "
                          "is the frame in one connected piece?");
  CHECK_NOTHROW(static_solve(fe, mats, apply_supports(fe, {{0, Support::clamped}, {3, Support::clamped}}),
                             VecX::Ones(12)));
}

TEST_CASE("static_solve: sizes and finiteness of its arguments", "[fe]") {
  const FeModel fe = straight_beam(1.0, 1, kSteel);
  const FeMatrices mats = assemble(fe, MassMatrixType::consistent);
  const DofMap map = apply_supports(fe, {{0, Support::clamped}});
  CHECK_THROWS_MENTIONING(static_solve(fe, mats, map, VecX::Zero(5)), std::invalid_argument,
                          "static_solve: the model has 6 DOFs, but F has 5, K has 6 rows and the DofMap 6");
  const FeMatrices small{MatX::Identity(3, 3), MatX::Identity(3, 3)};
  CHECK_THROWS_MENTIONING(static_solve(fe, small, map, VecX::Zero(6)), std::invalid_argument, "K has 3 rows");
  CHECK_THROWS_MENTIONING(static_solve(fe, mats, map_with(3, {1, 2}), VecX::Zero(6)), std::invalid_argument,
                          "the DofMap 3");
  CHECK_THROWS_MENTIONING(static_solve(fe, mats, map, vec({0, 0, 0, 1, kNaN, 0})), std::invalid_argument,
                          "static_solve: the load vector F is not finite");
}

// ---- argument checks kept outside the student's part of the exercise files ------------------

TEST_CASE("apply_supports reduce and expand: unknown nodes and sizes that do not match", "[fe]") {
  const FeModel fe = straight_beam(1.0, 2, kSteel);
  CHECK_THROWS_MENTIONING(apply_supports(fe, {{0, Support::clamped}, {7, Support::hinged}}), ModelError,
                          "support 1: node 7 does not exist (the model has 3 nodes, 0 .. 2)");
  CHECK_THROWS_MENTIONING(apply_supports(fe, {{-1, Support::free}}), ModelError, "support 0: node -1");
  const DofMap map = map_with(9, {2, 5, 6});
  CHECK_THROWS_MENTIONING(reduce(MatX(MatX::Zero(9, 8)), map), std::invalid_argument,
                          "reduce: the matrix is 9x8, the DofMap has 9 DOFs");
  CHECK_THROWS_MENTIONING(reduce(VecX(VecX::Zero(6)), map), std::invalid_argument,
                          "reduce: the vector has 6 entries, the DofMap has 9 DOFs");
  CHECK_THROWS_MENTIONING(expand(VecX(VecX::Zero(4)), map), std::invalid_argument,
                          "expand: the vector has 4 entries, the DofMap has 3 free DOFs");
}

TEST_CASE("expand of a matrix expands each column", "[fe]") {
  const DofMap map = map_with(5, {0, 3, 4});
  MatX columns(3, 2);
  columns << 1, 4, 2, 5, 3, 6;
  MatX expected(5, 2);
  expected << 1, 4, 0, 0, 0, 0, 2, 5, 3, 6;
  CHECK_CLOSE(expand(columns, map), expected, (Tolerance{1e-300, 0}), "column-wise expand with zeros at fixed DOFs");
  CHECK(expand(MatX(3, 0), map).cols() == 0);
}

TEST_CASE("modal_analysis: argument checks before the eigensolver", "[fe]") {
  const MatX K = (MatX(2, 2) << 2, -1, -1, 2).finished(), M = MatX::Identity(2, 2);
  CHECK_THROWS_MENTIONING(modal_analysis(MatX::Identity(2, 3), M, 1), std::invalid_argument,
                          "modal_analysis: K is 2x3, expected 2x2");
  CHECK_THROWS_MENTIONING(modal_analysis(K, MatX::Identity(3, 3), 1), std::invalid_argument,
                          "modal_analysis: M is 3x3, expected 2x2");
  MatX bad = K;
  bad(0, 1) = kNaN;
  CHECK_THROWS_MENTIONING(modal_analysis(bad, M, 1), std::invalid_argument, "modal_analysis: K is not finite");
  bad = M;
  bad(1, 0) = 0.5;
  CHECK_THROWS_MENTIONING(modal_analysis(K, bad, 1), std::invalid_argument, "modal_analysis: M is not symmetric");
  CHECK_THROWS_MENTIONING(modal_analysis(K, M, 0), std::invalid_argument,
                          "modal_analysis: count must be between 1 and 2, got 0");
  CHECK_THROWS_MENTIONING(modal_analysis(K, M, 3), std::invalid_argument, "count must be between 1 and 2, got 3");
  const MatX singular = (MatX(2, 2) << 1, 0, 0, 0).finished();
  CHECK_THROWS_MENTIONING(modal_analysis(K, singular, 1), std::invalid_argument,
                          "modal_analysis: M is not positive definite (a DOF without mass?)");
  // With valid arguments (reference): omega^2 = 1 and 3 for this K and M = I.
  const Modes modes = modal_analysis(K, M, 2);
  CHECK_CLOSE(modes.omega, vec({1.0, std::sqrt(3.0)}), kTight, "eigenvalues 1 and 3 of [[2, -1], [-1, 2]]");
  CHECK_CLOSE(modes.hertz(), VecX(modes.omega / (2 * kPi)), kTight, "hertz() = omega / (2 pi)");
}
