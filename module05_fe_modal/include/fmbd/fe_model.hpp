#pragma once
// Planar frame finite-element models (module 5, given code).
//
// A model is a set of nodes (coordinates in the body frame, metres) and two-node Euler-Bernoulli
// frame elements between them. Every node has three degrees of freedom, in this order:
//
//   u = (u_x, u_y, psi) of node 0, then node 1, ...      size 3 N (N nodes)
//
// u_x, u_y are the nodal displacements along the model's x and y axes and psi the small rotation
// of the cross-section (counterclockwise positive). Node k occupies u(3k .. 3k+2).

#include <string>
#include <vector>

#include "fmbd/errors.hpp"
#include "fmbd/planar.hpp"

namespace fmbd {

/// Material and cross-section of a frame element (SI units). All four must be positive.
struct Section {
  double E = 0.0;    ///< Young's modulus [Pa]
  double rho = 0.0;  ///< density [kg/m^3]
  double A = 0.0;    ///< cross-section area [m^2]
  double I = 0.0;    ///< second moment of area about the bending axis [m^4]
};

/// A square solid section of side a: A = a^2, I = a^4 / 12.
Section square_section(double E, double rho, double side);

/// Kind of element mass matrix (module 5, task T2).
enum class MassMatrixType {
  consistent,  ///< from the element shape functions (linear axial, cubic Hermite bending)
  lumped       ///< diagonal: half the mass on each node, rotary term rho A L^3 / 78 (HRZ)
};

/// A two-node frame element from node_a to node_b.
struct BeamElement {
  int node_a = 0;
  int node_b = 0;
  Section section;
};

/// Degrees of freedom of one node, in their order within the node.
enum class NodeDof { ux = 0, uy = 1, psi = 2 };

/// Index of a nodal degree of freedom in the full vector u: 3 node + dof.
inline int dof_index(int node, NodeDof d) { return 3 * node + static_cast<int>(d); }

/// A planar frame: nodes and elements. Built once, then only read.
class FeModel {
 public:
  /// Adds a node at body-frame position x [m]; returns its index. Throws ModelError if x is
  /// not finite.
  int add_node(const Vec2& x);

  /// Adds an element between two existing nodes; returns its index. Throws ModelError if a
  /// node index is out of range, the nodes coincide (zero length), or E, rho, A or I is not
  /// positive and finite. Messages name the element and the offending value.
  int add_element(int node_a, int node_b, const Section& section);

  const std::vector<Vec2>& nodes() const { return nodes_; }
  const std::vector<BeamElement>& elements() const { return elements_; }
  int num_nodes() const { return static_cast<int>(nodes_.size()); }
  int num_elements() const { return static_cast<int>(elements_.size()); }
  int num_dofs() const { return 3 * num_nodes(); }

  /// Length L = |x_b - x_a| of element e [m]. Throws ModelError for an unknown element.
  double length(int e) const;
  /// Angle alpha of element e: the angle from the model's x axis to the vector x_b - x_a [rad].
  double angle(int e) const;

  /// Throws ModelError unless the model can be assembled: at least one element, and every node
  /// belongs to an element (a node without elements has no stiffness and no mass).
  void validate() const;

  /// Throws ModelError naming `context` if `node` is not a node of this model.
  void check_node(int node, const std::string& context) const;

 private:
  void check_element(int e, const char* context) const;
  std::vector<Vec2> nodes_;
  std::vector<BeamElement> elements_;
};

/// A straight beam of the given length from `start` at angle `angle` (rad) to the x axis, divided
/// into `elements` equal elements: nodes 0 .. elements, node 0 at `start`.
FeModel straight_beam(double length, int elements, const Section& section, const Vec2& start = Vec2::Zero(),
                      double angle = 0.0);

}  // namespace fmbd
