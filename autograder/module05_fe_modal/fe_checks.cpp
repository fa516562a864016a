// The module 5 checks declared in fe_checks.hpp (documented there), compiled once for all the
// module's test files. Helpers used only here are in the anonymous namespace.

#include "fe_checks.hpp"

#include "linear_algebra.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace fmbd::testing::m05 {

namespace {

/// integral over [0, L] of f(x) by 5-point Gauss-Legendre (exact for polynomials up to degree 9).
double integrate(const std::function<double(double)>& f, double L) {
  static const double xi[5] = {-0.9061798459386640513, -0.5384693101056830910, 0.0, 0.5384693101056830910,
                               0.9061798459386640513};
  static const double wi[5] = {0.2369268850561890875, 0.4786286704993664680, 0.5688888888888888889,
                               0.4786286704993664680, 0.2369268850561890875};
  double sum = 0;
  for (int k = 0; k < 5; ++k) sum += wi[k] * f(0.5 * L * (1.0 + xi[k]));
  return 0.5 * L * sum;
}

using Row6 = Eigen::Matrix<double, 1, 6>;

/// u(x) = N_u(x) u_e: linear axial interpolation.
Row6 axial_shape(double x, double L) {
  const double s = x / L;
  Row6 N = Row6::Zero();
  N(0) = 1 - s;
  N(3) = s;
  return N;
}

/// v(x) = N_v(x) u_e: cubic Hermite interpolation of v from (v_a, psi_a, v_b, psi_b).
Row6 transverse_shape(double x, double L) {
  const double s = x / L;
  Row6 N = Row6::Zero();
  N(1) = 1 - 3 * s * s + 2 * s * s * s;
  N(2) = L * (s - 2 * s * s + s * s * s);
  N(4) = 3 * s * s - 2 * s * s * s;
  N(5) = L * (-s * s + s * s * s);
  return N;
}

/// u'(x) = B_u u_e.
Row6 axial_strain(double /*x*/, double L) {
  Row6 B = Row6::Zero();
  B(0) = -1 / L;
  B(3) = 1 / L;
  return B;
}

/// v''(x) = B_v(x) u_e: curvature of the Hermite interpolation.
Row6 curvature(double x, double L) {
  const double s = x / L;
  Row6 B = Row6::Zero();
  B(1) = (-6 + 12 * s) / (L * L);
  B(2) = (-4 + 6 * s) / L;
  B(4) = (6 - 12 * s) / (L * L);
  B(5) = (-2 + 6 * s) / L;
  return B;
}

/// Integral over the element of the 6x6 matrix f(x) (entrywise Gauss quadrature).
Mat6 integrate_matrix(const std::function<Mat6(double)>& f, double L) {
  Mat6 out;
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) out(r, c) = integrate([&](double x) { return f(x)(r, c); }, L);
  return out;
}

/// m_e = integral of rho A (N_u^T N_u + N_v^T N_v) dx.
Mat6 consistent_mass_by_quadrature(const Section& s, double L) {
  return integrate_matrix(
      [&](double x) -> Mat6 {
        const Row6 Nu = axial_shape(x, L), Nv = transverse_shape(x, L);
        return s.rho * s.A * (Nu.transpose() * Nu + Nv.transpose() * Nv);
      },
      L);
}

/// Copies of k with one entry, and with one symmetric pair of entries, negated, for every entry
/// (r, c) in `entries` (r < c).
void add_sign_suspects(std::vector<Suspect>& out, const Mat6& k, const std::vector<std::pair<int, int>>& entries,
                       const std::string& mistake) {
  for (const auto& [r, c] : entries) {
    Mat6 a = k, b = k, both = k;
    a(r, c) = -a(r, c);
    b(c, r) = -b(c, r);
    both(r, c) = -both(r, c);
    both(c, r) = -both(c, r);
    out.push_back({mistake, flat(a)});
    out.push_back({mistake, flat(b)});
    out.push_back({mistake, flat(both)});
  }
}

const char* const kStiffnessFormula =
    "k_e: EA/L [[1, -1], [-1, 1]] on (u_a, u_b); EI/L^3 [[12, 6L, -12, 6L], [6L, 4L^2, -6L, 2L^2], "
    "[-12, -6L, 12, -6L], [6L, 2L^2, -6L, 4L^2]] on (v_a, psi_a, v_b, psi_b)";

