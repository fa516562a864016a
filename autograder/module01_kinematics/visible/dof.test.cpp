// Module 1, task T7: rank of the constraint Jacobian and degrees of freedom.
#include <cmath>
#include <memory>

#include "fmbd/deformable.hpp"
#include "fmbd/dof.hpp"
#include "fmbd/examples.hpp"
#include "kinematics_checks.hpp"

using namespace fmbd;
using namespace fmbd::m01;

namespace {

void check_rank(const MatX& M, int expected, const char* what, const Hint& h) {
  INFO(what << " (" << M.rows() << "x" << M.cols() << "), expected rank " << expected);
  CHECK_NEAR_NAMED("your rank of this matrix", jacobian_rank(M), static_cast<double>(expected), kExact, h);
}

}  // namespace

GRADED_TEST("jacobian rank: hand-built matrices of known rank", "[M01][T7][points=1]") {
  check_rank(MatX(0, 0), 0, "empty 0x0 matrix", hint::rank_empty);
  check_rank(MatX(0, 6), 0, "0x6 matrix (no constraints)", hint::rank_empty);
  check_rank(MatX::Zero(3, 3), 0, "zero matrix", hint::rank_value);
  check_rank(MatX::Identity(3, 3), 3, "identity", hint::rank_value);

  MatX M(3, 4);
  M << 1, 2, 3, 4,  //
      2, 4, 6, 8,   // twice row 1
      0, 1, 0, -1;
  check_rank(M, 2, "row 2 = 2 x row 1", hint::rank_value);

  // Nearly dependent rows at the 1e-14 relative level count as dependent (round-off);
  // rows that differ at the 1e-6 level are independent.
  MatX near = M, apart = M;
  near.row(1) += 1e-14 * Eigen::RowVector4d(0.3, -0.7, 0.2, 0.9);
  apart.row(1) += 1e-6 * Eigen::RowVector4d(0.3, -0.7, 0.2, 0.9);
  check_rank(near, 2, "row 2 = 2 x row 1 + 1e-14 noise", hint::rank_relative);
  check_rank(apart, 3, "row 2 = 2 x row 1 + 1e-6 change", hint::rank_relative);

  // The decision is relative to the largest singular value: scaling changes nothing.
  check_rank(1e-12 * apart, 3, "1e-12 x (full rank matrix)", hint::rank_relative);
  check_rank(1e12 * near, 2, "1e12 x (rank 2 matrix with 1e-14 noise)", hint::rank_relative);

  // Random rank-2 product U V^T (6x9).
  testing::Random random(601);
  MatX U(6, 2), V(9, 2);
  for (int k = 0; k < 2; ++k) {
    U.col(k) = random.vector(6, -1, 1);
    V.col(k) = random.vector(9, -1, 1);
  }
  check_rank(U * V.transpose(), 2, "random 6x9 product U V^T of rank 2", hint::rank_value);
  check_rank((U * V.transpose()).transpose(), 2, "its transpose (9x6)", hint::rank_value);
}

GRADED_TEST("degrees of freedom: slider-crank and four-bar have 0 DOF driven and 1 undriven", "[M01][T7][points=1]") {
  for (bool driven : {true, false}) {
    examples::SliderCrankParameters sp;
    sp.driven = driven;
    const Model slider = examples::slider_crank(sp);
    examples::FourBarParameters fp;
    fp.driven = driven;
    const Model four = examples::four_bar(fp);
    for (double A : {0.4, 1.3, 2.2, 3.9, 5.1}) {
      INFO((driven ? "driven" : "undriven") << " mechanism at crank angle " << A);
      const VecX q = examples::slider_crank_configuration(sp, A);
      CHECK_NEAR_NAMED("your DOF of the slider-crank",
                       degrees_of_freedom(slider, q, (A - sp.A0) / sp.omega), driven ? 0.0 : 1.0,
                       kExact, hint::dof_rank);
      const VecX q4 = four_bar_configuration(fp, A);
      CHECK_NEAR_NAMED("your DOF of the four-bar",
                       degrees_of_freedom(four, q4, (A - fp.theta0) / fp.omega), driven ? 0.0 : 1.0,
                       kExact, hint::dof_rank);
    }
  }
}

