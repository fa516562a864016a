#include "fmbd/marker.hpp"

#include "fmbd/planar.hpp"

#include <stdexcept>
#include <string>
#include <type_traits>

namespace fmbd {

NodeMarker& NodeMarkerStore::slot(int node, int num_nodes) const {
  if (node < 0 || node >= num_nodes)
    throw std::out_of_range("node marker: node " + std::to_string(node) + " of a body of " +
                            std::to_string(num_nodes) + " nodes");
  const std::thread::id me = std::this_thread::get_id();
  const std::lock_guard<std::mutex> lock(mutex_);
  for (auto& [id, markers] : per_thread_)
    if (id == me) {
      if (static_cast<int>(markers.size()) != num_nodes) markers.resize(num_nodes);
      return markers[node];
    }
  per_thread_.emplace_back(me, std::vector<NodeMarker>(num_nodes));
  return per_thread_.back().second[node];
}

Marker body_marker(const Model& model, BodyId body, const VecX& q, const VecX& qd) {
  Marker m;
  m.body = body;
  if (body.is_ground()) return m;
  m.offset = model.offset(body);
  m.q = q.segment<3>(m.offset);
  m.qd = qd.segment<3>(m.offset);
  return m;
}

Marker point_marker(const Model& model, PointId P, const VecX& q, const VecX& qd) {
  const Point& point = model.point(P);
  Marker m = body_marker(model, point.body, q, qd);
  m.s_bar = point.s_bar;
  if (point.body.is_ground() || point.node < 0) return m;
  const Body& body = model.body(point.body);
  const int n = body.num_coordinates();
  thread_local VecX q_j, qd_j;  // the body's coordinates: no allocation once they have its size
  q_j = q.segment(m.offset, n);
  qd_j = qd.segment(m.offset, n);
  const NodeMarker& node = body.deformable->kept_node_marker(point.node, q_j, qd_j);
  m.q = node.pose;
  m.qd = node.velocity;
  m.s_bar = Vec2::Zero();
  m.kinematics = &node;
  m.convective = node.convective;
  m.node = point.node;
  m.deformable = body.deformable.get();
  return m;
}

Vec2 point_position(const Model& model, PointId P, const VecX& q) {
  const Marker m = point_marker(model, P, q, VecX::Zero(q.size()));
  return point_position(m.q, m.s_bar);  // M01T1, on the pose the kernels see
}

ConstraintMarkers constraint_markers(const Model& model, const Constraint& constraint, const VecX& q,
                                     const VecX& qd) {
  return std::visit(
      [&](const auto& c) -> ConstraintMarkers {
        using T = std::decay_t<decltype(c)>;
        if constexpr (std::is_same_v<T, AbsoluteAngleDriver>) {
          return {body_marker(model, c.body, q, qd), Marker{}};
        } else if constexpr (std::is_same_v<T, RelativeAngleDriver>) {
          return {body_marker(model, c.body_i, q, qd), body_marker(model, c.body_j, q, qd)};
        } else if constexpr (std::is_same_v<T, PointCoordinateDriver>) {
          return {point_marker(model, c.P, q, qd), Marker{}};
        } else {
          return {point_marker(model, c.P_i, q, qd), point_marker(model, c.P_j, q, qd)};
        }
      },
      constraint.type);
}

ConstraintMarkers constraint_markers(const Model& model, const Constraint& constraint, const VecX& q) {
  thread_local VecX at_rest;  // zeros of the last model's size: no allocation from call to call
  if (at_rest.size() != q.size()) at_rest = VecX::Zero(q.size());
  return constraint_markers(model, constraint, q, at_rest);
}

void add_node_jacobian_columns(MatX& Cq, int first_row, const Marker& marker, const RowBlock& block) {
  marker.deformable->add_node_columns(marker.node_kinematics(), block, first_row, marker.offset, Cq);
}

void add_node_generalised_force(VecX& target, const Marker& marker, const Vec3& Q) {
  marker.deformable->add_node_force(marker.node_kinematics(), Q, marker.offset, target);
}

}  // namespace fmbd