const char* const kConsistentFormula =
    "consistent m_e (m = rho A L): axial m/6 [[2, 1], [1, 2]]; bending m/420 [[156, 22L, 54, -13L], "
    "[22L, 4L^2, 13L, -3L^2], [54, 13L, 156, -22L], [-13L, -3L^2, -22L, 4L^2]]";

const char* const kLumpedFormula =
    "lumped m_e (m = rho A L): diag(m/2, m/2, m L^2/78, m/2, m/2, m L^2/78), zero off the diagonal";

/// R (3x3) with u_local = R u_global for a node, from the element axis e = (x_b - x_a)/L and its
/// normal n = perp(e): local axial = e . u, local transverse = n . u, psi unchanged.
Eigen::Matrix3d node_rotation(const Vec2& e) {
  const Vec2 n = perp(e);
  Eigen::Matrix3d R = Eigen::Matrix3d::Zero();
  R.block<1, 2>(0, 0) = e.transpose();
  R.block<1, 2>(1, 0) = n.transpose();
  R(2, 2) = 1;
  return R;
}

}  // namespace

// "beam_stiffness is wrong (...)" etc. when the student's T1/T2/T3 element functions disagree with
// the oracles on the elements of `fe`, else empty.
std::string element_upstream_hint(const FeModel& fe, MassMatrixType type) {
  std::string out;
  try {
    for (int e = 0; e < fe.num_elements(); ++e) {
      const Section& s = fe.elements()[e].section;
      const double L = fe.length(e);
      const Mat6 k = stiffness_by_quadrature(s, L);
      if (!compare(beam_stiffness(s, L), k, scaled(k, 1e-8)).ok) {
        out += "beam_stiffness is wrong (fix the T1 tests first). ";
        break;
      }
    }
  } catch (const std::exception&) {
    out += "beam_stiffness throws (fix T1 first). ";
  }
  try {
    for (int e = 0; e < fe.num_elements(); ++e) {
      const Section& s = fe.elements()[e].section;
      const double L = fe.length(e);
      const Mat6 m = mass_by_quadrature(s, L, type);
      if (!compare(beam_mass(s, L, type), m, scaled(m, 1e-8)).ok) {
        out += "beam_mass is wrong (fix the T2 tests first). ";
        break;
      }
    }
  } catch (const std::exception&) {
    out += "beam_mass throws (fix T2 first). ";
  }
  try {
    for (int e = 0; e < fe.num_elements(); ++e)
      if (!compare(beam_transformation(fe.angle(e)), element_rotation(axis_of(fe, e)), Tolerance{1e-12, 1e-12}).ok) {
        out += "beam_transformation is wrong (fix its T3 test first). ";
        break;
      }
  } catch (const std::exception&) {
    out += "beam_transformation throws. ";
  }
  return out;
}

std::string assembly_rule_hint(const FeModel& fe, MassMatrixType type) {
  const std::string upstream = element_upstream_hint(fe, type);
  if (!upstream.empty()) return upstream;
  return with_formula("your assemble: for every element add its matrices turned into the global frame (T = "
                      "beam_transformation(fe.angle(e))) to the blocks of its two nodes (three DOFs per node)",
                      "T^T k_e T and T^T m_e T; element DOFs 0..2 go to rows/columns 3a..3a+2, 3..5 to 3b..3b+2");
}

// ---- small helpers ------------------------------------------------------------------------

Section random_section(Random& rnd) {
  return Section{rnd.uniform(50e9, 220e9), rnd.uniform(1500, 8000), rnd.uniform(2e-4, 5e-3), rnd.uniform(2e-8, 2e-6)};
}

Section random_slender_section(Random& rnd, double length) {
  return square_section(rnd.uniform(60e9, 210e9), rnd.uniform(2000, 8000), length * rnd.uniform(0.008, 0.024));
}

// ---- shape functions and Gauss quadrature ---------------------------------------------------

