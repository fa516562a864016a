// Common legal constructs of a solution that the source check (fmbd-vet) must accept: every line
// is inside namespace fmbd, and what the compiler emits for it (weak typeinfo of function types,
// instantiations of std templates, guards of static locals, lambdas' closures) is its own data.
#include <algorithm>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fmbd {

// A student's own exception class, thrown and caught.
class SolverError : public std::runtime_error {
 public:
  explicit SolverError(const std::string& what) : std::runtime_error(what) {}
};

namespace {

int twice(int x) { return 2 * x; }
double halve(double x) noexcept { return 0.5 * x; }
std::vector<double> summarise(const std::map<std::string, double>& table, const SolverError* error) {
  return {static_cast<double>(table.size()), error == nullptr ? 0.0 : 1.0};
}

// A function template and a class template of the student's own, instantiated.
template <typename T>
T square(T x) {
  return x * x;
}

template <typename T>
struct Accumulator {
  T total{};
  void add(T value) { total += value; }
};

struct Shape {
  virtual ~Shape() = default;
  virtual double area() const = 0;
};

struct Square : Shape {
  double side = 1.0;
  double area() const override { return side * side; }
};

}  // namespace

int legal_constructs(int n) {
  // std::function made from function pointers (weak typeinfo of int (*)(int) and of the
  // noexcept function type), from a lambda, and a plain function pointer.
  std::function<int(int)> f = &twice;
  std::function<double(double)> g = &halve;
  int (*pointer)(int) = &twice;
  std::function<std::vector<double>(const std::map<std::string, double>&, const SolverError*)> k = &summarise;
  std::function<const char*(const SolverError&)> member = &SolverError::what;
  const int offset = n;
  std::function<int(int)> h = [offset](int x) { return x + offset; };
  auto lambda = [](int x) { return x - 1; };

  // std::map, std::vector and std::sort with a lambda.
  std::map<std::string, int> counts{{"a", 1}, {"b", 2}};
  std::vector<int> values{3, 1, 2};
  std::sort(values.begin(), values.end(), [](int a, int b) { return a > b; });

  // Debug output: iostream and ostringstream.
  std::ostringstream text;
  text << "n = " << n << ", first = " << values.front();
  if (n < 0) std::cout << text.str() << std::endl;

  // Exceptions: std::runtime_error and the student's own class.
  int caught = 0;
  try {
    if (n > 100) throw std::runtime_error("too large");
    if (n > 50) throw SolverError("did not converge");
  } catch (const SolverError& error) {
    caught = 2 + static_cast<int>(std::string(error.what()).size() > 0);
  } catch (const std::runtime_error&) {
    caught = 1;
  }

  // A static local (its guard) and the student's own templates.
  static const std::vector<double> table{1.0, 2.0, 3.0};
  Accumulator<double> sum;
  sum.add(square(table[1]));
  sum.add(g(square(2.0)));

  // std::unique_ptr and std::shared_ptr, with a virtual class of the student's own.
  std::unique_ptr<Shape> shape = std::make_unique<Square>();
  std::shared_ptr<Accumulator<int>> shared = std::make_shared<Accumulator<int>>();
  shared->add(square(n));

  const SolverError unused("unused");
  const int more = static_cast<int>(k({{"x", 1.0}}, &unused).size() + std::string(member(unused)).size());
  return more + f(n) + h(n) + pointer(n) + lambda(n) + counts["b"] + caught + static_cast<int>(sum.total) +
         static_cast<int>(shape->area()) + shared->total;
}

}  // namespace fmbd
