// Project tests (not graded) of the given code of module 1: the model builder's checks and
// messages, the row and coordinate descriptions, and the drive functions' derivatives.
// None of these calls an exercise function, so they pass with the student stubs linked.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <variant>

#include "fmbd/constraints.hpp"
#include "fmbd/drive_function.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/model.hpp"
#include "grading.hpp"

using namespace fmbd;
using fmbd::testing::Tolerance;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A body "b" with points "p" (on b) and "g" (on the ground).
struct Small {
  Model m;
  BodyId b;
  PointId p, g;
  Small() {
    b = m.add_body("b", 1.0, 0.5, Vec3(0.1, 0.2, 0.3));
    p = m.add_point(b, Vec2(0.5, 0), "p");
    g = m.add_point(ground, Vec2(1, 2), "g");
  }
};

Eigen::VectorXd as_vector(double x) { return Eigen::VectorXd::Constant(1, x); }

}  // namespace

TEST_CASE("model builder: unknown bodies and points are named", "[model]") {
  Small s;
  CHECK_THROWS_MENTIONING(s.m.add_point(BodyId{5}, Vec2::Zero(), "q"), ModelError, "point 'q': body 5 does not exist");
  CHECK_THROWS_MENTIONING(s.m.add_point(BodyId{-2}, Vec2::Zero(), "q"), ModelError, "body -2 does not exist");
  CHECK_THROWS_MENTIONING(s.m.add_revolute("r", PointId{7}, s.p), ModelError, "revolute joint 'r': point 7 does not exist");
  CHECK_THROWS_MENTIONING(s.m.add_fixed("f", s.p, PointId{-1}), ModelError, "fixed joint 'f': point -1 does not exist");
  CHECK_THROWS_MENTIONING(s.m.add_absolute_angle_driver("a", BodyId{3}, DriveFunction::constant(0)), ModelError,
                          "absolute-angle driver 'a': body 3 does not exist");
  CHECK_THROWS_MENTIONING(s.m.add_distance_driver("d", s.p, PointId{9}, DriveFunction::constant(1)), ModelError,
                          "distance driver 'd': point 9 does not exist");
  CHECK_THROWS_MENTIONING(s.m.find_body("nope"), ModelError, "unknown body 'nope'");
  CHECK_THROWS_MENTIONING(s.m.find_point("nope"), ModelError, "unknown point 'nope'");
  CHECK_THROWS_AS(s.m.body(ground), ModelError);
  CHECK(s.m.find_body("ground") == ground);
  CHECK(s.m.find_body("b") == s.b);
  CHECK(s.m.find_point("g") == s.g);
  CHECK(s.m.body_name(ground) == "ground");
  // Nothing was added by the failed calls.
  CHECK(s.m.points().size() == 2);
  CHECK(s.m.constraints().empty());
}

TEST_CASE("model builder: a zero-length translational axis is refused and others are normalised", "[model]") {
  Small s;
  CHECK_THROWS_MENTIONING(s.m.add_translational("t", s.g, s.p, Vec2::Zero()), ModelError,
                          "translational joint 't': the sliding axis has zero length");
  CHECK_THROWS_MENTIONING(s.m.add_translational("t", s.g, s.p, Vec2(1e-14, 0)), ModelError, "zero length");
  CHECK_THROWS_MENTIONING(s.m.add_translational("t", s.g, s.p, Vec2(kNaN, 1)), ModelError, "zero length");
  const int k = s.m.add_translational("t", s.g, s.p, Vec2(3, 4), 0.25);
  const auto& t = std::get<Translational>(s.m.constraints()[k].type);
  CHECK_CLOSE(t.axis_i, Vec2(0.6, 0.8), (Tolerance{1e-15, 1e-15}), "the builder normalises axis_i");
  CHECK(t.phi0 == 0.25);
  CHECK(s.m.constraints()[k].rows == 2);
}