Mat6 stiffness_by_quadrature(const Section& s, double L) {
  return integrate_matrix(
      [&](double x) -> Mat6 {
        const Row6 Bu = axial_strain(x, L), Bv = curvature(x, L);
        return s.E * s.A * Bu.transpose() * Bu + s.E * s.I * Bv.transpose() * Bv;
      },
      L);
}

Mat6 hrz_lumped_mass(const Section& s, double L) {
  const Mat6 c = consistent_mass_by_quadrature(s, L);
  const double m = integrate([&](double) { return s.rho * s.A; }, L);
  const double fu = m / (c(0, 0) + c(3, 3)), fv = m / (c(1, 1) + c(4, 4));
  Mat6 out = Mat6::Zero();
  out.diagonal() << fu * c(0, 0), fv * c(1, 1), fv * c(2, 2), fu * c(3, 3), fv * c(4, 4), fv * c(5, 5);
  return out;
}

Mat6 mass_by_quadrature(const Section& s, double L, MassMatrixType type) {
  return type == MassMatrixType::consistent ? consistent_mass_by_quadrature(s, L) : hrz_lumped_mass(s, L);
}

// ---- exact fields and their energies ------------------------------------------------------

Field random_field(Random& rnd, double L, double size, bool axial, bool bending) {
  Field f;
  if (axial) {
    f.a0 = size * rnd.uniform(-1, 1);
    f.a1 = size * rnd.uniform(-1, 1) / L;
  }
  if (bending) {
    f.b0 = size * rnd.uniform(-1, 1);
    f.b1 = size * rnd.uniform(-1, 1) / L;
    f.b2 = size * rnd.uniform(-1, 1) / (L * L);
    f.b3 = size * rnd.uniform(-1, 1) / (L * L * L);
  }
  return f;
}

double strain_product(const Section& s, double L, const Field& f1, const Field& f2) {
  return integrate([&](double x) { return s.E * s.A * f1.du(x) * f2.du(x) + s.E * s.I * f1.ddv(x) * f2.ddv(x); }, L);
}

double inertia_product(const Section& s, double L, const Field& f1, const Field& f2) {
  return integrate([&](double x) { return s.rho * s.A * (f1.u(x) * f2.u(x) + f1.v(x) * f2.v(x)); }, L);
}

// ---- element hints: which slip of the closed-form matrices reproduces the answer -------------

std::string stiffness_hint(const Mat6& actual, const Section& s, double L) {
  const Mat6 k = stiffness_by_quadrature(s, L);
  std::vector<Suspect> suspects;
  Mat6 swap_k = k;
  swap_k(2, 2) = swap_k(5, 5) = k(2, 5);
  swap_k(2, 5) = swap_k(5, 2) = k(2, 2);
  suspects.push_back({"4L^2 and 2L^2 swapped in the bending block? The diagonal psi entries are 4EI/L, the psi_a-psi_b "
                      "coupling 2EI/L",
                      flat(swap_k)});
  add_sign_suspects(suspects, k, {{1, 2}, {1, 5}, {2, 4}, {4, 5}},
                    "sign of a 6L term in the bending block: +6L couples v_a with psi_a and psi_b, -6L v_b with them");
  add_sign_suspects(suspects, k, {{1, 4}}, "sign of the 12 terms: +12 on the diagonal, -12 between v_a and v_b");
  add_sign_suspects(suspects, k, {{2, 5}}, "sign of 2L^2: psi_a-psi_b coupling is +2EI/L");
  add_sign_suspects(suspects, k, {{0, 3}}, "axial block sign: EA/L [[1, -1], [-1, 1]]");
  Mat6 no_A = k, EI_axial = k, bending_L2 = k, EI_only = k;
  for (int i : {0, 3})
    for (int j : {0, 3}) {
      no_A(i, j) /= s.A;
      EI_axial(i, j) *= s.I / s.A;
    }
  for (int i : {1, 2, 4, 5})
    for (int j : {1, 2, 4, 5}) {
      bending_L2(i, j) *= L;
      EI_only(i, j) /= s.E;
    }
  suspects.push_back({"E/L instead of EA/L? The axial stiffness is E A / L", flat(no_A)});
  suspects.push_back({"EI/L where EA/L belongs in the axial block", flat(EI_axial)});
  suspects.push_back({"bending factor is EI/L^3 (check the power of L)", flat(bending_L2)});
  suspects.push_back({"bending block without E: the factor is E I / L^3", flat(EI_only)});
  Mat6 k_T = k;
  k_T.block<2, 2>(0, 0).setZero();
  suspects.push_back({"the axial block is on DOFs 0 and 3 (u_a, u_b), bending on 1, 2, 4, 5", flat(k_T)});
  return diagnose(flat(actual), flat(k), suspects,
                  with_formula("your k_e differs from the Euler-Bernoulli element's stiffness", kStiffnessFormula),
                  scaled(k, 1e-8));
}

