// Module 3, task T1: the mass matrix of other models (hidden tests).
#include <string>

#include "dynamics_checks.hpp"
#include "fmbd/mass_matrix.hpp"
#include "grading.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m03;

GRADED_TEST("mass_matrix four-bar and single bodies kinetic energy and momentum", "[M03][T1][points=1]") {
  Random rnd(3151);
  std::vector<Model> models;
  models.push_back(examples::four_bar());
  for (int k = 0; k < 3; ++k) {
    Model m;
    m.add_body("only", rnd.uniform(0.2, 20.0), rnd.uniform(0.001, 0.5), rnd.vec3(-1, 1));
    models.push_back(m);
  }
  for (const Model& model : models) {
    const MatX M = mass_matrix(model);
    const int n = model.num_coordinates();
    INFO("hint: " << with_formula("your M is not n x n, one row and column per coordinate",
                                  "block k = diag(m_k, m_k, J_k)"));
    REQUIRE(M.rows() == n);
    REQUIRE(M.cols() == n);
    for (int trial = 0; trial < 3; ++trial) {
      const VecX qd = rnd.vector(n, -3, 3);
      double T = 0;
      for (int k = 0; k < model.num_bodies(); ++k) {
        const Body& b = model.bodies()[k];
        T += 0.5 * b.mass * qd.segment<2>(3 * k).squaredNorm() + 0.5 * b.inertia * qd(3 * k + 2) * qd(3 * k + 2);
      }
      CHECK_NEAR_NAMED(
          "the kinetic energy of your M", 0.5 * qd.dot(M * qd), T, kExact,
          with_formula("your M gives the wrong kinetic energy: is the phi entry the inertia J_k (not m_k, not "
                       "0)?",
                       "1/2 qd^T M qd = sum_k 1/2 (m_k |R_dot_k|^2 + J_k phi_dot_k^2)"));
      CHECK_CLOSE_NAMED(
          "the momentum M q_dot of your M", M * qd, mass_diagonal(model).cwiseProduct(qd), kExact,
          with_formula("your M is not diagonal", "M qd = (m_k x_dot_k, m_k y_dot_k, J_k phi_dot_k) per body"));
    }
  }
}
