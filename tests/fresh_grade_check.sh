#!/bin/sh
# A student's first grade of the module they are working on, on an empty build folder, scores what
# their code is worth: the source check builds everything it reads. In a copy of the fixture's
# week-3 release (modules 1-3) with correct code through module 3 and no build folder,
# `./workbook grade --module 2`, then `--module 3`, score every task of the code in full and say whose
# earlier modules they graded on; with module 1's skeleton back, module 2's grade names module 1's
# stubs and offers --reference-earlier, which scores module 2 in full. A source
# check that cannot run (its tool fails) is a build error (exit 3) that says so, never a score of 0.
# Usage: fresh_grade_check.sh SOURCE_TREE RELEASE_WORK_DIR WORK_DIR
#   RELEASE_WORK_DIR: the fixture "release" (release_setup.sh), whose week3/ is copied.
set -eu
tree=$1
releases=$2
work=$3
rm -rf "$work"
mkdir -p "$work"
touch "$work/grade.txt"
fail() {
  cat "$work/grade.txt" >&2
  echo "fresh grade check: $*" >&2
  exit 1
}
copy="$work/week3"
# Without its build folder (project.release may build a demo in it meanwhile).
(cd "$releases" && tar cf - --exclude=week3/build week3) | (cd "$work" && tar xf -)
[ ! -e "$copy/build" ] || fail "the copy has a build folder"
for module in module01_kinematics module02_newton_raphson module03_lagrange; do
  cp "$tree/solutions/$module/"*.cpp "$copy/$module/src/"
done

for n in 2 3; do
  status=0
  (cd "$copy" && ./workbook grade --module $n --require-full links_student_code) >"$work/grade.txt" 2>&1 || status=$?
  [ "$status" -eq 0 ] || fail "grade --module $n on a fresh build: exit $status, not 0 (every task of the code in full)"
  if grep -q "rejected by the source check" "$work/grade.txt"; then fail "the source check refused correct code"; fi
  # It says whose earlier modules it graded on: one's own, the released reference (modules 1-2 here) offered.
  case $n in
    2) earlier="module 2 runs on your own code of module 1 (--reference-earlier: on the released reference of module 1)" ;;
    3) earlier="module 3 runs on your own code of modules 1-2 (--reference-earlier: on the released reference of modules 1-2)" ;;
  esac
  grep -qF "workbook: $earlier" "$work/grade.txt" || fail "grade --module $n does not say: $earlier"
done

# Module 1 not done (its skeleton back): module 2's tests fail on module 1's stubs, and the grade names
# them and offers --reference-earlier, with which module 2 scores full on module 1's released reference.
cp "$releases/week3/module01_kinematics/src/"*.cpp "$copy/module01_kinematics/src/"
(cd "$copy" && ./workbook grade --module 2) >"$work/grade.txt" 2>&1 || fail "grade --module 2 on module 1's skeleton failed"
grep -q "^Tests of M02 failed on earlier modules' tasks not implemented yet: M01T" "$work/grade.txt" ||
  fail "module 1's stubs are not named under the table"
grep -qF "Finish them, or grade on the released reference of module 1: ./workbook grade --reference-earlier --module 2" \
  "$work/grade.txt" || fail "--reference-earlier is not offered"
status=0
(cd "$copy" && ./workbook grade --module 2 --reference-earlier --require-full links_student_code) >"$work/grade.txt" 2>&1 ||
  status=$?
[ "$status" -eq 0 ] || fail "grade --module 2 --reference-earlier on module 1's skeleton: exit $status, not 0 (full)"
grep -qF "workbook: module 2 runs on the released reference (solutions/) of module 1" "$work/grade.txt" ||
  fail "grade --reference-earlier does not say it graded on the released reference"
cp "$tree/solutions/module01_kinematics/"*.cpp "$copy/module01_kinematics/src/"

# The source check's tool fails (a stand-in that exits 2): exit 3, the reason, and no score.
vet="$copy/build/student/tools/fmbd-vet"
[ -x "$vet" ] || fail "no $vet after grading"
mv "$vet" "$vet.real"
printf '#!/bin/sh\necho "fmbd-vet: a stand-in that fails" >&2\nexit 2\n' >"$vet"
chmod +x "$vet"
touch "$copy/module03_lagrange/src/"*.cpp
status=0
(cd "$copy" && ./workbook grade --module 3) >"$work/grade.txt" 2>&1 || status=$?
mv "$vet.real" "$vet"
[ "$status" -eq 3 ] || fail "a source check that cannot run: exit $status, not 3"
grep -q "the source check of .* could not run, twice" "$work/grade.txt" || fail "the failure does not say the check could not run"
grep -q "not of your code, which was not graded" "$work/grade.txt" || fail "the failure does not say the code was not graded"
if grep -q "^Score:" "$work/grade.txt"; then fail "a score was printed for code that was never checked"; fi
echo "fresh grade check: modules 2 and 3 score full on an empty build; module 1's stubs offer --reference-earlier; a check that cannot run exits 3"