std::string mass_hint(const Mat6& actual, const Section& s, double L, MassMatrixType type) {
  const Mat6 m = mass_by_quadrature(s, L, type);
  const double total = s.rho * s.A * L;
  std::vector<Suspect> suspects;
  if (type == MassMatrixType::consistent) {
    Mat6 axial = m;
    axial(0, 0) = axial(3, 3) = total / 6;
    axial(0, 3) = axial(3, 0) = total / 3;
    suspects.push_back({with_formula("your m_e: consistent axial 1/6 and 1/3 swapped? The diagonal of the axial block "
                                     "is the larger", kConsistentFormula),
                        flat(axial)});
    add_sign_suspects(suspects, m, {{1, 2}, {4, 5}},
                      with_formula("your consistent m_e: sign of 22L, which couples v and psi of the same node",
                                   kConsistentFormula));
    add_sign_suspects(suspects, m, {{1, 5}, {2, 4}},
                      with_formula("your consistent m_e: sign of 13L, which couples v and psi of the two nodes",
                                   kConsistentFormula));
    add_sign_suspects(suspects, m, {{2, 5}},
                      with_formula("your consistent m_e: sign of 3L^2, which couples psi_a and psi_b",
                                   kConsistentFormula));
    Mat6 lumped_axial = m;
    lumped_axial(0, 0) = lumped_axial(3, 3) = total / 2;
    lumped_axial(0, 3) = lumped_axial(3, 0) = 0;
    suspects.push_back({with_formula("your consistent m_e has the lumped axial mass", kConsistentFormula),
                        flat(lumped_axial)});
    Mat6 no_axial = m;
    no_axial(0, 0) = no_axial(3, 3) = no_axial(0, 3) = no_axial(3, 0) = 0;
    suspects.push_back({with_formula("your consistent m_e: axial mass missing on u_a, u_b", kConsistentFormula),
                        flat(no_axial)});
    return diagnose(flat(actual), flat(m), suspects,
                    with_formula("your consistent m_e differs from the element's", kConsistentFormula),
                    scaled(m, 1e-8));
  }
  Mat6 rot0 = m, full = m, rot12 = m, rot420 = m;
  rot0(2, 2) = rot0(5, 5) = 0;
  for (int i : {0, 1, 3, 4}) full(i, i) = total;
  rot12(2, 2) = rot12(5, 5) = total * L * L / 12;
  rot420(2, 2) = rot420(5, 5) = total * L * L * 4 / 420;
  suspects.push_back({with_formula("your lumped m_e: lumped rotary term missing? HRZ gives each rotation a share, or M "
                                   "is singular", kLumpedFormula),
                      flat(rot0)});
  suspects.push_back({"your lumped m_e: lumped: half the element mass on each node, not all of it", flat(full)});
  suspects.push_back({with_formula("your lumped m_e: the rotary term is HRZ's, not that of a rod about its end",
                                   kLumpedFormula),
                      flat(rot12)});
  suspects.push_back({with_formula("your lumped m_e: the rotary term is the consistent one, not yet HRZ-scaled",
                                   kLumpedFormula),
                      flat(rot420)});
  return diagnose(flat(actual), flat(m), suspects,
                  with_formula("your lumped m_e differs from the element's", kLumpedFormula), scaled(m, 1e-8));
}

// ---- geometry: element axes, rigid motions, frames -------------------------------------------

Mat6 element_rotation(const Vec2& e) {
  Mat6 T = Mat6::Zero();
  T.topLeftCorner<3, 3>() = node_rotation(e);
  T.bottomRightCorner<3, 3>() = node_rotation(e);
  return T;
}

