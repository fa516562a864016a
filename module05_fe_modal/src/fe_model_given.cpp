// Planar frame FE models: building and checking (given code, module 5).
#include "fmbd/fe_model.hpp"

#include <cmath>
#include <sstream>

#include "fmbd/errors.hpp"

namespace fmbd {

namespace {

std::string element_name(int e, int a, int b) {
  std::ostringstream s;
  s << "element " << e << " (nodes " << a << "-" << b << ")";
  return s.str();
}

void check_positive(double value, const char* symbol, const char* what, const std::string& context) {
  if (!(std::isfinite(value) && value > 0.0)) {
    std::ostringstream s;
    s << context << ": " << what << " " << symbol << " must be positive and finite, got " << value;
    throw ModelError(s.str());
  }
}

}  // namespace

Section square_section(double E, double rho, double side) {
  return Section{E, rho, side * side, side * side * side * side / 12.0};
}

int FeModel::add_node(const Vec2& x) {
  if (!x.allFinite())
    throw ModelError("node " + std::to_string(num_nodes()) + ": coordinates are not finite");
  nodes_.push_back(x);
  return num_nodes() - 1;
}

void FeModel::check_node(int node, const std::string& context) const {
  if (node < 0 || node >= num_nodes())
    throw ModelError(context + ": node " + std::to_string(node) + " does not exist (the model has " +
                     std::to_string(num_nodes()) + " nodes, 0 .. " + std::to_string(num_nodes() - 1) + ")");
}

int FeModel::add_element(int node_a, int node_b, const Section& section) {
  const std::string name = element_name(num_elements(), node_a, node_b);
  check_node(node_a, name);
  check_node(node_b, name);
  const double L = (nodes_[node_b] - nodes_[node_a]).norm();
  if (!(L > 0.0)) throw ModelError(name + ": the nodes coincide, so the length is zero");
  check_positive(section.E, "E", "Young's modulus", name);
  check_positive(section.rho, "rho", "density", name);
  check_positive(section.A, "A", "cross-section area", name);
  check_positive(section.I, "I", "second moment of area", name);
  elements_.push_back(BeamElement{node_a, node_b, section});
  return num_elements() - 1;
}

void FeModel::check_element(int e, const char* context) const {
  if (e < 0 || e >= num_elements())
    throw ModelError(std::string(context) + ": element " + std::to_string(e) + " does not exist (the model has " +
                     std::to_string(num_elements()) + " elements)");
}

double FeModel::length(int e) const {
  check_element(e, "FeModel::length");
  const BeamElement& el = elements_[e];
  return (nodes_[el.node_b] - nodes_[el.node_a]).norm();
}

double FeModel::angle(int e) const {
  check_element(e, "FeModel::angle");
  const BeamElement& el = elements_[e];
  const Vec2 d = nodes_[el.node_b] - nodes_[el.node_a];
  return std::atan2(d.y(), d.x());
}

void FeModel::validate() const {
  if (elements_.empty()) throw ModelError("FE model: it has no elements");
  std::vector<bool> used(nodes_.size(), false);
  for (const BeamElement& el : elements_) used[el.node_a] = used[el.node_b] = true;
  for (int k = 0; k < num_nodes(); ++k)
    if (!used[k])
      throw ModelError("FE model: node " + std::to_string(k) +
                       " belongs to no element, so it has neither mass nor stiffness");
}

FeModel straight_beam(double length, int elements, const Section& section, const Vec2& start, double angle) {
  if (!(std::isfinite(length) && length > 0.0))
    throw ModelError("straight_beam: the length must be positive and finite, got " + readable(length));
  if (elements < 1)
    throw ModelError("straight_beam: at least one element is needed, got " + std::to_string(elements));
  const Vec2 step = length / elements * Vec2(std::cos(angle), std::sin(angle));
  FeModel fe;
  for (int k = 0; k <= elements; ++k) fe.add_node(start + k * step);
  for (int k = 0; k < elements; ++k) fe.add_element(k, k + 1, section);
  return fe;
}

}  // namespace fmbd
