// The hidden module 5 oracles declared in fe_oracles.hpp (documented there).

#include "fe_oracles.hpp"

#include <exception>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace fmbd::testing::m05 {

namespace {

// The numbering of a node's DOFs, behind the hint gate.
constexpr const char* kNodeDofs = "node k's DOFs are 3k (u_x), 3k+1 (u_y) and 3k+2 (psi)";

/// Free DOFs under a slipped rule: `fixes(kind)` lists the fixed DOFs (0 u_x, 1 u_y, 2 psi) of a
/// support kind, `combine` 0 the union, 1 the last support of a node wins, 2 the first one wins;
/// `stride` 3 (right) or 1 (node k taken as DOF k).
std::vector<int> free_with(int num_nodes, const std::vector<NodeSupport>& supports,
                           const std::function<std::vector<int>(Support)>& fixes, int combine, int stride = 3) {
  std::vector<int> state(3 * num_nodes, 0);  // 0 untouched, 1 fixed, 2 touched and free
  std::vector<bool> seen(num_nodes, false);
  for (const NodeSupport& s : supports) {
    if (combine == 2 && seen[s.node]) continue;
    if (combine == 1) {
      for (int d = 0; d < 3; ++d)
        if (stride * s.node + d < 3 * num_nodes) state[stride * s.node + d] = 0;
    }
    for (int d : fixes(s.support))
      if (stride * s.node + d < 3 * num_nodes) state[stride * s.node + d] = 1;
    seen[s.node] = true;
  }
  std::vector<int> out;
  for (int i = 0; i < 3 * num_nodes; ++i)
    if (state[i] != 1) out.push_back(i);
  return out;
}

}  // namespace

FeMatrices assemble_by_hand(const FeModel& fe, MassMatrixType type, Slip slip) {
  const int n = fe.num_dofs();
  FeMatrices out{MatX::Zero(n, n), MatX::Zero(n, n)};
  for (int e = 0; e < fe.num_elements(); ++e) {
    const BeamElement& el = fe.elements()[e];
    const double L = fe.length(e);
    Mat6 T = element_rotation(axis_of(fe, e));
    if (slip == Slip::unrotated) T.setIdentity();
    if (slip == Slip::T_transposed) T.transposeInPlace();
    const Mat6 k = T.transpose() * stiffness_by_quadrature(el.section, L) * T;
    const Mat6 m = T.transpose() * mass_by_quadrature(el.section, L, type) * T;
    const int at[2] = {3 * el.node_a, slip == Slip::node_b_after_a ? 3 * el.node_a + 3 : 3 * el.node_b};
    if (at[1] + 3 > n) continue;  // the slip ran off the matrix; the hint will not match
    for (int r = 0; r < 2; ++r)
      for (int c = 0; c < 2; ++c) {
        out.K.block<3, 3>(at[r], at[c]) += k.block<3, 3>(3 * r, 3 * c);
        out.M.block<3, 3>(at[r], at[c]) += m.block<3, 3>(3 * r, 3 * c);
      }
  }
  return out;
}

std::string assembly_hint(const MatX& actual, const FeModel& fe, MassMatrixType type, bool stiffness) {
  auto pick = [&](const FeMatrices& m) { return flat(stiffness ? m.K : m.M); };
  const FeMatrices right = assemble_by_hand(fe, type);
  const MatX& expected = stiffness ? right.K : right.M;
  const std::string upstream = element_upstream_hint(fe, type);
  if (actual.rows() == expected.rows() && actual.cols() == expected.cols() &&
      compare(actual, expected, scaled(expected, 1e-8)).ok)
    return upstream;  // this matrix is right
  if (!upstream.empty()) {
    // Is assemble right given the student's own element matrices? Then only those are to blame.
    try {
      const int n = fe.num_dofs();
      MatX mine = MatX::Zero(n, n);
      for (int e = 0; e < fe.num_elements(); ++e) {
        const BeamElement& el = fe.elements()[e];
        const Mat6 T = beam_transformation(fe.angle(e));
        const Mat6 local = stiffness ? beam_stiffness(el.section, fe.length(e)) : beam_mass(el.section, fe.length(e), type);
        const Mat6 g = T.transpose() * local * T;
        const int at[2] = {3 * el.node_a, 3 * el.node_b};
        for (int r = 0; r < 2; ++r)
          for (int c = 0; c < 2; ++c) mine.block<3, 3>(at[r], at[c]) += g.block<3, 3>(3 * r, 3 * c);
      }
      if (actual.rows() == n && actual.cols() == n && compare(actual, mine, scaled(mine, 1e-8)).ok)
        return upstream + "(assemble itself adds your element matrices correctly)";
    } catch (const std::exception&) {
    }
  }
  const std::string diagnosis = diagnose(
      flat(actual), pick(right),
      {{with_formula("your assembly turns the element matrices with T transposed: T turns global displacements into "
                     "local ones", "the global element matrix is T^T k_e T"),
        pick(assemble_by_hand(fe, type, Slip::T_transposed))},
       {with_formula("your assembly: element matrices not rotated? Turn each into the global frame with T = "
                     "beam_transformation(fe.angle(e))", "T^T k_e T and T^T m_e T"),
        pick(assemble_by_hand(fe, type, Slip::unrotated))},
       {with_formula("your assembly puts node b right after node a: node b's DOFs start at node b's own block (three "
                     "DOFs per node, numbered node by node), not after node a's",
                     "element DOFs 3..5 go to rows 3 node_b .. 3 node_b + 2, not 3a + 3 .. 3a + 5"),
        pick(assemble_by_hand(fe, type, Slip::node_b_after_a))}},
      with_formula("add each element's matrices, turned into the global frame, to the blocks of its two nodes (three "
                   "DOFs per node), for every element",
                   "T^T k_e T: element DOFs 0..2 to rows/columns 3a..3a+2, 3..5 to 3b..3b+2"),
      scaled(expected, 1e-8));
  return upstream + diagnosis;
}