Vec2 axis_of(const FeModel& fe, int e) {
  const BeamElement& el = fe.elements()[e];
  return (fe.nodes()[el.node_b] - fe.nodes()[el.node_a]).normalized();
}

MatX rigid_motions(const FeModel& fe, const Vec2& centre) {
  MatX R = MatX::Zero(fe.num_dofs(), 3);
  for (int k = 0; k < fe.num_nodes(); ++k) {
    R(3 * k, 0) = 1;
    R(3 * k + 1, 1) = 1;
    const Vec2 d = perp(fe.nodes()[k] - centre);
    R(3 * k, 2) = d.x();
    R(3 * k + 1, 2) = d.y();
    R(3 * k + 2, 2) = 1;
  }
  return R;
}

FeModel l_frame(Random& rnd, int per_member, const Section& column, const Section& beam, int* foot) {
  const Vec2 base = rnd.vec2(-1, 1);
  const double h = rnd.uniform(1.0, 2.5), w = rnd.uniform(1.0, 2.5), tilt = rnd.uniform(-0.4, 0.4);
  const Vec2 up(-std::sin(tilt), std::cos(tilt)), along(std::cos(tilt), std::sin(tilt));
  std::vector<Vec2> points;
  for (int k = 0; k <= per_member; ++k) points.push_back(base + h * k / per_member * up);
  for (int k = 1; k <= per_member; ++k) points.push_back(base + h * up + w * k / per_member * along);
  // Scrambled numbering: the first n - 1 points in reverse order with neighbours swapped in pairs;
  // the last point (the beam's tip, only ever node b) gets the highest number, so that an assembly
  // that puts node b at 3a + 3 gives wrong entries instead of writing past the matrix.
  const int n = static_cast<int>(points.size());
  std::vector<int> index(n);
  for (int k = 0; k + 1 < n; ++k) index[k] = n - 2 - k;
  for (int k = 0; k + 2 < n; k += 2) std::swap(index[k], index[k + 1]);
  index[n - 1] = n - 1;
  std::vector<Vec2> placed(n);
  for (int k = 0; k < n; ++k) placed[index[k]] = points[k];
  FeModel fe;
  for (const Vec2& p : placed) fe.add_node(p);
  for (int k = 0; k + 1 < n; ++k) fe.add_element(index[k], index[k + 1], k < per_member ? column : beam);
  if (foot) *foot = index[0];
  return fe;
}

FeModel triangle_frame(Random& rnd, int per_member, const Section& s) {
  Vec2 c[3];
  for (;;) {
    for (Vec2& p : c) p = rnd.vec2(-2, 2);
    bool ok = true;
    for (int k = 0; k < 3; ++k) {
      const Vec2 a = c[(k + 1) % 3] - c[k], b = c[(k + 2) % 3] - c[k];
      if (a.norm() < 1.0 || std::acos(a.normalized().dot(b.normalized())) < 0.35) ok = false;
    }
    if (ok) break;
  }
  std::vector<Vec2> points;
  for (int side = 0; side < 3; ++side)
    for (int k = 0; k < per_member; ++k)
      points.push_back(c[side] + (c[(side + 1) % 3] - c[side]) * static_cast<double>(k) / per_member);
  const int n = static_cast<int>(points.size());
  std::vector<int> index(n);
  // A permutation if gcd(5, n) = 1. The point at position 1 (node b of both its elements) gets the
  // highest number, so that no element has it as node a (see l_frame).
  for (int k = 0; k < n; ++k) index[k] = ((5 * (k - 1) + n - 1) % n + n) % n;
  std::vector<Vec2> placed(n);
  for (int k = 0; k < n; ++k) placed[index[k]] = points[k];
  FeModel fe;
  for (const Vec2& p : placed) fe.add_node(p);
  for (int k = 0; k < n; ++k) {
    const int a = index[k], b = index[(k + 1) % n];
    if (k % 2 == 0)
      fe.add_element(a, b, s);
    else
      fe.add_element(b, a, s);
  }
  return fe;
}

// ---- supports and eigenvalues, written out ----------------------------------------------------

MatX rows_cols(const MatX& A, const std::vector<int>& idx) { return A(idx, idx); }

