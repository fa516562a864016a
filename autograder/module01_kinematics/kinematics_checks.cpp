// Definitions of the module-1 checks (see kinematics_checks.hpp), compiled once per build.
#include "kinematics_checks.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

namespace fmbd::m01 {

namespace {

// The hint for C_q entries in local row `row` of constraint `c`: body i or j, x-y or phi columns.
Hint jacobian_hint(const Constraint& c, int row, bool body_i, bool phi) {
  switch (c.type.index()) {
    case 1:  // translational: row 0 normal offset, row 1 angle
      if (row == 1) return hint::angle_row_Cq;
      if (!phi) return hint::translational_Cq_translation;
      return body_i ? hint::translational_Cq_phi_i : hint::translational_Cq_phi_j;
    case 0:
    case 2:  // revolute, fixed: rows 0-1 points, fixed row 2 angle
      if (row == 2) return hint::angle_row_Cq;
      if (phi) return hint::revolute_Cq_phi;
      return body_i ? hint::revolute_Cq_i_translation : hint::revolute_Cq_j_translation;
    case 3: return hint::absolute_Cq;
    case 4: return hint::relative_Cq;
    case 5: return hint::coordinate_Cq;
    default: return hint::distance_Cq;
  }
}

std::string where(const Constraint& c) {
  return std::string(c.type_name()) + " '" + c.name + "', rows " + std::to_string(c.first_row) + ".." +
         std::to_string(c.first_row + c.rows - 1) + " of C (counted from 0)";
}

// A link from a to b: centroid at mid-length, body x axis along a -> b.
Vec3 link_between(const Vec2& a, const Vec2& b) {
  const Vec2 mid = 0.5 * (a + b), d = b - a;
  return Vec3(mid.x(), mid.y(), std::atan2(d.y(), d.x()));
}

}  // namespace

// ---- hints ----------------------------------------------------------------------------------

bool rotation_is_right() {
  try {
    for (double phi : {0.3, 1.9, -2.6}) {
      if (!testing::compare(rotation(phi), rot(phi), kExact).ok) return false;
    }
    return true;
  } catch (...) {  // not implemented yet
    return false;
  }
}

std::ostream& operator<<(std::ostream& out, const Hint& hint) {
  if (hint.builds_on_rotation && !rotation_is_right())
    out << "rotation() is not A(phi) yet, and this check goes through it: make the rotation tests (T1) pass "
           "first. Then: ";
  return out << testing::with_formula(hint.text, hint.formula);
}

// ---- one block ------------------------------------------------------------------------------

BlockDifferences block_differences(const BlockOfQ& block, const Vec3& q_i, const Vec3& q_j) {
  VecX x(6);
  x << q_i, q_j;
  const MatX J = testing::finite_difference_jacobian(
      [&](const VecX& y) -> VecX {
        const ConstraintBlock b = block(y.head<3>(), y.tail<3>());
        return VecX(b.C);
      },
      x, 1e-6);
  return {J.leftCols(3), J.rightCols(3)};
}

VecX time_difference(const std::function<ConstraintBlock(const DriveValue&)>& block, const DriveFunction& f,
                     double t) {
  return testing::finite_difference_first([&](double s) -> VecX { return VecX(block(f(s)).C); }, t, 1e-5);
}

// ---- whole model ----------------------------------------------------------------------------

ConstraintEvaluation kernel_evaluation(const Model& model, const VecX& q, double t) {
  const int m = model.num_constraints(), n = model.num_coordinates();
  ConstraintEvaluation e{VecX::Zero(m), MatX::Zero(m, n), VecX::Zero(m)};
  for (const Constraint& c : model.constraints()) {
    const ConstraintBlock b = evaluate_constraint(model, c, q, t);
    e.C.segment(c.first_row, c.rows) = b.C;
    e.Ct.segment(c.first_row, c.rows) = b.Ct;
    if (!c.body_i.is_ground()) e.Cq.block(c.first_row, model.offset(c.body_i), c.rows, 3) += b.Cq_i;
    if (!c.body_j.is_ground()) e.Cq.block(c.first_row, model.offset(c.body_j), c.rows, 3) += b.Cq_j;
  }
  return e;
}

bool check_model_derivatives(const Model& model, const VecX& q, double t) {
  const ConstraintEvaluation e = kernel_evaluation(model, q, t);
  const MatX J = testing::finite_difference_jacobian(
      [&](const VecX& y) -> VecX { return kernel_evaluation(model, y, t).C; }, q, 1e-6);
  const VecX Ct = testing::finite_difference_first(
      [&](double s) -> VecX { return kernel_evaluation(model, q, s).C; }, t, 1e-5);
  bool ok = true;
  for (const Constraint& c : model.constraints()) {
    INFO(where(c) << " at q = " << show(q) << ", t = " << t);
    for (bool side_i : {true, false}) {
      const BodyId body = side_i ? c.body_i : c.body_j;
      if (body.is_ground()) continue;
      for (bool phi : {false, true}) {
        INFO("this block: the " << (phi ? "phi column" : "x and y columns") << " of body "
                               << (side_i ? "i" : "j") << " '" << model.body_name(body)
                               << "' in these rows (its entries (row, column) count from 0 within the block)");
        const auto C_q_block = e.Cq.block(c.first_row, model.offset(body) + (phi ? 2 : 0), c.rows, phi ? 1 : 2);
        const auto fd = J.block(c.first_row, model.offset(body) + (phi ? 2 : 0), c.rows, phi ? 1 : 2);
        int bad = 0;
        while (bad < c.rows && testing::compare(C_q_block.row(bad), fd.row(bad), kFD).ok) ++bad;
        CHECK_CLOSE_NAMED("your C_q in this block", C_q_block, fd, kFD,
                          jacobian_hint(c, bad < c.rows ? bad : 0, side_i, phi));
        ok = ok && bad == c.rows;
      }
    }
    const auto rows_Ct = e.Ct.segment(c.first_row, c.rows);
    const auto fd_Ct = Ct.segment(c.first_row, c.rows);
    const Hint h = !c.is_driver() ? hint::joint_Ct : c.type.index() == 6 ? hint::distance_Ct : hint::driver_Ct;
    CHECK_CLOSE_NAMED("your C_t in these rows", rows_Ct, fd_Ct, kFD, h);
    ok = ok && testing::compare(rows_Ct, fd_Ct, kFD).ok;
  }
  return ok;
}

namespace {

bool near(const MatX& a, const MatX& b, double scale) { return (a - b).cwiseAbs().maxCoeff() <= 1e-9 * scale; }

// The likely mistake behind a block of the student's C_q (rows of c, columns of `body`) that is
// `got` where the kernels give `want`; `before` is what out held there before the call.
Hint block_hint(const Model& model, const Constraint& c, BodyId body, const MatX& got, const MatX& want,
                const MatX& before) {
  const double scale = std::max(1.0, std::max(want.cwiseAbs().maxCoeff(), got.cwiseAbs().maxCoeff()));
  if (!before.isZero(0.0) && near(got, want + before, scale)) return hint::assembly_stale;
  if (want.isZero(0.0)) {
    const bool has_ground = c.body_i.is_ground() || c.body_j.is_ground();
    return has_ground && model.offset(body) == 0 ? hint::assembly_ground : hint::assembly_columns;
  }
  if (near(got, 2 * want, scale)) return hint::assembly_twice;
  if (near(got, -want, scale)) return hint::assembly_sign;
  return hint::assembly_columns;
}

// The student's rows of one vector (C or C_t) against the kernels', rows of c.
bool check_rows(const VecX& got, const VecX& want, const VecX& before, const Constraint& c, const char* what) {
  const VecX g = got.segment(c.first_row, c.rows), w = want.segment(c.first_row, c.rows);
  if (testing::compare(g, w, kExact).ok) return true;
  const bool kept = !before.segment(c.first_row, c.rows).isZero(0.0) && g == before.segment(c.first_row, c.rows);
  INFO(what << ": the rows of " << where(c));
  CHECK_CLOSE_NAMED(std::string("your assembled ") + what + " in these rows", g, w, kExact,
                    kept ? hint::assembly_stale : hint::assembly_rows);
  return false;
}

}  // namespace

bool check_assembly(const Model& model, const VecX& q, double t, ConstraintEvaluation& out, const std::string& label) {
  INFO(label << ", q = " << show(q) << ", t = " << t);
  const ConstraintEvaluation before = out;
  evaluate_constraints(model, q, t, out);
  const ConstraintEvaluation want = kernel_evaluation(model, q, t);
  for (const Constraint& c : model.constraints()) {
    if (!check_rows(out.C, want.C, before.C, c, "C") || !check_rows(out.Ct, want.Ct, before.Ct, c, "C_t")) return false;
  }
  // A two-body constraint's rows of C_q left empty (of a constraint with the ground, they may be
  // empty because a block went to the ground's side: the per-body check below names that).
  for (const Constraint& c : model.constraints()) {
    if (c.body_i.is_ground() || c.body_j.is_ground()) continue;
    const MatX band = out.Cq.middleRows(c.first_row, c.rows), expected = want.Cq.middleRows(c.first_row, c.rows);
    if (!band.isZero(0.0) || expected.isZero(0.0)) continue;
    INFO("C_q: the rows of " << where(c) << ", all columns");
    CHECK_CLOSE_NAMED("your assembled C_q in these rows", band, expected, kExact, hint::assembly_Cq_rows);
    return false;
  }
  for (const Constraint& c : model.constraints()) {
    for (int k = 0; k < model.num_bodies(); ++k) {
      const BodyId body{k};
      const int at = model.offset(body);
      const MatX got = out.Cq.block(c.first_row, at, c.rows, 3), expected = want.Cq.block(c.first_row, at, c.rows, 3);
      if (testing::compare(got, expected, kExact).ok) continue;
      INFO("C_q: the rows of " << where(c) << ", the 3 columns of body '" << model.body_name(body) << "' (from column "
                               << at << ")");
      CHECK_CLOSE_NAMED("your assembled C_q in this block", got, expected, kExact,
                        block_hint(model, c, body, got, expected, before.Cq.block(c.first_row, at, c.rows, 3)));
      return false;
    }
  }
  // Your C_q and C_t are the derivatives of your own C.
  const MatX J = testing::finite_difference_jacobian([&](const VecX& y) -> VecX { return constraints(model, y, t); }, q, 1e-6);
  const VecX Ct = testing::finite_difference_first([&](double s) -> VecX { return constraints(model, q, s); }, t, 1e-5);
  INFO("C_q and C_t against central differences of your assembled C");
  CHECK_CLOSE_NAMED("your assembled C_q", out.Cq, J, kFD, hint::assembly_consistent);
  CHECK_CLOSE_NAMED("your assembled C_t", out.Ct, Ct, kFD, hint::assembly_consistent);
  return testing::compare(out.Cq, J, kFD).ok && testing::compare(out.Ct, Ct, kFD).ok;
}

Model assembly_model() {
  Model m;
  const BodyId b0 = m.add_body("b0", 1, 1), b1 = m.add_body("b1", 1, 1), b2 = m.add_body("b2", 1, 1);
  const PointId a0 = m.add_point(b0, Vec2(0.3, 0.1), "a0"), a1 = m.add_point(b1, Vec2(-0.2, 0.05), "a1");
  const PointId c1 = m.add_point(b1, Vec2(0.25, -0.1), "c1"), c2 = m.add_point(b2, Vec2(-0.15, 0.2), "c2");
  const PointId g2 = m.add_point(ground, Vec2(1.0, -0.5), "g2"), e2 = m.add_point(b2, Vec2(0.1, 0.3), "e2");
  const PointId d0 = m.add_point(b0, Vec2(-0.3, 0.2), "d0"), g1 = m.add_point(ground, Vec2(-1.0, 0.4), "g1");
  m.add_revolute("b0-b1", a0, a1);                       // 2 rows, bodies 0 and 1
  m.add_translational("b1-b2", c1, c2, Vec2(0.6, 0.8));  // 2 rows, bodies 1 and 2
  m.add_revolute("ground-b2", g2, e2);                    // 2 rows, the ground on side i
  m.add_absolute_angle_driver("b1 angle", b1, DriveFunction::polynomial({0.2, 0.7}));
  m.add_distance_driver("b0-b2 cable", d0, e2, DriveFunction::polynomial({0.9, 0.1, -0.05}));
  m.add_relative_angle_driver("b2 on ground", b2, ground, DriveFunction::polynomial({-0.3, 0.4}));  // ground on side j
  m.add_point_coordinate_driver("b0 x", d0, Axis::x, DriveFunction::polynomial({0.1, -0.2}));
  m.add_fixed("ground-b1", g1, m.add_point(b1, Vec2(0.05, 0.15), "f1"), 0.4);  // 3 rows, the ground on side i
  return m;
}

bool check_model_closes(const Model& model, const VecX& q, double t, Tolerance tol) {
  const VecX C = kernel_evaluation(model, q, t).C;
  bool ok = true;
  for (const Constraint& c : model.constraints()) {
    INFO(where(c) << " at q = " << show(q) << ", t = " << t);
    const auto rows = C.segment(c.first_row, c.rows);
    const VecX zero = VecX::Zero(c.rows);
    Hint h = hint::driver_C;
    switch (c.type.index()) {
      case 0: h = hint::revolute_closed; break;
      case 1: h = hint::translational_on_line; break;
      case 2: h = hint::fixed_closed; break;
      case 6: h = hint::distance_C; break;
      default: break;
    }
    const bool ok_c = testing::compare(rows, zero, tol).ok;
    CHECK_CLOSE_NAMED("your C in these rows", rows, zero, tol, h);
    ok = ok && ok_c;
  }
  return ok;
}

// ---- closed-form configurations -------------------------------------------------------------

VecX four_bar_configuration(const examples::FourBarParameters& p, double theta) {
  Vec2 C;
  REQUIRE(examples::four_bar_joint_C(p, theta, C));
  const Vec2 B(p.a * std::cos(theta), p.a * std::sin(theta));
  VecX q(9);
  q << link_between(Vec2::Zero(), B), link_between(B, C), link_between(C, Vec2(p.d, 0));
  q(2) = theta;
  return q;
}

Vec3 place(const Vec2& r, const Vec2& s_bar, double phi) {
  const double c = std::cos(phi), s = std::sin(phi);
  const Vec2 As(c * s_bar.x() - s * s_bar.y(), s * s_bar.x() + c * s_bar.y());
  return Vec3(r.x() - As.x(), r.y() - As.y(), phi);
}

Mat2 rot(double phi) {
  Mat2 A;
  A << std::cos(phi), -std::sin(phi), std::sin(phi), std::cos(phi);
  return A;
}

}  // namespace fmbd::m01
