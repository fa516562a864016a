// Module 5, task T4: supports by removal of DOFs: the free lists of clamped, hinged and free nodes
// DOF by DOF, and reduce / expand against index arithmetic written out here (visible tests).
#include <algorithm>
#include <string>
#include <vector>

#include "fe_checks.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/supports.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m05;

GRADED_TEST("apply_supports free lists for clamped hinged and free nodes", "[M05][T4][points=1]") {
  Random rnd(5401);
  // One support of each kind alone, then random mixtures (each node at most once).
  std::vector<std::pair<int, std::vector<NodeSupport>>> cases = {
      {4, {{0, Support::clamped}}}, {4, {{2, Support::hinged}}}, {3, {{1, Support::free}}}, {3, {}}};
  for (int n = 0; n < 8; ++n) {
    const int nodes = 3 + n % 5;
    std::vector<NodeSupport> supports;
    for (int k = 0; k < nodes; ++k) {
      const double pick = rnd.uniform(0, 1);
      if (pick < 0.3) supports.push_back({k, Support::clamped});
      else if (pick < 0.6) supports.push_back({k, Support::hinged});
      else if (pick < 0.75) supports.push_back({k, Support::free});
    }
    cases.push_back({nodes, supports});
  }
  for (const auto& [nodes, supports] : cases) {
    const FeModel fe = straight_beam(1.0, nodes - 1, square_section(2e11, 7800, 0.01));
    CAPTURE(nodes, describe(supports));
    const DofMap map = apply_supports(fe, supports);
    CHECK_NEAR_NAMED("your DofMap::num_dofs", map.num_dofs, 3.0 * nodes, (Tolerance{1e-14, 0}),
                     "DofMap::num_dofs is the size of the full vector u, 3 N = fe.num_dofs()");
    CAPTURE(as_vec(map.free).transpose());
    // The list: increasing, each DOF once, inside 0 .. 3N - 1.
    bool ordered = true;
    for (std::size_t r = 0; r < map.free.size(); ++r)
      ordered = ordered && map.free[r] >= 0 && map.free[r] < 3 * nodes && (r == 0 || map.free[r - 1] < map.free[r]);
    {
      INFO("hint: DofMap::free lists DOF numbers 0 .. 3N - 1 in increasing order, each once");
      CHECK(ordered);
    }
    // DOF by DOF: node k owns 3k (u_x), 3k + 1 (u_y) and 3k + 2 (psi); a clamp fixes all three, a
    // hinge u_x and u_y, and every DOF no support fixes is free.
    for (int k = 0; k < nodes; ++k) {
      Support kind = Support::free;
      for (const NodeSupport& s : supports)
        if (s.node == k) kind = s.support;
      for (int d = 0; d < 3; ++d) {
        const int i = 3 * k + d;
        const bool fixed = kind == Support::clamped || (kind == Support::hinged && d < 2);
        const bool listed = std::find(map.free.begin(), map.free.end(), i) != map.free.end();
        if (listed != fixed) continue;
        const char* dof_names[] = {"u_x", "u_y", "psi"};
        INFO("hint: " << with_formula(kind == Support::clamped ? "a clamp fixes u_x, u_y and psi: all three DOFs of its node"
                                      : kind == Support::hinged
                                          ? (d < 2 ? "a hinge fixes the position of its node: u_x and u_y"
                                                   : "a hinge lets the section turn: psi of a hinged node stays free")
                                          : "a node without a support (or Support::free) keeps all its DOFs in "
                                            "DofMap::free",
                                      "node k's DOFs are 3k (u_x), 3k+1 (u_y) and 3k+2 (psi)"));
        INFO(dof_names[d] << " of node " << k << " (DOF " << i << ") is "
                          << (listed ? "in your DofMap::free, but it is fixed" : "missing from your DofMap::free"));
        CHECK(listed == !fixed);
      }
    }
  }
  // Unknown nodes are refused (before any DOF is marked).
  const FeModel fe = straight_beam(1.0, 2, square_section(2e11, 7800, 0.01));
  CHECK_THROWS_MENTIONING(apply_supports(fe, {{0, Support::clamped}, {3, Support::hinged}}), ModelError, "node 3");
}

GRADED_TEST("reduce and expand round trip with zeros at fixed DOFs", "[M05][T4][points=1]") {
  Random rnd(5402);
  for (int n = 0; n < 8; ++n) {
    const int nodes = 2 + n % 4;
    const DofMap map = random_map(rnd, nodes);
    const int nf = map.num_free();
    CAPTURE(nodes, as_vec(map.free).transpose());
    const MatX A = MatX::NullaryExpr(map.num_dofs, map.num_dofs, [&] { return rnd.uniform(-1, 1); });  // not symmetric
    const VecX F = rnd.vector(map.num_dofs, -1, 1), u_f = rnd.vector(nf, -1, 1);

    const MatX A_ff = reduce(A, map);
    CHECK_CLOSE_NAMED("your reduce(A, map)",
                      A_ff, rows_cols(A, map.free), (Tolerance{1e-14, 0}), reduce_matrix_hint(A, map, A_ff));
    const VecX F_f = reduce(F, map);
    CHECK_CLOSE_NAMED("your reduce(F, map)",
                      F_f, VecX(F(map.free)), (Tolerance{1e-14, 0}), reduce_vector_hint(F, map, F_f));
    const VecX u = expand(u_f, map);
    const VecX u_expected = expand_by_hand(u_f, map);
    CHECK_CLOSE_NAMED("your expand(u_f, map)", u, u_expected, (Tolerance{1e-14, 0}), expand_hint(u_f, map, u));
    // Round trips: reduce(expand(u_f)) = u_f, and expand(reduce(F)) = F with zeros at the fixed DOFs.
    CHECK_CLOSE_NAMED("your reduce(expand(u_f))",
                      reduce(u, map), u_f, (Tolerance{1e-14, 0}), "reduce(expand(u_f)) must give u_f back");
    CHECK_CLOSE_NAMED("your expand(reduce(F))",
                      expand(F_f, map), expand_by_hand(VecX(F(map.free)), map), (Tolerance{1e-14, 0}),
                      "expand puts zeros at fixed DOFs: expand(reduce(F)) is F with the fixed entries zeroed");
  }
}
