#!/bin/sh
# A student release (./workbook release) builds from a clean copy, grades, and holds no hidden
# test text and no solution beyond the released modules, neither in its files nor in its
# binaries. Its READMEs link only to what it has and name no command it refuses; --solutions
# grades the released references; a demo runs on the released solutions of earlier modules.
# The releases, their first build and first grade come from the fixture "release"
# (release_setup.sh), which project.feedback shares; what this check changes in the release, it
# restores.
# Usage: release_check.sh SOURCE_TREE WORK_DIR DEMOS
#   WORK_DIR: the fixture's folder (release_setup.sh SOURCE_TREE WORK_DIR made it).
#   DEMOS: ON when the build has the demos (gnuplot-iostream found), OFF when it skips them.
set -eu
tree=$1
work=$2
demos=${3:-OFF}
release="$work/MBD course/release"  # a checkout path with a space (macOS: ~/Documents/MBD course)

fail() {
  echo "release check: $*" >&2
  exit 1
}
[ -f "$work/grade.txt" ] || fail "no first grade in $work: run the fixture release_setup.sh first"

# A week-3 release (modules 1-3, solutions of 1-2) and the whole course: the READMEs and the
# guides (docs/) link only to what the release has (the module table lists modules 1-3), and name
# no maintainer command.
week3=$work/week3
for copy in "$release" "$week3" "$work/full"; do
  sh "$tree/tests/readme_links.sh" "$copy" || fail "dead links in the READMEs of ${copy#"$work"/} (above)"
  if grep -rnE '\./workbook (test|release|gradescope|bench|studentify)\b' "$copy" --include=README.md ||
     grep -nE '\./workbook (test|release|gradescope|bench|studentify)\b' "$copy"/docs/*.md; then
    fail "the READMEs or guides of ${copy#"$work"/} name commands that a release refuses (above)"
  fi
done
grep -q '^| \[3\](module03_lagrange/README.md) ' "$week3/README.md" || fail "the week-3 README lost module 3's row"
[ "$(grep -c '^| \[[0-9]\](module' "$week3/README.md")" -eq 3 ] || fail "the week-3 README does not list modules 1-3"
grep -q '^| \[8\](module08_full_fff/README.md) ' "$work/full/README.md" || fail "the full release lost module 8's row"

# Layout: modules 1-2 only, solutions of module 1 only, no hidden tests or mistake catalogue.
[ -d "$release/module02_newton_raphson" ] || fail "module 2 is missing"
[ ! -e "$release/module03_lagrange" ] || fail "module 3 was released"
[ -d "$release/solutions/module01_kinematics" ] || fail "the solutions of module 1 are missing"
[ ! -e "$release/solutions/module02_newton_raphson" ] || fail "the solutions of module 2 were released"
[ ! -e "$release/autograder/mistakes" ] || fail "the mistake catalogue was released"
if find "$release" -path '*/hidden*' | grep -q .; then fail "a hidden folder was released"; fi