TEST_CASE("model builder: two drivers of the same quantity are refused", "[model]") {
  Small s;
  const BodyId c = s.m.add_body("c", 1, 1);
  const PointId pc = s.m.add_point(c, Vec2(0, 1), "pc");
  s.m.add_absolute_angle_driver("a1", s.b, DriveFunction::constant(0));
  CHECK_THROWS_MENTIONING(s.m.add_absolute_angle_driver("a2", s.b, DriveFunction::linear(0, 1)), ModelError,
                          "absolute-angle driver 'a2' duplicates driver 'a1': both drive the angle of body 'b'");
  s.m.add_relative_angle_driver("r1", s.b, c, DriveFunction::constant(0));
  CHECK_THROWS_MENTIONING(s.m.add_relative_angle_driver("r2", s.b, c, DriveFunction::constant(1)), ModelError,
                          "duplicates driver 'r1'");
  CHECK_THROWS_MENTIONING(s.m.add_relative_angle_driver("r3", c, s.b, DriveFunction::constant(1)), ModelError,
                          "duplicates driver 'r1'");
  CHECK_THROWS_MENTIONING(s.m.add_relative_angle_driver("r4", ground, s.b, DriveFunction::constant(1)), ModelError,
                          "duplicates driver 'a1': both drive the angle of body 'b'");
  s.m.add_point_coordinate_driver("x1", pc, Axis::x, DriveFunction::constant(0));
  CHECK_THROWS_MENTIONING(s.m.add_point_coordinate_driver("x2", pc, Axis::x, DriveFunction::constant(1)), ModelError,
                          "both drive the x coordinate of point 'pc'");
  CHECK_NOTHROW(s.m.add_point_coordinate_driver("y1", pc, Axis::y, DriveFunction::constant(0)));
  s.m.add_distance_driver("d1", s.p, pc, DriveFunction::constant(1));
  CHECK_THROWS_MENTIONING(s.m.add_distance_driver("d2", pc, s.p, DriveFunction::constant(1)), ModelError,
                          "both drive the distance between points 'p' and 'pc'");
  CHECK(s.m.constraints().size() == 5);
  CHECK(s.m.num_constraints() == 5);
}

TEST_CASE("model builder: duplicate and empty names are refused", "[model]") {
  Small s;
  CHECK_THROWS_MENTIONING(s.m.add_body("b", 1, 1), ModelError, "duplicate body name 'b'");
  CHECK_THROWS_MENTIONING(s.m.add_point(s.b, Vec2::Zero(), "p"), ModelError, "duplicate point name 'p'");
  s.m.add_revolute("j", s.g, s.p);
  CHECK_THROWS_MENTIONING(s.m.add_fixed("j", s.g, s.p), ModelError, "duplicate constraint name 'j'");
  CHECK_THROWS_MENTIONING(s.m.add_body("", 1, 1), ModelError, "a body needs a non-empty name");
  CHECK_THROWS_MENTIONING(s.m.add_point(s.b, Vec2::Zero(), ""), ModelError, "a point needs a non-empty name");
  // Names are per kind: a point may share a body's name.
  CHECK_NOTHROW(s.m.add_point(s.b, Vec2::Zero(), "b"));
  CHECK(s.m.num_bodies() == 1);
  CHECK(s.m.num_constraints() == 2);
}

TEST_CASE("model builder: a joint or driver from a body to itself is refused", "[model]") {
  Small s;
  const PointId p2 = s.m.add_point(s.b, Vec2(-0.5, 0), "p2");
  const PointId g2 = s.m.add_point(ground, Vec2(0, 0), "g2");
  CHECK_THROWS_MENTIONING(s.m.add_revolute("self", s.p, p2), ModelError, "revolute joint 'self': connects body 'b' to itself");
  CHECK_THROWS_MENTIONING(s.m.add_fixed("grounds", s.g, g2), ModelError, "connects body 'ground' to itself");
  CHECK_THROWS_MENTIONING(s.m.add_translational("slide", p2, s.p, Vec2::UnitX()), ModelError, "to itself");
  CHECK_THROWS_MENTIONING(s.m.add_relative_angle_driver("rr", s.b, s.b, DriveFunction::constant(0)), ModelError,
                          "relative-angle driver 'rr': connects body 'b' to itself");
  CHECK_THROWS_MENTIONING(s.m.add_distance_driver("dd", s.p, p2, DriveFunction::constant(1)), ModelError, "to itself");
  CHECK(s.m.constraints().empty());
}