std::vector<int> free_dofs_by_hand(int num_nodes, const std::vector<NodeSupport>& supports) {
  std::vector<bool> fixed(3 * num_nodes, false);
  for (const NodeSupport& s : supports) {
    if (s.support == Support::free) continue;
    fixed[3 * s.node] = fixed[3 * s.node + 1] = true;
    if (s.support == Support::clamped) fixed[3 * s.node + 2] = true;
  }
  std::vector<int> out;
  for (int i = 0; i < 3 * num_nodes; ++i)
    if (!fixed[i]) out.push_back(i);
  return out;
}

DofMap map_by_hand(int num_nodes, const std::vector<NodeSupport>& supports) {
  DofMap m;
  m.num_dofs = 3 * num_nodes;
  m.free = free_dofs_by_hand(num_nodes, supports);
  return m;
}

std::string free_list_hint(int num_nodes, const std::vector<NodeSupport>& supports, const std::vector<int>& actual) {
  auto right = [](Support k) {
    return k == Support::clamped ? std::vector<int>{0, 1, 2} : k == Support::hinged ? std::vector<int>{0, 1}
                                                                                     : std::vector<int>{};
  };
  auto hinge_psi = [](Support k) { return k == Support::free ? std::vector<int>{} : std::vector<int>{0, 1, 2}; };
  auto hinge_only_psi = [](Support k) {
    return k == Support::clamped ? std::vector<int>{0, 1, 2} : k == Support::hinged ? std::vector<int>{2}
                                                                                     : std::vector<int>{};
  };
  auto clamp_two = [](Support k) { return k == Support::free ? std::vector<int>{} : std::vector<int>{0, 1}; };
  std::vector<int> fixed_list;
  {
    const std::vector<int> f = free_dofs_by_hand(num_nodes, supports);
    std::vector<bool> is_free(3 * num_nodes, false);
    for (int i : f) is_free[i] = true;
    for (int i = 0; i < 3 * num_nodes; ++i)
      if (!is_free[i]) fixed_list.push_back(i);
  }
  const std::vector<std::pair<std::string, std::vector<int>>> suspects = {
      {with_formula("hinged must fix u_x and u_y, not psi: a hinge lets the section turn", kNodeDofs),
       free_with(num_nodes, supports, hinge_psi, 0)},
      {with_formula("hinged must fix u_x and u_y, not psi: yours fixes the section's rotation only", kNodeDofs),
       free_with(num_nodes, supports, hinge_only_psi, 0)},
      {"repeated supports: the fixed DOFs are the union; a later support of the same node must not free DOFs",
       free_with(num_nodes, supports, right, 1)},
      {"repeated supports: the fixed DOFs are the union; a later support of the same node adds its DOFs",
       free_with(num_nodes, supports, right, 2)},
      {with_formula("clamped fixes all three DOFs of the node (psi too)", kNodeDofs),
       free_with(num_nodes, supports, clamp_two, 0)},
      {with_formula("your DOF numbers count one DOF per node: each node has three (u_x, u_y, psi), numbered node by "
                    "node",
                    "node k's DOFs are 3k, 3k+1, 3k+2, not k, k+1, k+2"),
       free_with(num_nodes, supports, right, 0, 1)},
      {"DofMap::free lists the free DOFs, not the fixed ones", fixed_list}};
  const std::vector<int> expected = free_dofs_by_hand(num_nodes, supports);
  for (const auto& [mistake, list] : suspects)
    if (actual == list && expected != list) return mistake;
  return with_formula("clamped fixes all three DOFs of its node, hinged the two displacements, free nothing; "
                      "DofMap::free lists every other DOF, ascending",
                      kNodeDofs);
}

const char* name_of(Ends e) {
  switch (e) {
    case Ends::clamped_free: return "clamped-free";
    case Ends::pinned_pinned: return "pinned-pinned";
    case Ends::free_free: return "free-free";
    case Ends::clamped_clamped: return "clamped-clamped";
    case Ends::clamped_pinned: return "clamped-pinned";
  }
  return "?";
}

}  // namespace fmbd::testing::m05