namespace {

// A stand-in flexible body for counting freedom: one node at its frame's origin that its n_f
// elastic coordinates do not move (G = [I 0]), so a hinge there leaves all of them free.
class LooseModesBody final : public DeformableBody {
 public:
  explicit LooseModesBody(int modes) : modes_(modes) {}
  int num_modes() const override { return modes_; }
  int num_nodes() const override { return 1; }
  Vec2 node_position(int) const override { return Vec2::Zero(); }
  double mass() const override { return 1.0; }
  double inertia() const override { return 1.0; }
  NodeMarker node_marker(int, const VecX& q, const VecX& qd) const override {
    NodeMarker marker;
    marker.pose = q.head<3>();
    marker.velocity = qd.head<3>();
    marker.G = MatX::Identity(3, 3 + modes_);
    return marker;
  }
  void add_node_columns(const NodeMarker& node, const RowBlock& B, int first_row, int at, MatX& Cq) const override {
    Cq.block(first_row, at, B.rows(), node.G.cols()) += B * node.G;
  }
  RowVector node_gamma_term(const NodeMarker& node, const RowBlock& B) const override { return -(B * node.convective); }
  void add_node_force(const NodeMarker& node, const Vec3& Q, int at, VecX& Q_a) const override {
    Q_a.segment(at, node.G.cols()) += node.G.transpose() * Q;
  }
  void add_mass(const VecX&, int at, MatX& M) const override { M.diagonal().segment(at, 3 + modes_).array() += 1.0; }
  void add_forces(const VecX&, const VecX&, const Vec2&, int, VecX&) const override {}
  double kinetic_energy(const VecX&, const VecX& qd) const override { return 0.5 * qd.squaredNorm(); }
  double potential_energy(const VecX&, const Vec2&) const override { return 0.0; }

 private:
  int modes_;
};

}  // namespace

GRADED_TEST("degrees of freedom: free body 3 and welded body 0 and redundant revolutes use the rank",
            "[M01][T7][points=1]") {
  // One free body: no constraints at all.
  Model free;
  free.add_body("free", 1, 1, Vec3(0.2, 0.3, 0.4));
  CHECK_NEAR_NAMED("your DOF of one free body",
                   degrees_of_freedom(free, free.initial_guess()), 3.0, kExact, hint::rank_empty);

  // One body welded to the ground (ground on side i).
  Model welded;
  const BodyId w = welded.add_body("welded", 1, 1);
  const PointId g = welded.add_point(ground, Vec2(0.3, -0.2), "weld ground");
  const PointId p = welded.add_point(w, Vec2(0.1, 0.05), "weld body");
  welded.add_fixed("weld", g, p, 0.4);
  const VecX q_w = place(Vec2(0.3, -0.2), Vec2(0.1, 0.05), 0.4);
  CHECK_NEAR_NAMED("your DOF of a body welded to the ground",
                   degrees_of_freedom(welded, q_w), 0.0, kExact, hint::dof_rank);

  // A pendulum hinged twice at the same place: 4 rows but rank 2, so 1 DOF (not 3 - 4 = -1).
  Model pendulum;
  const BodyId b = pendulum.add_body("pendulum", 1, 1);
  const PointId O = pendulum.add_point(ground, Vec2(0, 0), "O");
  const PointId top = pendulum.add_point(b, Vec2(-0.5, 0), "top");
  pendulum.add_revolute("hinge", O, top);
  pendulum.add_revolute("second hinge", top, O);  // the same hinge again, sides swapped
  for (double phi : {-1.0, 0.3, 2.0}) {
    INFO("pendulum with a redundant second hinge at phi = " << phi << " (rows m = 4, 3 n_b = 3)");
    CHECK_NEAR_NAMED("your DOF of the pendulum hinged twice",
                     degrees_of_freedom(pendulum, place(Vec2::Zero(), Vec2(-0.5, 0), phi)), 1.0,
                     kExact, hint::dof_rank);
  }

  // A flexible body (modules 7 and 8) with 2 elastic coordinates, hinged at a node that they do not
  // move: n = 3 + 2 coordinates, rank 2, so 3 DOF (the swing and both modes).
  Model flexible;
  const BodyId f = flexible.add_flexible_body("flexible", std::make_shared<LooseModesBody>(2));
  flexible.add_revolute("hinge", flexible.add_point(ground, Vec2::Zero(), "O"), flexible.add_node_point(f, 0, "node 0"));
  INFO("one flexible body with n_f = 2 hinged at a node: n = 5 coordinates, 1 body, rank 2");
  CHECK_NEAR_NAMED("your DOF of the hinged flexible body",
                   degrees_of_freedom(flexible, VecX::Zero(5)), 3.0, kExact, hint::dof_coordinates);
}
