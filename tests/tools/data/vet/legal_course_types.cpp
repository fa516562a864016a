// Legal constructs over the course's own types that the source check (fmbd-vet) must accept:
// every line is inside namespace fmbd, and what the compiler emits for it (weak typeinfo of
// function types over Eigen types, instantiations of std and Eigen templates over MatX, VecX,
// Vec3, Model and the body data, guards of static locals) is its own data, not the student's.
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "fmbd/dof.hpp"
#include "fmbd/flexible_body.hpp"
#include "fmbd/model.hpp"
#include "fmbd/planar.hpp"

namespace fmbd {
namespace {

// A template of the student's own in an unnamed namespace, instantiated over Eigen types.
template <typename Vector>
double weighted_norm(const Vector& v, double weight) {
  return weight * v.norm();
}

// A type of the student's own, used as a static local and in containers.
struct Cache {
  std::map<int, MatX> jacobians;
  std::vector<Vec3> poses;
  double scale(const Vec3& pose) const { return pose.norm() + static_cast<double>(poses.size()); }
};

double mass_of(const Body& body) { return body.mass; }
double total_mass(const Model& model) {
  double total = 0.0;
  for (int i = 0; i < model.num_bodies(); ++i) total += model.body(BodyId{i}).mass;
  return total;
}

}  // namespace

double legal_course_types(const Model& model, const MatX& Cq, const VecX& q) {
  // The case: a task function through a std::function of its exact signature, made from
  // its pointer, and the same through std::bind and a function pointer.
  const std::function<int(const MatX&)> rank = jacobian_rank;
  const std::function<int(const Model&, const VecX&, double)> dof = &degrees_of_freedom;
  int (*const rank_pointer)(const MatX&) = &jacobian_rank;
  const auto dof_now = std::bind(degrees_of_freedom, std::cref(model), std::placeholders::_1, 0.0);
  const std::function<double(const Model&)> mass = &total_mass;
  const std::function<double(const Body&)> body_mass = mass_of;

  // Lambdas that capture the course's types by value and by reference.
  const Vec3 offset(1.0, 2.0, 0.5);
  const auto shifted = [offset, Cq](const Vec3& pose) -> Vec3 { return pose + offset * Cq.rows(); };
  const auto residual = [&model, &q]() { return q.size() - model.num_coordinates(); };

  // std containers of the course's types, smart pointers to them, and a static local of the
  // student's own type (its guard).
  static Cache cache;
  cache.poses.push_back(shifted(Vec3::Zero()));
  cache.jacobians[static_cast<int>(cache.poses.size())] = Cq;
  std::vector<MatX> blocks{Cq, Cq.transpose()};
  std::map<std::string, VecX> named{{"q", q}};
  std::set<int> rows{0, 1};
  std::unique_ptr<Model> copy = std::make_unique<Model>(model);
  std::shared_ptr<const FlexibleBodyData> data = std::make_shared<FlexibleBodyData>();
  std::vector<Body> bodies;
  for (int i = 0; i < model.num_bodies(); ++i) bodies.push_back(model.body(BodyId{i}));

  double sum = weighted_norm(q, 2.0) + weighted_norm(offset, 1.0) + cache.scale(offset);
  sum += static_cast<double>(rank(Cq) + rank_pointer(Cq) + dof(model, q, 0.0) + dof_now(q) + residual());
  sum += mass(*copy) + (bodies.empty() ? 0.0 : body_mass(bodies.front()));
  sum += static_cast<double>(blocks.size() + named.size() + rows.size()) + (data ? 0.0 : 1.0);
  return sum;
}

}  // namespace fmbd
