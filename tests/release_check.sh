#!/bin/sh
# A student release (./workbook release) builds from a clean copy, grades, and holds no hidden
# test text and no solution beyond the released modules, neither in its files nor in its
# binaries. Usage: release_check.sh SOURCE_TREE WORK_DIR
set -eu
tree=$1
work=$2
rm -rf "$work"
release=$work/release
"$tree/workbook" release --out "$release" --through 2 --solutions-through 1

fail() {
  echo "release check: $*" >&2
  exit 1
}

# Layout: modules 1-2 only, solutions of module 1 only, no hidden tests or mistake catalogue.
[ -d "$release/module02_newton_raphson" ] || fail "module 2 is missing"
[ ! -e "$release/module03_lagrange" ] || fail "module 3 was released"
[ -d "$release/solutions/module01_kinematics" ] || fail "the solutions of module 1 are missing"
[ ! -e "$release/solutions/module02_newton_raphson" ] || fail "the solutions of module 2 were released"
[ ! -e "$release/autograder/mistakes" ] || fail "the mistake catalogue was released"
if find "$release" -path '*/hidden*' | grep -q .; then fail "a hidden folder was released"; fi

# The README speaks to students: its instructor-only parts are left out.
grep -q "^    ./workbook grade$" "$release/README.md" || fail "the release README lost its quick start"
if grep -n "^## Instructor guide\|^## For instructors\|^    ./workbook test$" "$release/README.md" ||
   grep -rn "instructor-only" "$release" --include=README.md; then
  fail "the release READMEs hold instructor-only parts (lines above)"
fi

# The release builds and grades: its score line, and the modules it has.
(cd "$release" && ./workbook grade) >"$work/grade.txt" 2>&1 || { cat "$work/grade.txt"; fail "grading failed"; }
grep -q "^Score: " "$work/grade.txt" || fail "no score line"
grep -q "^M02 " "$work/grade.txt" || fail "module 2 was not graded"

# Module 2 on the released reference of module 1: its tests then stop at module 2's own tasks.
grep -q "not implemented yet: M01" "$work/grade.txt" || fail "module 2 on the skeleton of module 1 did not reach M01"
(cd "$release" && ./workbook grade --module 2 --reference-earlier) >"$work/grade-reference.txt" 2>&1 ||
  { cat "$work/grade-reference.txt"; fail "grading on the released reference failed"; }
grep -q "^M02 " "$work/grade-reference.txt" || fail "--reference-earlier did not grade module 2"
if grep "not implemented yet: M01" "$work/grade-reference.txt"; then
  fail "--reference-earlier graded module 2 on the skeleton of module 1 (lines above)"
fi

# A student's own ./workbook grade runs the source check too (issue 17): a forger in module 1 is
# rejected with its reason; in the student variant, module 2 links it and is rejected as well.
cp "$release/module01_kinematics/src/planar.cpp" "$work/planar.cpp"
cat "$tree/tests/forgers/static_init.cpp" >>"$release/module01_kinematics/src/planar.cpp"
(cd "$release" && ./workbook grade) >"$work/grade-forged.txt" 2>&1 || { cat "$work/grade-forged.txt"; fail "grading failed"; }
grep -q "^M01 scores 0: rejected by the source check: module01_kinematics/src/planar.cpp:[0-9]*: #include <unistd.h>" \
  "$work/grade-forged.txt" || { cat "$work/grade-forged.txt"; fail "the forger in module 1 was not rejected"; }
grep -q "^M02 scores 0: rejected by the source check" "$work/grade-forged.txt" ||
  { cat "$work/grade-forged.txt"; fail "module 2 links the forger but was not rejected"; }
cp "$work/planar.cpp" "$release/module01_kinematics/src/planar.cpp"

# No solution code outside solutions/module01 (the markers themselves appear in the docs and
# in the studentify tool, which explain them).
if grep -rl "BEGIN SOLUTION" "$release" --include='*.cpp' --include='*.hpp' |
   grep -v "^$release/solutions/module01_kinematics/" | grep -v "^$release/tools/" | grep -v "^$release/build/" | grep .; then
  fail "solution code outside the released solutions (files above)"
fi

# No hidden test name anywhere in the release, sources or binaries.
grep -ho 'GRADED_TEST("[^"]*"' "$tree"/autograder/module0[12]_*/hidden/*.test.cpp | sed 's/GRADED_TEST("//; s/"$//' \
  >"$work/hidden-names.txt"
[ -s "$work/hidden-names.txt" ] || fail "no hidden test names found to look for"
while IFS= read -r name; do
  if grep -rlaF -- "$name" "$release" | grep .; then fail "the hidden test '$name' is in the files above"; fi
done <"$work/hidden-names.txt"

# The GitHub Classroom workflow: one step per task, worth together the release's visible points;
# a step's command fails on a skeleton and passes on the reference.
(cd "$release" && ./workbook classroom) >"$work/classroom.txt" 2>&1 || { cat "$work/classroom.txt"; fail "classroom failed"; }
workflow=$release/.github/workflows/classroom.yml
max=$(sed -n 's|^Score: [0-9.]*/\([0-9.]*\)$|\1|p' "$work/grade.txt")
points=$(sed -n 's|^ *max-score: ||p' "$workflow" | awk '{ s += $1 } END { print s }')
[ "$points" = "$max" ] || fail "the workflow's steps are worth $points points; the release's visible tests $max"
steps=$(grep -c "uses: classroom-resources/autograding-command-grader@v1" "$workflow")
[ "$steps" -eq "$(grep -c '^  T[0-9]' "$work/grade.txt")" ] || fail "$steps steps, but the score table has other tasks"
grep -q "runners: m01-t1,m01-t2," "$workflow" || fail "the reporter does not list the steps"
command=$(sed -n 's|^ *command: ||p' "$workflow" | head -n 1)
[ "$command" = "./workbook grade --task M01T1 --strict" ] || fail "unexpected first command: $command"
if (cd "$release" && $command) >/dev/null 2>&1; then fail "the step of M01 T1 passes on the skeleton"; fi
(cd "$release" && ./workbook grade --solutions --task M01T1 --strict) >/dev/null 2>&1 ||
  fail "the step of M01 T1 fails on the reference"
(cd "$release" && ./workbook grade --solutions --module 1 --strict) >/dev/null 2>&1 ||
  fail "the released reference of module 1 does not score full marks"
echo "release check: modules 1-2 built and graded; no hidden test and no solution beyond module 1; classroom workflow"
