#!/bin/sh
# Gradescope image setup (run once, as root, in /autograder/source; written by
# ./workbook gradescope). Installs the distribution's packages and builds the grader by grading
# the reference solutions as a submission, so that a student's run compiles only their files.
# Any of the Debian 12, Ubuntu 22.04 and Ubuntu 24.04 base images: Catch2 v2 or v3 (24.04) both
# build, and the graded course needs no Spectra.
set -eu
source=$(CDPATH='' cd -- "$(dirname -- "$0")" && pwd)
. "$source/gradescope.conf"
export DEBIAN_FRONTEND=noninteractive
# The first grading installs the build packages (./workbook does, as root) and builds everything.
# The reference solutions must score every task of the graded items that link the student's code
# (the course manifest's capability links_student_code); the others grade what the solutions do
# not hold, such as a student's answers file (the tutorial problems).
# shellcheck disable=SC2086
if ! "$source/workbook" grade --submission "$source/solutions" $MODULE_ARGS --require-full links_student_code; then
  echo "setup.sh: the reference solutions do not score every task of the code (above)"
  exit 1
fi
echo "setup.sh: the grader is built and gives the reference solutions every point of the code"