TEST_CASE("model builder: mass and inertia must be finite and not negative; zero is a point mass or a massless link",
          "[model]") {
  Model m;
  CHECK_THROWS_MENTIONING(m.add_body("m1", -2.0, 1.0), ModelError, "body 'm1': mass must be finite and not negative, got -2");
  CHECK_THROWS_MENTIONING(m.add_body("m2", kNaN, 1.0), ModelError, "mass must be finite and not negative, got nan");
  CHECK_THROWS_MENTIONING(m.add_body("m3", std::numeric_limits<double>::infinity(), 1.0), ModelError, "mass");
  CHECK_THROWS_MENTIONING(m.add_body("j1", 1.0, -1.0), ModelError, "body 'j1': inertia must be finite and not negative");
  CHECK_THROWS_MENTIONING(m.add_body("q0", 1.0, 1.0, Vec3(0, kNaN, 0)), ModelError, "initial guess q0 is not finite");
  CHECK(m.num_bodies() == 0);
  // ModelError is an invalid_argument, like every argument check of the library.
  CHECK_THROWS_AS(m.add_body("m4", -1.0, 1.0), std::invalid_argument);
  m.add_body("point", 1.0, 0.0);
  m.add_body("massless", 0.0, 0.0);
  CHECK(m.num_bodies() == 2);
}

TEST_CASE("model builder: the ground cannot be driven", "[model]") {
  Small s;
  CHECK_THROWS_MENTIONING(s.m.add_absolute_angle_driver("a", ground, DriveFunction::constant(0)), ModelError,
                          "the ground cannot be driven");
  CHECK_THROWS_MENTIONING(s.m.add_point_coordinate_driver("x", s.g, Axis::x, DriveFunction::constant(0)), ModelError,
                          "point 'g' is on the ground and cannot be driven");
  CHECK_THROWS_MENTIONING(s.m.add_point(s.b, Vec2(kNaN, 0), "bad"), ModelError, "point 'bad': coordinates are not finite");
}

TEST_CASE("model: rows, bodies, initial guess and body coordinates", "[model]") {
  const Model m = examples::slider_crank();
  REQUIRE(m.num_bodies() == 3);
  CHECK(m.num_coordinates() == 9);
  CHECK(m.num_constraints() == 9);
  const int rows[] = {0, 2, 4, 6, 8};
  const int sizes[] = {2, 2, 2, 2, 1};
  for (std::size_t k = 0; k < m.constraints().size(); ++k) {
    CHECK(m.constraints()[k].first_row == rows[k]);
    CHECK(m.constraints()[k].rows == sizes[k]);
  }
  CHECK(m.constraints()[3].body_i == ground);
  CHECK(m.constraints()[4].body_j == ground);
  CHECK(std::string(m.constraints()[3].type_name()) == "translational joint");
  CHECK(m.constraints()[4].is_driver());
  CHECK_FALSE(m.constraints()[0].is_driver());
  const VecX q = m.initial_guess();
  REQUIRE(q.size() == 9);
  CHECK(m.body_coordinates(q, BodyId{1}) == q.segment<3>(3));
  CHECK(m.body_coordinates(q, ground) == Vec3::Zero());
  CHECK_THROWS_MENTIONING(m.body_coordinates(VecX::Zero(4), BodyId{0}), std::invalid_argument,
                          "Model::body_coordinates: q has size 4, expected 9");
  CHECK_THROWS_MENTIONING(evaluate_constraints(m, VecX::Zero(8), 0.0), std::invalid_argument,
                          "evaluate_constraints: q has size 8, expected 9");
}

