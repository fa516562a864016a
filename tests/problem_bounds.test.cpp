// Bounds that the tutorial problems' READMEs state about their drawn numbers, from the variants
// of 300 students (each grid's end is drawn among them).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "grading.hpp"
#include "modules.hpp"
#include "problems.hpp"

using namespace fmbd::problems;

namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("M07P1: the spin stays at most the README's share of the stretch mode's frequency sqrt(2k/m)",
          "[problems][readme]") {
  const std::vector<Problem> problems = module07_problems();
  const auto p1 = std::find_if(problems.begin(), problems.end(), [](const Problem& p) { return p.id == "M07P1"; });
  REQUIRE(p1 != problems.end());
  // Drawn: m [kg], d [m], k [N/m], Omega [rad/s]. The stretch mode: 2m q_f_ddot = -4k q_f.
  double m_max = 0, k_min = 1e300, omega_max = 0, worst = 0;
  for (int s = 0; s < 300; ++s) {
    const std::vector<double> v = make_variant(*p1, "student " + std::to_string(s)).parameters;
    REQUIRE(v.size() >= 4);
    m_max = std::max(m_max, v[0]);
    k_min = std::min(k_min, v[2]);
    omega_max = std::max(omega_max, v[3]);
    worst = std::max(worst, v[3] / std::sqrt(2 * v[2] / v[0]));
  }
  const double bound = omega_max / std::sqrt(2 * k_min / m_max);  // the grid's corner
  CHECK(worst <= bound);  // no student beyond the grid's corner
  char quoted[160];
  std::snprintf(quoted, sizeof quoted, "at most %.3f of the stretch mode's frequency √(2k/m), reached at m = %g kg, "
                "k = %g N/m and Ω = %g rad/s", bound, m_max, k_min, omega_max);
  const std::string text = read_text(std::string(FMBD_SOURCE_DIR) + "/module07_intuitive_flexible/problems/README.md");
  REQUIRE_FALSE(text.empty());
  std::string flat = text;  // the README wraps its lines
  std::replace(flat.begin(), flat.end(), '\n', ' ');
  INFO("the README should say: " << quoted);
  CHECK(flat.find(quoted) != std::string::npos);
}