# The README speaks to students: its instructor-only parts are left out.
grep -q "^    ./workbook grade --module 1$" "$release/README.md" || fail "the release README lost its quick start"
if grep -n "^## Instructor guide\|^## For instructors\|^    ./workbook test$" "$release/README.md" ||
   grep -rn "instructor-only" "$release" --include=README.md || grep -n "instructor-only" "$release"/docs/*.md; then
  fail "the release READMEs or guides hold instructor-only parts (lines above)"
fi
# The guides (docs/): the students' and the lecturers' go with a release, and the pages on the
# build and the decisions; the instructor's and the maintainers' stay out (the release policy).
for guide in students lecturers building decisions; do
  [ -f "$release/docs/$guide.md" ] || fail "the release lost docs/$guide.md"
  grep -q "^| \[docs/$guide.md\](docs/$guide.md) " "$release/README.md" || fail "the release README lost its link to docs/$guide.md"
done
for guide in instructors engine performance tests; do
  [ ! -e "$release/docs/$guide.md" ] || fail "the release carries docs/$guide.md, an instructor's guide"
done
if grep -n "](docs/\(instructors\|engine\|performance\|tests\)\.md" "$release/README.md"; then
  fail "the release README links to an instructor's guide (above)"
fi

# Its help lists only what a student can run: no maintainer command, and no bench without the
# extras (which commands a copy lists: project.frontend).
# (help.txt: the fixture ran ./workbook help in the release.)
grep -q "^  grade " "$work/help.txt" || fail "the release's help lost the grade command"
if grep -E "^  (test|release|gradescope|studentify|bench)( |$)" "$work/help.txt"; then
  fail "the release's help lists maintainer commands (above)"
fi

# The release builds and grades: its score line, and the modules it has.
# (grade.txt: the fixture's first ./workbook grade in the release.)
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
trap 'cp "$work/planar.cpp" "$release/module01_kinematics/src/planar.cpp"' EXIT  # the shared release, restored
cat "$tree/tests/forgers/static_init.cpp" >>"$release/module01_kinematics/src/planar.cpp"
(cd "$release" && ./workbook grade) >"$work/grade-forged.txt" 2>&1 || { cat "$work/grade-forged.txt"; fail "grading failed"; }
grep -q "^M01 scores 0: rejected by the source check: module01_kinematics/src/planar.cpp:[0-9]*: #include <unistd.h>" \
  "$work/grade-forged.txt" || { cat "$work/grade-forged.txt"; fail "the forger in module 1 was not rejected"; }
grep -q "^M02 scores 0: rejected by the source check" "$work/grade-forged.txt" ||
  { cat "$work/grade-forged.txt"; fail "module 2 links the forger but was not rejected"; }
cp "$work/planar.cpp" "$release/module01_kinematics/src/planar.cpp"
trap - EXIT

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

# The GitHub Classroom workflow: one step per task of the items in it (the course manifest's
# capability classroom: the code's; the tutorial problems have no step, a release checks their
# format only), worth together the points of those tasks in the release's first grade (its
# tasks.csv, read by ./workbook inspect); a step's command fails on a skeleton and passes on the
# reference.
(cd "$release" && ./workbook classroom) >"$work/classroom.txt" 2>&1 || { cat "$work/classroom.txt"; fail "classroom failed"; }
workflow=$release/.github/workflows/classroom.yml
max=$("$release/workbook" inspect tasks "$work/tasks.csv" --of classroom --sum max_score) ||
  fail "the first grade's tasks.csv cannot be read"
tasks=$("$release/workbook" inspect tasks "$work/tasks.csv" --of classroom --count) || fail "the tasks cannot be counted"
[ "$tasks" -gt 0 ] || fail "the first grade graded no task of the workflow's items"
points=$("$release/workbook" inspect classroom "$workflow" --sum max_score) || fail "the workflow cannot be read"
[ "$points" = "$max" ] || fail "the workflow's steps are worth $points points; the release's visible tests $max"
steps=$("$release/workbook" inspect classroom "$workflow" --count)
[ "$steps" -eq "$tasks" ] || fail "$steps steps, but the first grade graded $tasks tasks of the workflow's items"
grep -q "runners: m01-t1,m01-t2," "$workflow" || fail "the reporter does not list the steps"
command=$("$release/workbook" inspect classroom "$workflow" | head -n 1 | cut -f 3)
[ "$command" = "./workbook grade --task M01T1 --strict" ] || fail "unexpected first command: $command"
if (cd "$release" && $command) >/dev/null 2>&1; then fail "the step of M01 T1 passes on the skeleton"; fi
(cd "$release" && ./workbook grade --solutions --task M01T1 --strict) >/dev/null 2>&1 ||
  fail "the step of M01 T1 fails on the reference"
(cd "$release" && ./workbook grade --solutions --module 1 --strict) >/dev/null 2>&1 ||
  fail "the released reference of module 1 does not score full marks"

# --solutions grades the modules whose reference the release carries (module 1 here), and names a
# module asked for that has none.
(cd "$release" && ./workbook grade --solutions --strict) >"$work/grade-solutions.txt" 2>&1 ||
  { cat "$work/grade-solutions.txt"; fail "--solutions did not grade the released reference to full marks"; }
grep -q "^M01 " "$work/grade-solutions.txt" || { cat "$work/grade-solutions.txt"; fail "--solutions did not grade module 1"; }
if grep "^M02 " "$work/grade-solutions.txt"; then fail "--solutions graded module 2, whose reference is not released"; fi
if (cd "$release" && ./workbook grade --solutions --module 2) >"$work/grade-solutions-2.txt" 2>&1; then
  fail "--solutions --module 2 succeeded without module 2's reference"
fi
grep -q "^workbook: --solutions: module 2 (module02_newton_raphson) has no reference solution here" \
  "$work/grade-solutions-2.txt" || { cat "$work/grade-solutions-2.txt"; fail "--solutions --module 2 did not name the module"; }

# The tutorial problems in a student's own copy: not graded before they are started; then
# `./workbook problems` prints a student's numbers (another student's differ) and writes the
# answers file; grading takes the remembered name. Module 1's reference is released here, so its
# answers are graded; module 2's is not, so only their format is checked.
grep -qF "not graded here: M01P (module01_kinematics/answers.txt) M02P (module02_newton_raphson/answers.txt); ./workbook problems MNN prints the problems" "$work/grade.txt" ||
  fail "the release's first grade does not say that the problems are not started"
trap 'rm -f "$release/module01_kinematics/answers.txt" "$release/module02_newton_raphson/answers.txt" "$release/build/student.name"' EXIT
(cd "$release" && ./workbook problems M01 --student "Ada Lovelace") >"$work/problems.txt" 2>&1 ||
  { cat "$work/problems.txt"; fail "./workbook problems M01 failed"; }
grep -q "^## M01P2: " "$work/problems.txt" && grep -q "wrote module01_kinematics/answers.txt" "$work/problems.txt" &&
  [ -f "$release/module01_kinematics/answers.txt" ] || { cat "$work/problems.txt"; fail "no problems or no answers file"; }
(cd "$release" && ./workbook problems M01P2 --student "Bob Smith") >"$work/problems-bob.txt" 2>&1 || fail "problems for Bob failed"
[ "$(grep -A2 "^## M01P2" "$work/problems.txt")" != "$(grep -A2 "^## M01P2" "$work/problems-bob.txt")" ] ||
  fail "two students got the same numbers for M01P2"
(cd "$release" && ./workbook problems M02 --student "Ada Lovelace") >/dev/null 2>&1 || fail "./workbook problems M02 failed"
FMBD_STUDENT="Ada Lovelace" "$release/build/student/problems/m01_problems" --model-answers >"$release/module01_kinematics/answers.txt"
echo "M02P1 = 0.5" >>"$release/module02_newton_raphson/answers.txt"
(cd "$release" && ./workbook grade) >"$work/grade-problems.txt" 2>&1 || fail "grading the answers failed"
grep -q 'M01P M02P graded with the numbers of "Ada Lovelace"' "$work/grade-problems.txt" &&
  grep -q "M02P without the reference here: only the format of the answers is checked" "$work/grade-problems.txt" &&
  [ "$(grep -c "PASS  M01P[123]: " "$work/grade-problems.txt")" -eq 3 ] &&
  grep -q "FAIL  M02P1: .*format OK; the value is graded by your instructor's grader" "$work/grade-problems.txt" ||
  { cat "$work/grade-problems.txt"; fail "the answers were not graded as expected"; }
rm -f "$release/module01_kinematics/answers.txt" "$release/module02_newton_raphson/answers.txt" "$release/build/student.name"
trap - EXIT

# Week 3: the module 3 demo runs on the released solutions of modules 1-2, so the skeleton of
# module 3 stops it at a task of module 3, not of an earlier module.
if [ "$demos" = ON ]; then
  if (cd "$week3" && ./workbook demo slider_crank_reactions --out "$work/demo") >"$work/demo.txt" 2>&1; then
    cat "$work/demo.txt"; fail "the module 3 demo ran to its end on the skeleton of module 3"
  fi
  if grep "not implemented yet: M0[12]" "$work/demo.txt" || ! grep -q "not implemented yet: M03" "$work/demo.txt"; then
    cat "$work/demo.txt"; fail "the module 3 demo of week 3 did not run on the released solutions of modules 1-2"
  fi
fi
echo "release check: modules 1-2 built and graded; the tutorial problems printed and graded; no hidden test and no solution beyond module 1; classroom workflow;" \
  "READMEs of weeks 2, 3 and the whole course; --solutions; demos on released solutions"
