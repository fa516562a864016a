// Module 1, task T1: rotation matrix, its derivative, point position and point Jacobian.
#include <cmath>

#include "fmbd/planar.hpp"
#include "kinematics_checks.hpp"

using namespace fmbd;
using namespace fmbd::m01;

GRADED_TEST("rotation: A is orthonormal with det 1 and A(a) A(b) equals A(a + b)", "[M01][T1][points=1]") {
  testing::Random random(101);
  for (int k = 0; k < 20; ++k) {
    const double a = random.uniform(-kPi, kPi), b = random.uniform(-kPi, kPi);
    INFO("a = " << a << ", b = " << b);
    const Mat2 A = rotation(a);
    CHECK_CLOSE_NAMED("A^T A of your A(a)", A.transpose() * A, Mat2::Identity(), kExact, hint::rotation_orthonormal);
    CHECK_NEAR_NAMED("the determinant of your A(a)",
                     A(0, 0) * A(1, 1) - A(0, 1) * A(1, 0), 1.0, kExact, hint::rotation_orthonormal);  // det
    CHECK_CLOSE_NAMED("your A(a) A(b)", rotation(a) * rotation(b), rotation(a + b), kExact, hint::rotation_group);
    // The first column is the body x axis: (cos a, sin a).
    CHECK_CLOSE_NAMED("the first column of your A(a)",
                      A.col(0), Vec2(std::cos(a), std::sin(a)), kExact, hint::rotation_transposed);
  }
}

GRADED_TEST("point position: a quarter turn maps the body x axis to the global y axis", "[M01][T1][points=1]") {
  // Hand-built: body at R = (2, -1) turned by pi/2; the body point (1, 0) sits at R + (0, 1).
  CHECK_CLOSE_NAMED("your r_P of s_bar = (1, 0) on a body at q_i = (0, 0, pi/2)",
                    point_position(Vec3(0, 0, kPi / 2), Vec2(1, 0)), Vec2(0, 1), kExact, hint::rotation_transposed);
  CHECK_CLOSE_NAMED("your A(pi/2) times (1, 0)",
                    rotation(kPi / 2) * Vec2(1, 0), Vec2(0, 1), kExact, hint::rotation_transposed);
  CHECK_CLOSE_NAMED("your r_P of s_bar = (1, 0) on a body at q_i = (2, -1, pi/2)",
                    point_position(Vec3(2, -1, kPi / 2), Vec2(1, 0)), Vec2(2, 0), kExact, hint::point_position);
  // Half a turn: (0.3, 0.4) -> (-0.3, -0.4); no rotation: R + s.
  CHECK_CLOSE_NAMED("your r_P of s_bar = (0.3, 0.4) on a body at q_i = (1, 1, pi)",
                    point_position(Vec3(1, 1, kPi), Vec2(0.3, 0.4)), Vec2(0.7, 0.6), kExact, hint::point_position);
  CHECK_CLOSE_NAMED("your r_P of s_bar = (0.3, 0.4) on a body at q_i = (0.5, -2, 0)",
                    point_position(Vec3(0.5, -2, 0), Vec2(0.3, 0.4)), Vec2(0.8, -1.6), kExact, hint::point_position);
  // A point keeps its distance from the centroid.
  testing::Random random(102);
  for (int k = 0; k < 10; ++k) {
    const Vec3 q = random.vec3(-3, 3);
    const Vec2 s = random.vec2(-1, 1);
    INFO("q_i = " << show(q) << ", s_bar = " << show(s));
    CHECK_NEAR_NAMED("the distance of your r_P from the centroid R_i",
                     (point_position(q, s) - q.head<2>()).norm(), s.norm(), kExact, hint::point_position);
  }
}

GRADED_TEST("rotation derivative: matches central finite differences of rotation", "[M01][T1][points=1]") {
  testing::Random random(103);
  for (int k = 0; k < 20; ++k) {
    const double phi = random.uniform(-kPi, kPi);
    INFO("phi = " << phi);
    const double h = 1e-6;
    const Mat2 fd = (rotation(phi + h) - rotation(phi - h)) / (2 * h);
    const Mat2 dA = rotation_derivative(phi);
    CHECK_CLOSE_NAMED("your dA/dphi", dA, fd, kFD, hint::rotation_derivative);
    CHECK_CLOSE_NAMED("your dA/dphi", dA, rotation(phi) * I_tilde(), kExact, hint::rotation_derivative);
    if (!testing::compare(dA, fd, kFD).ok) break;
  }
}

GRADED_TEST("point jacobian: matches central finite differences of point position", "[M01][T1][points=1]") {
  testing::Random random(104);
  for (int k = 0; k < 20; ++k) {
    const Vec3 q = random.vec3(-2, 2);
    const Vec2 s = random.vec2(-1, 1);
    INFO("q_i = " << show(q) << ", s_bar = " << show(s));
    const MatX fd = testing::finite_difference_jacobian(
        [&](const VecX& y) -> VecX { return point_position(y, s); }, VecX(q), 1e-6);
    const Eigen::Matrix<double, 2, 3> J = point_jacobian(q, s);
    CHECK_CLOSE_NAMED("the x-y columns of your dr_P/dq_i",
                      J.leftCols(2), fd.leftCols(2), kFD, hint::jacobian_translation);
    CHECK_CLOSE_NAMED("the phi column of your dr_P/dq_i", J.col(2), fd.col(2), kFD, hint::jacobian_rotation);
    if (!testing::compare(J, fd, kFD).ok) break;
  }
}
