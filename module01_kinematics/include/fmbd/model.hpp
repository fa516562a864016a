#pragma once
// The model: constant structure of a planar multibody system (bodies, points, joints,
// drivers, and from module 3 on gravity and force elements), built once with the builder API and then only read. The state (q, q_dot, t)
// lives outside it and is passed to the free functions of every module.
//
// Coordinates: q = (x_1, y_1, phi_1, x_2, y_2, phi_2, ...), size 3 n_b for rigid bodies. Body k
// (0-based) occupies q(offset(k) .. offset(k) + 2), offset(k) = 3k while every body is rigid.
// A flexible body (module 7 on) has 3 + n_f coordinates (R_x, R_y, theta, q_f), so the offsets
// of the bodies after it shift by n_f. The ground is not a body: `ground` has no coordinates.
//
// Constraints are numbered in the order they were added; constraint c occupies rows
// first_row .. first_row + rows - 1 of C(q, t) (eq. 1).

#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "fmbd/deformable.hpp"
#include "fmbd/drive_function.hpp"
#include "fmbd/planar.hpp"

namespace fmbd {

/// Index of a body in Model::bodies(); `ground` (index -1) is the fixed global frame.
struct BodyId {
  int index = -1;
  bool is_ground() const { return index < 0; }
  friend bool operator==(BodyId a, BodyId b) { return a.index == b.index; }
  friend bool operator!=(BodyId a, BodyId b) { return a.index != b.index; }
};
inline constexpr BodyId ground{-1};

/// Index of a point in Model::points().
struct PointId {
  int index = -1;
  friend bool operator==(PointId a, PointId b) { return a.index == b.index; }
};

/// A body. q0 is its initial guess (x, y, phi) for the position analysis. A rigid body has no
/// `deformable` part; a flexible body (module 7 on) has one, and (x, y, phi) are then the
/// coordinates (R, theta) of its floating frame at the undeformed centroid.
struct Body {
  std::string name;
  double mass = 1.0;     ///< m [kg], >= 0 (used from module 3 on)
  double inertia = 1.0;  ///< J about the centroid [kg m^2], >= 0 (used from module 3 on)
  Vec3 q0 = Vec3::Zero();
  std::shared_ptr<const DeformableBody> deformable;  ///< null for a rigid body

