#pragma once
// The problem lists of the modules, each defined in moduleNN_*/problems/problems.cpp. A module's
// program (problems/main.cpp) calls its own; the project's tests call them all. Also what the
// module files share: pi, a degree in radians, a 2-vector as an answer, the beams' materials.
#include <vector>

#include "problems.hpp"

namespace fmbd::problems {

std::vector<Problem> module01_problems();  ///< M01P1..: DOF, a point's position, a joint's C_q
std::vector<Problem> module02_problems();  ///< M02P1..: a Newton step, a slider's velocity, gamma
std::vector<Problem> module03_problems();  ///< M03P1..: a pivot's reaction, a generalised mass, a torque, hinge forces
std::vector<Problem> module04_problems();  ///< M04P1..: a free pendulum's q_ddot, an RK4 step, a drift
std::vector<Problem> module05_problems();  ///< M05P1..: stiffness entries, a beam's f_1, mass entries
std::vector<Problem> module06_problems();  ///< M06P1..: a rotation mode, a constraint mode, a reduced mass entry
std::vector<Problem> module07_problems();  ///< M07P1..: a spinning body's stretch and energy, a node load
std::vector<Problem> module08_problems();  ///< M08P1..: Q_v, M(q), Coriolis, the spin's stretch, foreshortening

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDeg = kPi / 180;

/// The materials of the beam problems (modules 5 and 6): steel or aluminium, by the draw.
struct Material {
  const char* name;
  double E, rho;  // Pa, kg/m^3
};
inline constexpr Material kMaterials[2] = {{"steel", 210e9, 7850}, {"aluminium", 70e9, 2700}};

/// A 2-vector (x(), y()) as an answer.
template <typename Vector>
Quantity vec2(const Vector& v) {
  return Quantity::vector({v.x(), v.y()});
}

}  // namespace fmbd::problems
