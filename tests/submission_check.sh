#!/bin/sh
# ./workbook grade --submission: only exercise files are taken from the submission, a missing
# file scores 0 with its name shown, extra files are listed and ignored, and a submission
# cannot replace a test or a header. The submission's folder and the results' paths hold spaces.
# Graded with the workbook of the fixture "grader" (gradescope_setup.sh: an instructor's copy of
# module 1 whose grader setup.sh built), which project.gradescope, project.batch and
# project.forgers share.
# Usage: submission_check.sh SOURCE_TREE GRADER WORK_DIR
#   GRADER: the instructor's copy that grades (the fixture's autograder/source).
set -eu
tree=$1
grader=$2
work=$3
rm -rf "$work"
submission="$work/alice smith"
mkdir -p "$submission/module01_kinematics/src" "$submission/autograder/module01_kinematics/visible"
# Module 1's reference solutions, one of them flat, one left out; plus a file that tries to
# replace a graded test with one that always passes, and a note.
cp "$tree"/solutions/module01_kinematics/joints.cpp "$tree"/solutions/module01_kinematics/drivers.cpp \
   "$tree"/solutions/module01_kinematics/planar.cpp "$tree"/solutions/module01_kinematics/assembly.cpp \
   "$submission/module01_kinematics/src/"
mv "$submission/module01_kinematics/src/planar.cpp" "$submission/planar.cpp"
printf '#include "grading.hpp"\nGRADED_TEST("always passes", "[M01][T1][points=100]") {}\n' \
  >"$submission/autograder/module01_kinematics/visible/planar.test.cpp"
echo "my notes" >"$submission/notes.txt"

fail() {
  cat "$work/grade.txt" >&2
  echo "submission check: $*" >&2
  exit 1
}
"$grader/workbook" grade --submission "$submission" --module 1 >"$work/grade.txt" 2>&1 || fail "grading failed"
grep -q "missing from the submission (their tasks score 0): module01_kinematics/src/dof.cpp" "$work/grade.txt" ||
  fail "the missing dof.cpp is not reported"
grep -q "ignored (not exercise files):.*notes.txt" "$work/grade.txt" || fail "the extra notes.txt is not reported"
grep -q "ignored (not exercise files):.*planar.test.cpp" "$work/grade.txt" || fail "the test file is not ignored"
grep -q "not implemented yet: M01T7" "$work/grade.txt" || fail "dof.cpp's tasks did not fail as not implemented"
grep -q "^Score: 32/44" "$work/grade.txt" || fail "expected 32/44 (all but the 5 points of the missing file and the 7 of the unanswered problems)"
# --require-full links_student_code: the code's tasks below their maximum are named, exit 1; the
# unanswered problems (an item without that capability) are not among them. A kind is no
# capability: exit 2.
status=0
"$grader/workbook" grade --submission "$submission" --module 1 --require-full links_student_code \
  >"$work/grade.txt" 2>&1 || status=$?
[ "$status" -eq 1 ] || fail "--require-full with a task of the code at 0: exit $status, not 1"
grep -q "^M01 T7: 0 of 5, not_implemented$" "$work/grade.txt" || fail "--require-full does not name M01 T7"
if grep -q "^M01 P[0-9]*: " "$work/grade.txt"; then fail "--require-full links_student_code names a tutorial problem"; fi
grep -q "^workbook: 1 of the 7 tasks of the items with links_student_code scored below their maximum" "$work/grade.txt" ||
  fail "--require-full does not count the tasks below their maximum"
status=0
"$grader/workbook" grade --submission "$submission" --module 1 --require-full problems >"$work/grade.txt" 2>&1 ||
  status=$?
[ "$status" -eq 2 ] && grep -q "no capability 'problems'" "$work/grade.txt" ||
  fail "--require-full with a kind's name: exit $status"
# The results files where their paths hold a space.
results="$work/my results"
"$grader/workbook" grade --submission "$submission" --module 1 --json "$results/results.json" --csv "$results/tasks.csv" \
  >"$work/grade.txt" 2>&1 || fail "grading with --json and --csv failed"
grep -q '"score": 32' "$results/results.json" || fail "results.json (its path holds a space) lacks the score"
grep -q "^M01,T7,0,5," "$results/tasks.csv" || fail "tasks.csv (its path holds a space) lacks task 7"
echo "submission check: exercise files graded, the missing one scored 0, the rest ignored"
