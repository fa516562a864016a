// The program of one module's tutorial problems (m01_problems, ...): the module's problem list
// (FMBD_PROBLEMS_FUNCTION, defined in moduleNN_*/problems/problems.cpp) and run_program().
#include "problems.hpp"

namespace fmbd::problems {
std::vector<Problem> FMBD_PROBLEMS_FUNCTION();
}  // namespace fmbd::problems

int main(int argc, char** argv) {
  fmbd::problems::ProgramConfig config;
  config.module_tag = FMBD_PROBLEMS_MODULE;
  config.answers_path = FMBD_PROBLEMS_ANSWERS;
  config.worked_path = FMBD_PROBLEMS_WORKED;
  config.has_reference = FMBD_PROBLEMS_HAVE_REFERENCE != 0;
  return fmbd::problems::run_program(fmbd::problems::FMBD_PROBLEMS_FUNCTION(), config, argc, argv);
}