std::string describe(const std::vector<NodeSupport>& supports) {
  std::string out;
  for (const NodeSupport& s : supports) {
    if (!out.empty()) out += ", ";
    out += "node " + std::to_string(s.node) +
           (s.support == Support::clamped ? " clamped" : s.support == Support::hinged ? " hinged" : " free");
  }
  return out.empty() ? "no supports" : out;
}

DofMap random_map(Random& rnd, int num_nodes) {
  DofMap m;
  m.num_dofs = 3 * num_nodes;
  const int forced = static_cast<int>(rnd.uniform(0, 3));
  for (int i = 0; i < m.num_dofs; ++i)
    if (i != forced && rnd.uniform(0, 1) < 0.6) m.free.push_back(i);
  if (m.free.empty()) m.free.push_back(m.num_dofs - 1);
  return m;
}

VecX expand_by_hand(const VecX& u_free, const DofMap& map) {
  VecX u = VecX::Zero(map.num_dofs);
  for (int r = 0; r < map.num_free(); ++r) u(map.free[r]) = u_free(r);
  return u;
}

std::string reduce_matrix_hint(const MatX& A, const DofMap& map, const MatX& actual) {
  const int nf = map.num_free();
  const MatX right = rows_cols(A, map.free);
  return diagnose(flat(actual), flat(right),
                  {{with_formula("your reduce takes the top-left block: pick the rows and columns of the free DOFs",
                                 "A_ff(r, c) = A(free[r], free[c])"),
                    flat(MatX(A.topLeftCorner(nf, nf)))},
                   {with_formula("your reduce is transposed", "A_ff(r, c) = A(free[r], free[c])"),
                    flat(MatX(right.transpose()))}},
                  with_formula("your reduce must pick the rows and columns of the free DOFs, num_free x num_free",
                               "A_ff(r, c) = A(free[r], free[c])"),
                  Tolerance{1e-14, 0});
}

std::string reduce_vector_hint(const VecX& F, const DofMap& map, const VecX& actual) {
  return diagnose(actual, VecX(F(map.free)),
                  {{with_formula("your reduce takes the first entries: pick those of the free DOFs", "F_f(r) = F(free[r])"),
                    VecX(F.head(map.num_free()))}},
                  with_formula("your reduce must pick the entries of the free DOFs, num_free of them",
                               "F_f(r) = F(free[r])"),
                  Tolerance{1e-14, 0});
}

std::string expand_hint(const VecX& u_free, const DofMap& map, const VecX& actual) {
  VecX head = VecX::Zero(map.num_dofs);
  head.head(map.num_free()) = u_free;
  return diagnose(actual, expand_by_hand(u_free, map),
                  {{with_formula("your expand fills the first entries: u_free(r) belongs at the free DOF free[r]",
                                 "u(free[r]) = u_free(r)"),
                    head}},
                  "your expand must put zeros at fixed DOFs and u_free(r) at the free DOF free[r]; size num_dofs",
                  Tolerance{1e-14, 0});
}

VecX eigenvalues_by_hand(const MatX& K, const MatX& M) {
  return generalized_eigen(K, M, false).values;
}

VecX omegas_of(const VecX& lambda) { return lambda.cwiseMax(0.0).cwiseSqrt(); }

std::string omega_hint(const VecX& actual, const MatX& K, const MatX& M, int count) {
  const VecX lambda = eigenvalues_by_hand(K, M);
  const VecX right = omegas_of(lambda.head(count));
  const VecX top = omegas_of(lambda.tail(count));
  return diagnose(actual, right,
                  {{with_formula("your omega: omega is sqrt(lambda), not lambda", "K phi = lambda M phi, lambda = "
                                 "omega^2"),
                    VecX(lambda.head(count))},
                   {"largest modes instead of the lowest? Eigen returns lambda ascending: keep the first `count`",
                    top},
                   {"largest modes instead of the lowest? Eigen returns lambda ascending: keep the first `count`",
                    VecX(top.reverse())},
                   {"omega descending: return the lowest modes in ascending order", VecX(right.reverse())},
                   {"your omega is in Hz: omega is in rad/s (Modes::hertz divides by 2 pi)", VecX(right / (2 * kPi))},
                   {"omega is sqrt(lambda), not lambda / 2 or 2 lambda", VecX(lambda.head(count) / 2)}},
                  with_formula("your omega: the `count` lowest of the generalised symmetric eigenproblem, ascending",
                               "omega_i = sqrt(lambda_i) of K phi = lambda M phi"),
                  Tolerance{1e-9 * right.cwiseAbs().maxCoeff(), 1e-6});
}