  bool is_flexible() const { return deformable != nullptr; }
  int num_coordinates() const { return 3 + (deformable ? deformable->num_modes() : 0); }
};

/// A point on a body: s_bar are its body-frame coordinates relative to the centroid. On the
/// ground, s_bar is the global position. A point on a flexible body sits at an FE node
/// (node >= 0); its s_bar is then the undeformed node position x_bar_k, for reference only.
struct Point {
  std::string name;
  BodyId body;
  Vec2 s_bar = Vec2::Zero();
  int node = -1;  ///< FE node on a flexible body, -1 on a rigid body or the ground
};

enum class Axis { x = 0, y = 1 };

// ---- Joint and driver types. Body i owns P_i, body j owns P_j. -----------------------------

/// Revolute joint (2 rows): r_Pi - r_Pj = 0.
struct Revolute {
  PointId P_i, P_j;
};
/// Translational (prismatic) joint (2 rows): P_j slides along the line through P_i with
/// direction axis_i (body-i frame, unit length), and the bodies keep their relative angle:
///   n_i^T (r_Pj - r_Pi) = 0,  n_i = A_i I~ axis_i;   phi_j - phi_i - phi0 = 0.
struct Translational {
  PointId P_i, P_j;
  Vec2 axis_i = Vec2::UnitX();
  double phi0 = 0.0;
};
/// Fixed joint (3 rows): r_Pi - r_Pj = 0 and phi_j - phi_i - phi0 = 0. With body i = ground
/// it welds body j to the ground.
struct Fixed {
  PointId P_i, P_j;
  double phi0 = 0.0;
};
/// Absolute-angle driver (1 row): phi_i - f(t) = 0.
struct AbsoluteAngleDriver {
  BodyId body;
  DriveFunction f;
};
/// Relative-angle driver (1 row): phi_j - phi_i - f(t) = 0.
struct RelativeAngleDriver {
  BodyId body_i, body_j;
  DriveFunction f;
};
/// Point-coordinate driver (1 row): e_axis^T r_P - f(t) = 0.
struct PointCoordinateDriver {
  PointId P;
  Axis axis;
  DriveFunction f;
};
/// Distance driver (1 row): 1/2 (d^T d - f(t)^2) = 0 with d = r_Pj - r_Pi.
/// (The squared form stays smooth where d passes through zero.)
struct DistanceDriver {
  PointId P_i, P_j;
  DriveFunction f;
};

using ConstraintType = std::variant<Revolute, Translational, Fixed, AbsoluteAngleDriver,
                                    RelativeAngleDriver, PointCoordinateDriver, DistanceDriver>;

// ---- Force elements (used from module 3 on). ----------------------------------------------

enum class Frame { global, body };

/// A constant force F applied at point P, with F given in the global frame or in the frame of
/// the point's body (a follower force that turns with the body).
struct PointForce {
  PointId P;
  Vec2 F = Vec2::Zero();
  Frame frame = Frame::global;
};
/// A pure torque T(t) on a body (counter-clockwise positive).
struct Torque {
  BodyId body;
  DriveFunction T;
};
/// Translational spring-damper-actuator between P_i and P_j, acting along the line P_i -> P_j.
/// Its tension is f = k (L - L0) + c L_dot + f_a(t), L = |r_Pj - r_Pi|: positive f pulls the
/// points together.
struct Tsda {
  PointId P_i, P_j;
  double k = 0.0, L0 = 0.0, c = 0.0;
  DriveFunction actuator;
};
/// Rotational spring-damper-actuator between body i and body j (either may be the ground),
/// acting on the relative angle theta = phi_j - phi_i with the torque
/// T = k (theta - theta0) + c theta_dot + T_a(t): -T on body j, +T on body i.
struct Rsda {
  BodyId body_i, body_j;
  double k = 0.0, theta0 = 0.0, c = 0.0;
  DriveFunction actuator;
};

using ForceElement = std::variant<PointForce, Torque, Tsda, Rsda>;

struct Force {
  std::string name;
  ForceElement element;
};

/// One joint or driver and where its equations sit in C.
struct Constraint {
  std::string name;
  ConstraintType type;
  BodyId body_i;       ///< first body (may be ground)
  BodyId body_j;       ///< second body (ground for one-body drivers)
  int first_row = 0;   ///< row of its first equation in C
  int rows = 0;        ///< number of equations: 1, 2 or 3
  bool is_driver() const;
  const char* type_name() const;  ///< "revolute", "distance driver", ...
};

class Model {
 public:
  // ---- builder: each call checks its arguments and throws ModelError naming the culprit ----

  /// Adds a body with mass m >= 0, centroidal inertia J >= 0 and initial guess q0 = (x, y, phi).
  /// Zero makes a point mass (J = 0) or a massless link (m = J = 0); the model must then be well
  /// posed: every motion that its constraints allow carries mass (see solve_augmented).
  BodyId add_body(const std::string& name, double mass, double inertia, const Vec3& q0 = Vec3::Zero());
  /// Adds a point with body-frame coordinates s_bar on `body` (global coordinates on ground).
  /// Throws ModelError on a flexible body: use add_node_point there.
  PointId add_point(BodyId body, const Vec2& s_bar, const std::string& name);
  /// Adds a point at global position r in the initial configuration: on a body, at
  /// s_bar = A(phi0)^T (r - R0) with (R0, phi0) its initial guess q0, so that published data
  /// given at joints can be entered as it stands (calls rotation(), task M01T1). Throws
  /// ModelError on a flexible body.
  PointId add_point_at(BodyId body, const Vec2& r, const std::string& name);

  /// Adds a flexible body (modules 7 and 8) with its elastic part; q0 = (R, theta) is the initial
  /// guess of its floating frame, and its elastic coordinates start at zero.
  BodyId add_flexible_body(const std::string& name, std::shared_ptr<const DeformableBody> deformable,
                           const Vec3& q0 = Vec3::Zero());
  /// Adds a point at FE node `node` of a flexible body; joints and forces attach there.
  PointId add_node_point(BodyId body, int node, const std::string& name);