TEST_CASE("model: describe_row and describe_coordinate name the culprit", "[model]") {
  const Model m = examples::slider_crank();
  CHECK(m.describe_row(0) == "revolute joint 'O' (equation 1 of 2)");
  CHECK(m.describe_row(3) == "revolute joint 'B' (equation 2 of 2)");
  CHECK(m.describe_row(7) == "translational joint 'slider guide' (equation 2 of 2)");
  CHECK(m.describe_row(8) == "absolute-angle driver 'crank angle' (equation 1 of 1)");
  CHECK(m.describe_row(9) == "row 9 (no such constraint row)");
  CHECK(m.describe_row(-1) == "row -1 (no such constraint row)");
  CHECK(m.describe_coordinate(0) == "x of body 'crank'");
  CHECK(m.describe_coordinate(4) == "y of body 'rod'");
  CHECK(m.describe_coordinate(8) == "phi of body 'slider'");
  CHECK(m.describe_coordinate(9) == "coordinate 9 (out of range)");
  CHECK(m.describe_coordinate(-1) == "coordinate -1 (out of range)");
}

TEST_CASE("drive functions: first and second derivatives match finite differences", "[drive]") {
  struct Named {
    const char* name;
    DriveFunction f;
  };
  const Named functions[] = {
      {"constant", DriveFunction::constant(2.5)},
      {"linear", DriveFunction::linear(1.0, -0.75)},
      {"polynomial", DriveFunction::polynomial({0.3, -1.2, 0.5, 0.25, -0.05})},
      {"harmonic", DriveFunction::harmonic(0.2, 1.5, 2.3, 0.4)},
      {"smooth step", DriveFunction::smooth_step(-0.5, 1.0, 0.5, 2.5)},
      {"custom", DriveFunction::custom([](double t) { return DriveValue{std::exp(t), std::exp(t), std::exp(t)}; },
                                       "exponential")},
  };
  const Tolerance first{1e-8, 1e-8}, second{2e-6, 2e-6};
  for (const Named& n : functions) {
    for (double t : {-0.7, 0.0, 0.6, 1.1, 1.5, 2.2, 3.4}) {
      INFO(n.name << " at t = " << t);
      const DriveValue v = n.f(t);
      const VecX fd1 = fmbd::testing::finite_difference_first([&](double s) { return as_vector(n.f(s).f); }, t, 1e-5);
      const VecX fd2 = fmbd::testing::finite_difference_first([&](double s) { return as_vector(n.f(s).fd); }, t, 1e-5);
      const VecX fdd = fmbd::testing::finite_difference_second([&](double s) { return as_vector(n.f(s).f); }, t, 1e-4);
      CHECK_CLOSE(as_vector(v.fd), fd1, first, "f' must be the derivative of f");
      CHECK_CLOSE(as_vector(v.fdd), fd2, first, "f'' must be the derivative of f'");
      CHECK_CLOSE(as_vector(v.fdd), fdd, second, "f'' must be the second derivative of f");
    }
  }
}

TEST_CASE("drive functions: values of the named constructors", "[drive]") {
  const Tolerance exact{1e-14, 1e-14};
  const DriveValue p = DriveFunction::polynomial({0.3, -1.2, 0.5, 0.25})(2.0);
  CHECK_NEAR(p.f, 0.3 - 2.4 + 2.0 + 2.0, exact, "polynomial value");
  CHECK_NEAR(p.fd, -1.2 + 2.0 + 3.0, exact, "polynomial first derivative");
  CHECK_NEAR(p.fdd, 1.0 + 3.0, exact, "polynomial second derivative");
  const DriveValue empty = DriveFunction::polynomial({})(1.7);
  CHECK(empty.f == 0.0);
  CHECK(empty.fd == 0.0);
  const DriveValue l = DriveFunction::linear(1.0, 2.0)(3.0);
  CHECK_NEAR(l.f, 7.0, exact, "linear value");
  CHECK_NEAR(l.fd, 2.0, exact, "linear rate");
  CHECK(l.fdd == 0.0);
  const DriveValue h = DriveFunction::harmonic(0.5, 2.0, 3.0, 0.25)(0.0);
  CHECK_NEAR(h.f, 0.5 + 2.0 * std::sin(0.25), exact, "harmonic value");
  CHECK_NEAR(h.fd, 6.0 * std::cos(0.25), exact, "harmonic rate");
  CHECK_NEAR(h.fdd, -18.0 * std::sin(0.25), exact, "harmonic acceleration");
  CHECK(DriveFunction::polynomial({1, 2, 3}).description() == "polynomial of degree 2");
  CHECK(DriveFunction::constant(1).description() == "polynomial of degree 0");
  CHECK(DriveFunction::harmonic(0, 1, 1).description() == "harmonic");
  CHECK(DriveFunction::smooth_step(0, 1, 0, 1).description() == "smooth step");
  CHECK(DriveFunction::custom([](double) { return DriveValue{}; }, "mine").description() == "mine");
}

