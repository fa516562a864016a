// Module 1, task T1 (hidden): large angles and angles near +-pi.
#include <cmath>

#include "fmbd/planar.hpp"
#include "kinematics_checks.hpp"

using namespace fmbd;
using namespace fmbd::m01;

GRADED_TEST("point jacobian: large angles and angles near plus or minus pi", "[M01][T1][points=1]") {
  // Half a turn: A(+-pi) = -I.
  CHECK_CLOSE_NAMED("your A(pi)", rotation(kPi), -Mat2::Identity(), kExact, hint::rotation_orthonormal);
  CHECK_CLOSE_NAMED("your A(-pi)", rotation(-kPi), -Mat2::Identity(), kExact, hint::rotation_orthonormal);
  CHECK_CLOSE_NAMED("your A(-pi/2) times (1, 0)",
                    rotation(-kPi / 2) * Vec2(1, 0), Vec2(0, -1), kExact, hint::rotation_transposed);

  testing::Random random(1101);
  const double angles[] = {kPi - 1e-3, kPi + 1e-3, -kPi + 1e-9, -kPi - 1e-3, 7.5, -12.25, 31.0, -47.3, 50.0};
  for (double phi : angles) {
    const Vec3 q(random.uniform(-5, 5), random.uniform(-5, 5), phi);
    const Vec2 s = random.vec2(-2, 2);
    INFO("q_i = " << show(q) << ", s_bar = " << show(s));
    const Mat2 A = rotation(phi);
    CHECK_CLOSE_NAMED("A^T A of your A(phi)", A.transpose() * A, Mat2::Identity(), kExact, hint::rotation_orthonormal);
    CHECK_CLOSE_NAMED("the first column of your A(phi)",
                      A.col(0), Vec2(std::cos(phi), std::sin(phi)), kExact, hint::rotation_transposed);
    CHECK_CLOSE_NAMED("your A(phi) A(-phi)",
                      rotation(phi) * rotation(-phi), Mat2::Identity(), kExact, hint::rotation_group);
    const double h = 1e-6;
    CHECK_CLOSE_NAMED("your dA/dphi", rotation_derivative(phi), (rotation(phi + h) - rotation(phi - h)) / (2 * h), kFD,
                      hint::rotation_derivative);
    CHECK_CLOSE_NAMED("your r_P", point_position(q, s), q.head<2>() + rot(phi) * s, kExact, hint::point_position);
    const MatX fd = testing::finite_difference_jacobian(
        [&](const VecX& y) -> VecX { return point_position(y, s); }, VecX(q), 1e-6);
    const Eigen::Matrix<double, 2, 3> J = point_jacobian(q, s);
    CHECK_CLOSE_NAMED("the x-y columns of your dr_P/dq_i",
                      J.leftCols(2), fd.leftCols(2), kFD, hint::jacobian_translation);
    CHECK_CLOSE_NAMED("the phi column of your dr_P/dq_i", J.col(2), fd.col(2), kFD, hint::jacobian_rotation);
  }
}
