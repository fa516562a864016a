#pragma once
// Independent oracles shared by the graded tests: tolerances, entrywise comparison,
// central finite differences. Plain Eigen, no test framework.

#include <Eigen/Core>

#include <cmath>
#include <functional>
#include <initializer_list>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace fmbd::testing {

/// |actual - expected| <= atol + rtol * |expected|, entrywise.
struct Tolerance {
  double atol = 1e-9;
  double rtol = 1e-9;
};

struct Comparison {
  bool ok = true;
  std::string report;  // "max error 3e-12 at (1, 4)" or the worst entry when not ok
};

template <typename A, typename E>
Comparison compare(const Eigen::MatrixBase<A>& actual, const Eigen::MatrixBase<E>& expected,
                   Tolerance tol) {
  Comparison out;
  std::ostringstream s;
  if (actual.rows() != expected.rows() || actual.cols() != expected.cols()) {
    s << "size " << actual.rows() << "x" << actual.cols() << ", expected " << expected.rows()
      << "x" << expected.cols();
    return {false, s.str()};
  }
  double worst_excess = -1;
  Eigen::Index wr = 0, wc = 0;
  for (Eigen::Index c = 0; c < actual.cols(); ++c) {
    for (Eigen::Index r = 0; r < actual.rows(); ++r) {
      const double a = actual(r, c), e = expected(r, c);
      const double allowed = tol.atol + tol.rtol * std::abs(e);
      const double excess = std::isfinite(a) ? std::abs(a - e) / allowed
                                             : std::numeric_limits<double>::infinity();
      if (excess > worst_excess) {
        worst_excess = excess;
        wr = r;
        wc = c;
      }
    }
  }
  if (actual.size() == 0) return {true, "empty"};
  out.ok = worst_excess <= 1.0;
  s.precision(10);
  if (actual.size() == 1) {
    s << "got " << actual(0, 0) << ", expected " << expected(0, 0) << " (atol " << tol.atol << ", rtol "
      << tol.rtol << ")";
    out.report = s.str();
    return out;
  }
  s << "worst entry (" << wr << ", " << wc << "): got " << actual(wr, wc) << ", expected "
    << expected(wr, wc) << " (atol " << tol.atol << ", rtol " << tol.rtol << ")";
  out.report = s.str();
  return out;
}

inline Eigen::Matrix<double, 1, 1> as_matrix(double x) { return Eigen::Matrix<double, 1, 1>(x); }

/// Central difference Jacobian of f: R^n -> R^m at x, step h: (f(x + h e_k) - f(x - h e_k)) / 2h.
inline Eigen::MatrixXd finite_difference_jacobian(
    const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& f, const Eigen::VectorXd& x,
    double h = 1e-6) {
  const Eigen::VectorXd f0 = f(x);
  Eigen::MatrixXd J(f0.size(), x.size());
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    Eigen::VectorXd xp = x, xm = x;
    xp(k) += h;
    xm(k) -= h;
    J.col(k) = (f(xp) - f(xm)) / (2 * h);
  }
  return J;
}

/// Central first and second derivatives of g: R -> R^m at t, step h.
inline Eigen::VectorXd finite_difference_first(
    const std::function<Eigen::VectorXd(double)>& g, double t, double h = 1e-5) {
  return (g(t + h) - g(t - h)) / (2 * h);
}
inline Eigen::VectorXd finite_difference_second(
    const std::function<Eigen::VectorXd(double)>& g, double t, double h = 1e-4) {
  return (g(t + h) - 2 * g(t) + g(t - h)) / (h * h);
}

/// A typical wrong answer and the mistake that produces it.
struct Suspect {
  std::string mistake;
  Eigen::VectorXd value;
};

/// The mistake whose wrong answer `actual` matches (and the right answer `expected` does not),
/// or `otherwise`. Gives a failing check a hint that names the likely mistake.
inline std::string diagnose(const Eigen::VectorXd& actual, const Eigen::VectorXd& expected,
                            const std::vector<Suspect>& suspects, const std::string& otherwise,
                            Tolerance tol = Tolerance{1e-6, 1e-6}) {
  if (actual.size() != expected.size())
    return "wrong size: got " + std::to_string(actual.size()) + " entries, expected " +
           std::to_string(expected.size()) + ". " + otherwise;
  for (const Suspect& s : suspects) {
    if (s.value.size() != actual.size()) continue;
    if (compare(actual, s.value, tol).ok && !compare(expected, s.value, tol).ok) return s.mistake;
  }
  return otherwise;
}

/// A vector from a list: vec({1, 2, 3}).
inline Eigen::VectorXd vec(std::initializer_list<double> values) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index k = 0;
  for (double x : values) v(k++) = x;
  return v;
}

/// The entries of a matrix as one vector (column by column), for compare() of matrices.
template <typename Derived>
Eigen::VectorXd flat(const Eigen::MatrixBase<Derived>& m) {
  const Eigen::MatrixXd copy = m;
  return Eigen::Map<const Eigen::VectorXd>(copy.data(), copy.size());
}

/// Deterministic random numbers for tests: a fixed seed per test, so that a failure can be
/// reproduced and a hard-coded answer cannot pass.
class Random {
 public:
  explicit Random(unsigned seed) : engine_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }
  Eigen::VectorXd vector(Eigen::Index n, double lo, double hi) {
    Eigen::VectorXd v(n);
    for (Eigen::Index k = 0; k < n; ++k) v(k) = uniform(lo, hi);
    return v;
  }
  Eigen::Vector2d vec2(double lo, double hi) { return vector(2, lo, hi); }
  Eigen::Vector3d vec3(double lo, double hi) { return vector(3, lo, hi); }

 private:
  std::mt19937 engine_;
};

}  // namespace fmbd::testing