TEST_CASE("drive functions: the smooth step rests at both ends", "[drive]") {
  const double f0 = -0.5, f1 = 1.0, t0 = 0.5, t1 = 2.5;
  const DriveFunction f = DriveFunction::smooth_step(f0, f1, t0, t1);
  const Tolerance exact{1e-14, 1e-14};
  // Constant outside [t0, t1], with zero rates.
  for (double t : {-1.0, 0.0, t0}) {
    INFO("t = " << t);
    CHECK(f(t).f == f0);
    CHECK(f(t).fd == 0.0);
    CHECK(f(t).fdd == 0.0);
  }
  for (double t : {t1, 3.0, 10.0}) {
    INFO("t = " << t);
    CHECK(f(t).f == f1);
    CHECK(f(t).fd == 0.0);
    CHECK(f(t).fdd == 0.0);
  }
  CHECK_NEAR(f(0.5 * (t0 + t1)).f, 0.5 * (f0 + f1), exact, "the step passes its midpoint halfway");
  CHECK_NEAR(f(0.5 * (t0 + t1)).fdd, 0.0, exact, "the acceleration changes sign halfway");
  // f, f' and f'' are continuous at the ends: just inside they are near their end values.
  const double e = 1e-6;
  const Tolerance near_end{1e-9, 0.0};
  CHECK_NEAR(f(t0 + e).f, f0, near_end, "f continuous at t0");
  CHECK_NEAR(f(t0 + e).fd, 0.0, near_end, "f' continuous at t0");
  CHECK_NEAR(f(t0 + e).fdd, 0.0, (Tolerance{1e-4, 0.0}), "f'' continuous at t0");
  CHECK_NEAR(f(t1 - e).f, f1, near_end, "f continuous at t1");
  CHECK_NEAR(f(t1 - e).fd, 0.0, near_end, "f' continuous at t1");
  CHECK_NEAR(f(t1 - e).fdd, 0.0, (Tolerance{1e-4, 0.0}), "f'' continuous at t1");
  // Central differences across the ends see zero rates.
  for (double t : {t0, t1}) {
    INFO("t = " << t);
    const VecX fd1 = fmbd::testing::finite_difference_first([&](double s) { return as_vector(f(s).f); }, t, 1e-5);
    const VecX fdd = fmbd::testing::finite_difference_second([&](double s) { return as_vector(f(s).f); }, t, 1e-4);
    CHECK_CLOSE(fd1, as_vector(0.0), (Tolerance{1e-9, 0.0}), "f' = 0 at the ends");
    CHECK_CLOSE(fdd, as_vector(0.0), (Tolerance{1e-3, 0.0}), "f'' = 0 at the ends");
  }
}

TEST_CASE("drive functions: invalid arguments are refused", "[drive]") {
  CHECK_THROWS_MENTIONING(DriveFunction::smooth_step(0, 1, 2.0, 2.0), std::invalid_argument, "needs t1 > t0");
  CHECK_THROWS_MENTIONING(DriveFunction::smooth_step(0, 1, 3.0, 2.0), std::invalid_argument, "needs t1 > t0");
  CHECK_THROWS_MENTIONING(DriveFunction::custom(std::function<DriveValue(double)>(), "none"), std::invalid_argument,
                          "empty function");
}
