#include "fmbd/model.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "fmbd/errors.hpp"

namespace fmbd {

namespace {

std::string quoted(const std::string& name) { return "'" + name + "'"; }

// What a driver drives, as a key: two drivers with the same key drive the same quantity.
std::string driven_quantity(const Model& model, const ConstraintType& type) {
  std::ostringstream key;
  if (auto* d = std::get_if<AbsoluteAngleDriver>(&type)) {
    key << "the angle of body " << quoted(model.body_name(d->body));
  } else if (auto* d = std::get_if<RelativeAngleDriver>(&type)) {
    // Relative to the ground it is an absolute angle; (i, j) and (j, i) drive the same angle.
    if (d->body_i.is_ground() || d->body_j.is_ground()) {
      key << "the angle of body " << quoted(model.body_name(d->body_i.is_ground() ? d->body_j : d->body_i));
    } else {
      const auto [a, b] = std::minmax(d->body_i.index, d->body_j.index);
      key << "the relative angle of bodies " << quoted(model.body_name(BodyId{a})) << " and "
          << quoted(model.body_name(BodyId{b}));
    }
  } else if (auto* d = std::get_if<PointCoordinateDriver>(&type)) {
    key << "the " << (d->axis == Axis::x ? "x" : "y") << " coordinate of point "
        << quoted(model.point(d->P).name);
  } else if (auto* d = std::get_if<DistanceDriver>(&type)) {
    const auto a = std::min(d->P_i.index, d->P_j.index), b = std::max(d->P_i.index, d->P_j.index);
    key << "the distance between points " << quoted(model.points()[a].name) << " and "
        << quoted(model.points()[b].name);
  }
  return key.str();
}

}  // namespace

bool Constraint::is_driver() const {
  return std::holds_alternative<AbsoluteAngleDriver>(type) ||
         std::holds_alternative<RelativeAngleDriver>(type) ||
         std::holds_alternative<PointCoordinateDriver>(type) ||
         std::holds_alternative<DistanceDriver>(type);
}

const char* Constraint::type_name() const {
  static constexpr const char* names[] = {"revolute joint",        "translational joint",
                                          "fixed joint",           "absolute-angle driver",
                                          "relative-angle driver", "point-coordinate driver",
                                          "distance driver"};
  return names[type.index()];
}

// ---- builder -------------------------------------------------------------------------------

BodyId Model::add_body(const std::string& name, double mass, double inertia, const Vec3& q0) {
  check_new_name(name, "body");
  // Zero is allowed (a point mass, a massless link); whether the model is then well posed depends
  // on its joints, and the augmented solve names a motion that carries no mass.
  if (!(mass >= 0) || !std::isfinite(mass))
    throw ModelError("body " + quoted(name) + ": mass must be finite and not negative, got " + readable(mass));
  if (!(inertia >= 0) || !std::isfinite(inertia))
    throw ModelError("body " + quoted(name) + ": inertia must be finite and not negative, got " + readable(inertia));
  if (!q0.allFinite()) throw ModelError("body " + quoted(name) + ": initial guess q0 is not finite");
  return push_body(Body{name, mass, inertia, q0, nullptr});
}

BodyId Model::push_body(Body body) {
  offsets_.push_back(num_coordinates_);
  num_coordinates_ += body.num_coordinates();
  bodies_.push_back(std::move(body));
  return BodyId{num_bodies() - 1};
}

BodyId Model::add_flexible_body(const std::string& name, std::shared_ptr<const DeformableBody> deformable,
                                const Vec3& q0) {
  check_new_name(name, "body");
  if (!deformable) throw ModelError("flexible body " + quoted(name) + ": no deformable part given");
  if (!q0.allFinite()) throw ModelError("flexible body " + quoted(name) + ": initial guess q0 is not finite");
  const double mass = deformable->mass(), inertia = deformable->inertia();
  if (!(mass > 0) || !std::isfinite(mass) || !(inertia > 0) || !std::isfinite(inertia))
    throw ModelError("flexible body " + quoted(name) + ": its mass and inertia must be positive and finite");
  return push_body(Body{name, mass, inertia, q0, std::move(deformable)});
}

PointId Model::add_point(BodyId body, const Vec2& s_bar, const std::string& name) {
  check_new_name(name, "point");
  check_body(body, "point " + quoted(name));
  if (!body.is_ground() && bodies_[body.index].is_flexible())
    throw ModelError("point " + quoted(name) + ": body " + quoted(bodies_[body.index].name) +
                     " is flexible; attach points to its FE nodes with add_node_point");
  if (!s_bar.allFinite()) throw ModelError("point " + quoted(name) + ": coordinates are not finite");
  points_.push_back(Point{name, body, s_bar, -1});
  return PointId{static_cast<int>(points_.size()) - 1};
}

PointId Model::add_point_at(BodyId body, const Vec2& r, const std::string& name) {
  check_body(body, "point " + quoted(name));
  if (body.is_ground()) return add_point(body, r, name);
  const Vec3& q0 = bodies_[body.index].q0;
  return add_point(body, rotation(q0.z()).transpose() * (r - q0.head<2>()), name);
}

PointId Model::add_node_point(BodyId body, int node, const std::string& name) {
  check_new_name(name, "point");
  check_body(body, "point " + quoted(name));
  if (body.is_ground() || !bodies_[body.index].is_flexible())
    throw ModelError("point " + quoted(name) + ": body " + quoted(body_name(body)) +
                     " is not flexible; use add_point");
  const DeformableBody& d = *bodies_[body.index].deformable;
  if (node < 0 || node >= d.num_nodes())
    throw ModelError("point " + quoted(name) + ": body " + quoted(bodies_[body.index].name) + " has no node " +
                     std::to_string(node) + " (nodes 0 .. " + std::to_string(d.num_nodes() - 1) + ")");
  points_.push_back(Point{name, body, d.node_position(node), node});
  return PointId{static_cast<int>(points_.size()) - 1};
}

int Model::add_revolute(const std::string& name, PointId P_i, PointId P_j) {
  const std::string context = "revolute joint " + quoted(name);
  check_point(P_i, context);
  check_point(P_j, context);
  return add_constraint(name, Revolute{P_i, P_j}, point(P_i).body, point(P_j).body, 2);
}

int Model::add_translational(const std::string& name, PointId P_i, PointId P_j, const Vec2& axis_i,
                             double phi0) {
  const std::string context = "translational joint " + quoted(name);
  check_point(P_i, context);
  check_point(P_j, context);
  const double length = axis_i.norm();
  if (!(length > 1e-12) || !std::isfinite(length))
    throw ModelError(context + ": the sliding axis has zero length; give a direction such as (1, 0)");
  return add_constraint(name, Translational{P_i, P_j, axis_i / length, phi0}, point(P_i).body,
                        point(P_j).body, 2);
}

int Model::add_fixed(const std::string& name, PointId P_i, PointId P_j, double phi0) {
  const std::string context = "fixed joint " + quoted(name);
  check_point(P_i, context);
  check_point(P_j, context);
  return add_constraint(name, Fixed{P_i, P_j, phi0}, point(P_i).body, point(P_j).body, 3);
}

int Model::add_absolute_angle_driver(const std::string& name, BodyId body, DriveFunction f) {
  check_body(body, "absolute-angle driver " + quoted(name));
  if (body.is_ground()) throw ModelError("absolute-angle driver " + quoted(name) + ": the ground cannot be driven");
  return add_constraint(name, AbsoluteAngleDriver{body, std::move(f)}, body, ground, 1);
}

int Model::add_relative_angle_driver(const std::string& name, BodyId body_i, BodyId body_j, DriveFunction f) {
  const std::string context = "relative-angle driver " + quoted(name);
  check_body(body_i, context);
  check_body(body_j, context);
  return add_constraint(name, RelativeAngleDriver{body_i, body_j, std::move(f)}, body_i, body_j, 1);
}

int Model::add_point_coordinate_driver(const std::string& name, PointId P, Axis axis, DriveFunction f) {
  check_point(P, "point-coordinate driver " + quoted(name));
  if (point(P).body.is_ground())
    throw ModelError("point-coordinate driver " + quoted(name) + ": point " + quoted(point(P).name) +
                     " is on the ground and cannot be driven");
  return add_constraint(name, PointCoordinateDriver{P, axis, std::move(f)}, point(P).body, ground, 1);
}

int Model::add_distance_driver(const std::string& name, PointId P_i, PointId P_j, DriveFunction f) {
  const std::string context = "distance driver " + quoted(name);
  check_point(P_i, context);
  check_point(P_j, context);
  return add_constraint(name, DistanceDriver{P_i, P_j, std::move(f)}, point(P_i).body, point(P_j).body, 1);
}

int Model::add_constraint(const std::string& name, ConstraintType type, BodyId i, BodyId j, int rows) {
  check_new_name(name, "constraint");
  Constraint c{name, std::move(type), i, j, num_rows_, rows};
  if (i == j)
    throw ModelError(std::string(c.type_name()) + " " + quoted(name) + ": connects body " +
                     quoted(body_name(i)) + " to itself");
  if (c.is_driver()) {
    const std::string quantity = driven_quantity(*this, c.type);
    for (const Constraint& other : constraints_) {
      if (other.is_driver() && driven_quantity(*this, other.type) == quantity)
        throw ModelError(std::string(c.type_name()) + " " + quoted(name) + " duplicates driver " +
                         quoted(other.name) + ": both drive " + quantity);
    }
  }
  constraints_.push_back(std::move(c));
  num_rows_ += rows;
  return static_cast<int>(constraints_.size()) - 1;
}

// ---- forces --------------------------------------------------------------------------------

namespace {

void check_coefficient(double value, const std::string& context, const char* what) {
  if (!(value >= 0) || !std::isfinite(value))
    throw ModelError(context + ": " + what + " must be finite and not negative, got " + readable(value));
}

}  // namespace

void Model::set_gravity(const Vec2& g) {
  if (!g.allFinite()) throw ModelError("gravity is not finite");
  gravity_ = g;
}

int Model::add_point_force(const std::string& name, PointId P, const Vec2& F, Frame frame) {
  check_point(P, "point force " + quoted(name));
  if (point(P).body.is_ground())
    throw ModelError("point force " + quoted(name) + ": point " + quoted(point(P).name) +
                     " is on the ground, where a force does nothing");
  if (!F.allFinite()) throw ModelError("point force " + quoted(name) + ": F is not finite");
  return add_force(name, PointForce{P, F, frame});
}

int Model::add_torque(const std::string& name, BodyId body, DriveFunction T) {
  check_body(body, "torque " + quoted(name));
  if (body.is_ground()) throw ModelError("torque " + quoted(name) + ": a torque on the ground does nothing");
  return add_force(name, Torque{body, std::move(T)});
}

int Model::add_tsda(const std::string& name, PointId P_i, PointId P_j, double k, double L0, double c,
                    DriveFunction actuator) {
  const std::string context = "spring-damper " + quoted(name);
  check_point(P_i, context);
  check_point(P_j, context);
  check_coefficient(k, context, "stiffness k");
  check_coefficient(L0, context, "free length L0");
  check_coefficient(c, context, "damping c");
  if (point(P_i).body == point(P_j).body)
    throw ModelError(context + ": both points are on body " + quoted(body_name(point(P_i).body)));
  return add_force(name, Tsda{P_i, P_j, k, L0, c, std::move(actuator)});
}

int Model::add_rsda(const std::string& name, BodyId body_i, BodyId body_j, double k, double theta0, double c,
                    DriveFunction actuator) {
  const std::string context = "rotational spring-damper " + quoted(name);
  check_body(body_i, context);
  check_body(body_j, context);
  check_coefficient(k, context, "stiffness k");
  check_coefficient(c, context, "damping c");
  if (!std::isfinite(theta0)) throw ModelError(context + ": theta0 is not finite");
  if (body_i == body_j) throw ModelError(context + ": connects body " + quoted(body_name(body_i)) + " to itself");
  return add_force(name, Rsda{body_i, body_j, k, theta0, c, std::move(actuator)});
}

int Model::add_force(const std::string& name, ForceElement element) {
  check_new_name(name, "force");
  forces_.push_back(Force{name, std::move(element)});
  return static_cast<int>(forces_.size()) - 1;
}

// ---- checks --------------------------------------------------------------------------------

void Model::check_new_name(const std::string& name, const std::string& kind) const {
  if (name.empty()) throw ModelError("a " + kind + " needs a non-empty name");
  auto clash = [&](const auto& items) {
    for (const auto& item : items)
      if (item.name == name) return true;
    return false;
  };
  if ((kind == "body" && clash(bodies_)) || (kind == "point" && clash(points_)) ||
      (kind == "constraint" && clash(constraints_)) || (kind == "force" && clash(forces_)))
    throw ModelError("duplicate " + kind + " name " + quoted(name));
}

void Model::check_body(BodyId id, const std::string& context) const {
  if (id.index < -1 || id.index >= num_bodies())
    throw ModelError(context + ": body " + std::to_string(id.index) + " does not exist (the model has " +
                     std::to_string(num_bodies()) + " bodies; use fmbd::ground for the ground)");
}

void Model::check_point(PointId id, const std::string& context) const {
  if (id.index < 0 || id.index >= static_cast<int>(points_.size()))
    throw ModelError(context + ": point " + std::to_string(id.index) + " does not exist (the model has " +
                     std::to_string(points_.size()) + " points)");
}

void Model::check_size(const VecX& v, int expected, const char* what, const char* where) {
  if (v.size() != expected)
    throw std::invalid_argument(std::string(where) + ": " + what + " has size " + std::to_string(v.size()) +
                                ", expected " + std::to_string(expected));
}

// ---- queries -------------------------------------------------------------------------------

const Body& Model::body(BodyId id) const {
  if (id.index < 0 || id.index >= num_bodies())
    throw ModelError("body " + std::to_string(id.index) + " does not exist (the model has " +
                     std::to_string(num_bodies()) + " bodies)");
  return bodies_[id.index];
}

const Point& Model::point(PointId id) const {
  check_point(id, "Model::point");
  return points_[id.index];
}

BodyId Model::find_body(const std::string& name) const {
  for (int k = 0; k < num_bodies(); ++k)
    if (bodies_[k].name == name) return BodyId{k};
  if (name == "ground") return ground;
  throw ModelError("unknown body " + quoted(name));
}

PointId Model::find_point(const std::string& name) const {
  for (std::size_t k = 0; k < points_.size(); ++k)
    if (points_[k].name == name) return PointId{static_cast<int>(k)};
  throw ModelError("unknown point " + quoted(name));
}

std::string Model::body_name(BodyId id) const {
  return id.is_ground() ? "ground" : body(id).name;
}

int Model::offset(BodyId id) const {
  body(id);  // range check
  return offsets_[id.index];
}

VecX Model::initial_guess() const {
  VecX q = VecX::Zero(num_coordinates());
  for (int k = 0; k < num_bodies(); ++k) q.segment<3>(offsets_[k]) = bodies_[k].q0;
  return q;
}

Vec3 Model::body_coordinates(const VecX& q, BodyId id) const {
  check_size(q, num_coordinates(), "q", "Model::body_coordinates");
  if (id.is_ground()) return Vec3::Zero();
  return q.segment<3>(offset(id));
}

VecX Model::body_state(const VecX& q, BodyId id) const {
  check_size(q, num_coordinates(), "q", "Model::body_state");
  return q.segment(offset(id), body(id).num_coordinates());
}

std::string Model::describe_row(int row) const {
  for (const Constraint& c : constraints_) {
    if (row >= c.first_row && row < c.first_row + c.rows) {
      return std::string(c.type_name()) + " " + quoted(c.name) + " (equation " +
             std::to_string(row - c.first_row + 1) + " of " + std::to_string(c.rows) + ")";
    }
  }
  return "row " + std::to_string(row) + " (no such constraint row)";
}

std::string Model::describe_coordinate(int k) const {
  static constexpr const char* names[] = {"x", "y", "phi"};
  if (k < 0 || k >= num_coordinates()) return "coordinate " + std::to_string(k) + " (out of range)";
  const int b = static_cast<int>(std::upper_bound(offsets_.begin(), offsets_.end(), k) - offsets_.begin()) - 1;
  const int local = k - offsets_[b];
  if (local < 3) return std::string(names[local]) + " of body " + quoted(bodies_[b].name);
  return "q_f " + std::to_string(local - 3 + 1) + " of body " + quoted(bodies_[b].name);
}

}  // namespace fmbd