std::string shapes_hint(const MatX& shapes, const MatX& M) {
  bool unit = shapes.cols() > 0;
  for (Eigen::Index c = 0; c < shapes.cols(); ++c) unit = unit && std::abs(shapes.col(c).norm() - 1) < 1e-8;
  if (unit)
    return with_formula("your shapes not mass-normalised: they have unit Euclidean norm, not unit M-norm",
                        "phi^T M phi = 1");
  bool m_unit = shapes.cols() > 0;
  for (Eigen::Index c = 0; c < shapes.cols(); ++c)
    m_unit = m_unit && std::abs(shapes.col(c).dot(M * shapes.col(c)) - 1) < 1e-6;
  if (m_unit)
    return with_formula("your shapes are mass-normalised but not eigenvectors: each column must solve the eigenproblem "
                        "with its own omega, in the order of omega", "K phi = omega^2 M phi");
  return with_formula("your shapes not mass-normalised: scale each column by its M-norm", "phi^T M phi = 1");
}

// ---- Euler-Bernoulli beams: tables and models ---------------------------------------------------

std::array<double, 4> beta_L(Ends e) {
  switch (e) {
    case Ends::clamped_free: return {1.87510407, 4.69409113, 7.85475744, 10.99554073};
    case Ends::pinned_pinned: return {kPi, 2 * kPi, 3 * kPi, 4 * kPi};
    case Ends::free_free:
    case Ends::clamped_clamped: return {4.73004074, 7.85320462, 10.99560784, 14.13716549};
    case Ends::clamped_pinned: return {3.92660231, 7.06858275, 10.21017612, 13.35176878};
  }
  return {0, 0, 0, 0};
}

double bending_omega(double betaL, const Section& s, double L) {
  return betaL * betaL * std::sqrt(s.E * s.I / (s.rho * s.A * L * L * L * L));
}

BeamProblem beam_problem(double L, double angle, const Section& s, int elements, Ends ends, MassMatrixType type,
                         const Vec2& start) {
  BeamProblem p;
  p.fe = straight_beam(L, elements, s, start, angle);
  p.section = s;
  p.L = L;
  p.angle = angle;
  // Element e spans DOFs 3e..3e+5 of the chain; in the beam's own axes no element is rotated.
  const int n = p.fe.num_dofs();
  const double h = L / elements;
  MatX K_axis = MatX::Zero(n, n), M_axis = MatX::Zero(n, n);
  for (int e = 0; e < elements; ++e) {
    K_axis.block<6, 6>(3 * e, 3 * e) += stiffness_by_quadrature(s, h);
    M_axis.block<6, 6>(3 * e, 3 * e) += mass_by_quadrature(s, h, type);
  }
  MatX R = MatX::Zero(n, n);
  for (int k = 0; k <= elements; ++k) R.block<3, 3>(3 * k, 3 * k) = node_rotation(Vec2(std::cos(angle), std::sin(angle)));
  const MatX K = R.transpose() * K_axis * R, M = R.transpose() * M_axis * R;
  // The ends: a clamp removes u_x, u_y and psi of its node, a pin u_x and u_y.
  const int last = 3 * elements;
  std::vector<int> fixed;
  switch (ends) {
    case Ends::clamped_free: fixed = {0, 1, 2}; break;
    case Ends::pinned_pinned: fixed = {0, 1, last, last + 1}; break;
    case Ends::free_free: break;
    case Ends::clamped_clamped: fixed = {0, 1, 2, last, last + 1, last + 2}; break;
    case Ends::clamped_pinned: fixed = {0, 1, 2, last, last + 1}; break;
  }
  for (int i = 0; i < n; ++i)
    if (std::find(fixed.begin(), fixed.end(), i) == fixed.end()) p.free.push_back(i);
  p.K = rows_cols(K, p.free);
  p.M = rows_cols(M, p.free);
  return p;
}

}  // namespace fmbd::testing::m05
