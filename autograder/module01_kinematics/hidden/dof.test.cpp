// Module 1, task T7 (hidden): rank of scaled, tall and wide matrices; a redundant linkage.
#include <cmath>

#include "fmbd/dof.hpp"
#include "kinematics_checks.hpp"

using namespace fmbd;
using namespace fmbd::m01;

GRADED_TEST("jacobian rank: tall wide scaled and nearly dependent matrices", "[M01][T7][points=1]") {
  testing::Random random(1601);
  struct Case {
    int rows, cols, rank;
    double scale;
  };
  for (const Case& c : {Case{9, 9, 8, 1.0}, Case{4, 12, 3, 1e-9}, Case{12, 5, 5, 1e9}, Case{7, 7, 1, 1e-15},
                        Case{10, 6, 4, 1e15}, Case{3, 3, 3, 1e-200}}) {
    MatX U = MatX::Zero(c.rows, c.rank), V = MatX::Zero(c.cols, c.rank);
    for (int k = 0; k < c.rank; ++k) {
      U.col(k) = random.vector(c.rows, -1, 1);
      V.col(k) = random.vector(c.cols, -1, 1);
    }
    MatX M = c.scale * U * V.transpose();
    // Round-off noise at the 1e-14 relative level must not add rank.
    M += 1e-14 * c.scale * random.vector(c.rows * c.cols, -1, 1).reshaped(c.rows, c.cols);
    INFO(c.rows << "x" << c.cols << " product of rank " << c.rank << ", scaled by " << c.scale
                << ", with 1e-14 relative noise");
    CHECK_NEAR_NAMED("your rank of this matrix",
                     jacobian_rank(M), static_cast<double>(c.rank), kExact, hint::rank_relative);
  }
  // A single non-zero entry, and a matrix with a tiny but genuine second row.
  MatX one = MatX::Zero(5, 3);
  one(3, 1) = -2e-7;
  CHECK_NEAR_NAMED("your rank of a matrix with one non-zero entry",
                   jacobian_rank(one), 1.0, kExact, hint::rank_relative);
  MatX tiny(2, 2);
  tiny << 1, 0, 0, 1e-6;
  CHECK_NEAR_NAMED("your rank of a matrix with a tiny second row",
                   jacobian_rank(tiny), 2.0, kExact, hint::rank_relative);
  CHECK_NEAR_NAMED("your rank of a 5x0 matrix", jacobian_rank(MatX(5, 0)), 0.0, kExact, hint::rank_empty);
}

GRADED_TEST("degrees of freedom: a parallelogram with a redundant middle link keeps 1 DOF", "[M01][T7][points=1]") {
  // Three parallel cranks of length a at x = 0, d/2, d, joined by a horizontal coupler:
  // 4 bodies (12 coordinates), 6 revolute joints (12 rows), yet the linkage moves: rank 11.
  const double a = 0.2, d = 0.6;
  Model m;
  const BodyId c1 = m.add_body("crank 1", 1, 1), c2 = m.add_body("crank 2", 1, 1);
  const BodyId c3 = m.add_body("crank 3", 1, 1), coupler = m.add_body("coupler", 1, 1);
  const BodyId cranks[] = {c1, c2, c3};
  for (int k = 0; k < 3; ++k) {
    const std::string tag = std::to_string(k + 1);
    const PointId g = m.add_point(ground, Vec2(k * d / 2, 0), "ground " + tag);
    const PointId lo = m.add_point(cranks[k], Vec2(-a / 2, 0), "crank " + tag + " low");
    const PointId hi = m.add_point(cranks[k], Vec2(a / 2, 0), "crank " + tag + " high");
    const PointId top = m.add_point(coupler, Vec2((k - 1) * d / 2, 0), "coupler " + tag);
    m.add_revolute("pivot " + tag, g, lo);
    m.add_revolute("top " + tag, hi, top);
  }
  for (double theta : {0.5, 1.2, 2.4}) {
    VecX q(12);
    const Vec2 e(std::cos(theta), std::sin(theta));
    for (int k = 0; k < 3; ++k) q.segment<3>(3 * k) << Vec2(k * d / 2, 0) + 0.5 * a * e, theta;
    q.segment<3>(9) << Vec2(d / 2, 0) + a * e, 0.0;
    INFO("crank angle " << theta << ": rows m = 12, 3 n_b = 12, rank 11");
    REQUIRE(check_model_closes(m, q, 0.0));
    CHECK_NEAR_NAMED("your DOF of the parallelogram with a redundant link",
                     degrees_of_freedom(m, q), 1.0, kExact, hint::dof_rank);
  }
}