  int add_revolute(const std::string& name, PointId P_i, PointId P_j);
  /// axis_i (body-i frame) is normalised; a zero-length axis throws.
  int add_translational(const std::string& name, PointId P_i, PointId P_j, const Vec2& axis_i,
                        double phi0 = 0.0);
  int add_fixed(const std::string& name, PointId P_i, PointId P_j, double phi0 = 0.0);
  int add_absolute_angle_driver(const std::string& name, BodyId body, DriveFunction f);
  int add_relative_angle_driver(const std::string& name, BodyId body_i, BodyId body_j, DriveFunction f);
  int add_point_coordinate_driver(const std::string& name, PointId P, Axis axis, DriveFunction f);
  int add_distance_driver(const std::string& name, PointId P_i, PointId P_j, DriveFunction f);

  /// Uniform gravitational acceleration g (global frame, m/s^2) on every body; default zero.
  void set_gravity(const Vec2& g);
  int add_point_force(const std::string& name, PointId P, const Vec2& F, Frame frame = Frame::global);
  int add_torque(const std::string& name, BodyId body, DriveFunction T);
  /// k >= 0, L0 >= 0, c >= 0; actuator f_a(t) defaults to zero.
  int add_tsda(const std::string& name, PointId P_i, PointId P_j, double k, double L0, double c,
               DriveFunction actuator = DriveFunction::constant(0.0));
  /// k >= 0, c >= 0; actuator T_a(t) defaults to zero.
  int add_rsda(const std::string& name, BodyId body_i, BodyId body_j, double k, double theta0, double c,
               DriveFunction actuator = DriveFunction::constant(0.0));

  // ---- queries ----
  int num_bodies() const { return static_cast<int>(bodies_.size()); }
  int num_coordinates() const { return num_coordinates_; }  ///< n = 3 n_b + sum of n_f
  /// Index in q of the first coordinate of `body` (3k while all bodies are rigid).
  int offset(BodyId body) const;
  int num_constraints() const { return num_rows_; }         ///< m = rows of C
  const std::vector<Body>& bodies() const { return bodies_; }
  const std::vector<Point>& points() const { return points_; }
  const std::vector<Constraint>& constraints() const { return constraints_; }
  const std::vector<Force>& forces() const { return forces_; }
  const Vec2& gravity() const { return gravity_; }
  const Body& body(BodyId id) const;    ///< throws for ground or an unknown id
  const Point& point(PointId id) const;
  BodyId find_body(const std::string& name) const;  ///< throws ModelError if absent
  PointId find_point(const std::string& name) const;
  std::string body_name(BodyId id) const;  ///< "ground" for the ground

  /// Stacked initial guesses q0 of all bodies (size n; elastic coordinates zero).
  VecX initial_guess() const;
  /// Coordinates (x, y, phi) of `body` taken from q (of a flexible body: its frame (R, theta));
  /// zero for the ground. Checks sizes.
  Vec3 body_coordinates(const VecX& q, BodyId body) const;
  /// All coordinates of `body` (3 or 3 + n_f) taken from q. Checks sizes; not for the ground.
  VecX body_state(const VecX& q, BodyId body) const;
  /// "revolute joint 'A' (equation 2 of 2)" for a row of C.
  std::string describe_row(int row) const;
  /// "phi of body 'crank'" or "q_f 2 of body 'rod'" for an entry of q.
  std::string describe_coordinate(int k) const;
  /// Throws std::invalid_argument unless v.size() == expected, naming `what` and `where`.
  static void check_size(const VecX& v, int expected, const char* what, const char* where);

 private:
  void check_body(BodyId id, const std::string& context) const;
  void check_point(PointId id, const std::string& context) const;
  void check_new_name(const std::string& name, const std::string& kind) const;
  int add_constraint(const std::string& name, ConstraintType type, BodyId i, BodyId j, int rows);
  int add_force(const std::string& name, ForceElement element);

  BodyId push_body(Body body);

  std::vector<Body> bodies_;
  std::vector<int> offsets_;
  int num_coordinates_ = 0;
  std::vector<Point> points_;
  std::vector<Constraint> constraints_;
  std::vector<Force> forces_;
  Vec2 gravity_ = Vec2::Zero();
  int num_rows_ = 0;
};

}  // namespace fmbd
