#!/bin/sh
# A new kind of graded item is one manifest entry and one program: a course of two items of kinds
# that no code knows (autograder/fixtures/answers) is graded by ./workbook grade as it is, with
# its programs' feedback in the table and in results.json. "answers": numbers in a text file,
# checked with a tolerance. "personal": like the tutorial problems, an input that needs the
# identity the grader trusts; its capabilities alone make the front end skip it until its answers
# file exists, ./workbook problems print it and write that file, hand the file over, and grade it
# with the numbers of --student, the remembered name, or Gradescope's metadata, or say that it
# needs a name. The course's path holds an '@', a space and a non-ASCII letter (a CI job
# folder, a university home folder), and its test list comes from a trusted build (the program
# and its lister go to the driver as separate arguments, not one string split at '@'). Run as
# root, it is also graded inside a folder that the tests' user (nobody) cannot enter: the grader
# names the folder and the fix instead of "lists no tests".
# Usage: graded_kind_check.sh SOURCE_TREE WORK_DIR
set -eu
# The compiler sees this course's odd absolute paths, as a student's does: no ccache base folder
# (the suite's shared cache would hand it relative ones).
unset CCACHE_BASEDIR
tree=$1
# The tests' user (nobody, as root) must reach the course (reachable_work.sh).
. "$tree/tests/reachable_work.sh"
reachable_work "$2"

fail() {
  cat "$work/grade.txt" >&2 || true
  echo "graded kind check: $*" >&2
  exit 1
}

# The course: the command, the presets, the manifest functions, the grade driver and the shared
# code it adds (common/), the front end,
# and the fixture's CMakeLists.txt, program, key and a student's answers.
course="$work/job@2/Prüfung kurs"
mkdir -p "$course/cmake" "$course/autograder" "$course/tools" "$course/problems"
cp "$tree/workbook" "$tree/CMakePresets.json" "$course/"
cp "$tree/cmake/FmbdManifest.cmake" "$course/cmake/"
cp -R "$tree/autograder/driver" "$course/autograder/"
cp -R "$tree/common" "$course/"
cp -R "$tree/frontend" "$course/"
cp "$tree"/tools/*.hpp "$course/tools/"
fixture=$tree/autograder/fixtures/answers
# The item's test list from a trusted build of the same program (REFERENCE_TARGET), as the
# course's modules have it: the front end then hands the driver a program and its lister.
sed -e 's/TARGET m90_answers CLASSROOM/TARGET m90_answers REFERENCE_TARGET m90_reference CLASSROOM/' \
    -e 's/^fmbd_write_manifest()$/add_executable(m90_reference problems\/answers_kind.cpp)\
get_target_property(definitions m90_answers COMPILE_DEFINITIONS)\
target_compile_definitions(m90_reference PRIVATE ${definitions})\
target_link_libraries(m90_reference PRIVATE fmbd_protocol)\
&/' "$fixture/course.cmake" >"$course/CMakeLists.txt"
grep -q "REFERENCE_TARGET m90_reference" "$course/CMakeLists.txt" && grep -q "^add_executable(m90_reference" "$course/CMakeLists.txt" ||
  fail "the fixture's course.cmake changed: give its item a reference here again"
cp "$fixture/answers_kind.cpp" "$fixture/key.txt" "$course/problems/"
cat >"$course/problems/answers.txt" <<'ANSWERS'
# P1 is right; P2 has the wrong sign, P3 half the value; P4 is not a number; P5 is missing.
P1 9.81
P2 0.5
P3 2.0
P4 three
ANSWERS

(cd "$course" && ./workbook grade --json "$work/my results/results.json" --csv "$work/my results/tasks.csv") \
  >"$work/grade.txt" 2>&1 || fail "grading failed"
grep -q "^Score: 2/6$" "$work/grade.txt" || fail "expected 2/6 (P1 only; M91P not started)"
grep -qF "not graded here: M91P (problems/personal.txt); ./workbook problems MNN prints the problems" "$work/grade.txt" ||
  fail "the personal item without its answers file is not said to be not started"
grep -q "P2: the sine of -30 degrees .*the sign is wrong" "$work/grade.txt" || fail "P2's sign is not named"
grep -q "P3: .*off by a factor of 2" "$work/grade.txt" || fail "P3's factor of 2 is not named"
grep -q "P4: .*line 5 ('P4 three')" "$work/grade.txt" || fail "P4's malformed line is not named by its number"
grep -q 'P5: .*add a line "P5 VALUE"' "$work/grade.txt" || fail "P5's missing answer is not named"
grep -q '"score": 2' "$work/my results/results.json" || fail "results.json does not hold the score"
# Its items are tutorial problems ([Pk] tags, k the key's TASK): tasks M90P1 and M90P2 of the tables.
grep -q "^M90,P1,2,3,failed$" "$work/my results/tasks.csv" || fail "no row M90,P1 in tasks.csv: $(cat "$work/my results/tasks.csv")"
grep -q "^M90,P2,0,3,failed$" "$work/my results/tasks.csv" || fail "no row M90,P2 in tasks.csv: $(cat "$work/my results/tasks.csv")"
grep -q '"P1"' "$work/my results/results.json" || fail "results.json does not tag the problems P1"
# The answer fixed, the item scores it: its program reads the answers file at each run.
sed -i 's/^P2 0.5$/P2 -0.5/' "$course/problems/answers.txt"
(cd "$course" && ./workbook grade) >"$work/grade.txt" 2>&1 || fail "grading again failed"
grep -q "^Score: 3/6$" "$work/grade.txt" || fail "the fixed answer did not score"

# The personal item: ./workbook problems prints it with Ada's numbers (3 letters) and writes its
# answers file; the grade takes the remembered name, --student, or Gradescope's metadata.
(cd "$course" && ./workbook problems M91 --student "Ada") >"$work/problems.txt" 2>&1 ||
  { cat "$work/problems.txt" >&2; fail "./workbook problems M91 failed"; }
grep -q "^## M91P1: the weight of 1 kg in newtons, times 3 " "$work/problems.txt" &&
  grep -q "wrote problems/personal.txt" "$work/problems.txt" && grep -q "^P5 $" "$course/problems/personal.txt" ||
  { cat "$work/problems.txt" >&2; fail "no problems with Ada's numbers, or no answers file"; }
printf 'P1 29.43\nP2 -1.5\n' >"$course/problems/personal.txt"
(cd "$course" && ./workbook grade --csv "$work/my results/tasks.csv") >"$work/grade.txt" 2>&1 || fail "grading Ada's answers failed"
grep -q "^workbook: M91P graded with the numbers of \"Ada\"$" "$work/grade.txt" || fail "the remembered name is not said"
grep -q "^Score: 6/12$" "$work/grade.txt" || fail "expected 6/12 (M91P1, M91P2 right for Ada)"
grep -q "^M91,P1,3,3,passed$" "$work/my results/tasks.csv" || fail "no row M91,P1 in tasks.csv: $(cat "$work/my results/tasks.csv")"
(cd "$course" && ./workbook grade --student "Bo") >"$work/grade.txt" 2>&1 || fail "grading as Bo failed"
grep -q "^Score: 3/12$" "$work/grade.txt" && grep -q "graded with the numbers of \"Bo\"" "$work/grade.txt" ||
  fail "Ada's answers scored for Bo"
printf '{"users": [{"email": "ada@example.org", "name": "Ada"}]}\n' >"$work/submission_metadata.json"
(cd "$course" && ./workbook grade --gradescope-metadata "$work/submission_metadata.json") >"$work/grade.txt" 2>&1 ||
  fail "grading with Gradescope's metadata failed"
grep -q "graded with the numbers of \"ada@example.org\"" "$work/grade.txt" || fail "Gradescope's user is not the identity"
rm -f "$course/build/student.name"
(cd "$course" && ./workbook grade) >"$work/grade.txt" 2>&1 || fail "grading without a name failed"
grep -q "^workbook: the numbers of M91P depend on your name: ./workbook grade --student" "$work/grade.txt" &&
  grep -q "FAIL  P1: .*-- hint: no identity: your numbers depend on your name" "$work/grade.txt" && grep -q "^Score: 3/12$" "$work/grade.txt" ||
  fail "grading without a name does not say that M91P needs one"

# A manifest of an older schema (a build configured before the tree changed) is configured again,
# once, saying so. (./workbook rebuilds build/student's manifest before it starts the front end, so
# the front end is started here on a current copy, and grade finds the build's own one older.)
manifest="$course/build/student/course.json"
cp "$manifest" "$work/course.json"
sed -i 's/"schema" : 3,/"schema" : 2,/' "$manifest"
grep -q '"schema" : 2,' "$manifest" || fail "the manifest's schema could not be made older: $(head -c 200 "$manifest")"
(cd "$course" && build/student/frontend/fmbd-workbook --source . --manifest "$work/course.json" grade --student "Ada") \
  >"$work/grade.txt" 2>&1 || fail "grading with an older manifest failed"
[ "$(grep -c "course.json is of schema 2, written before this tree changed; configuring .*build/student again" "$work/grade.txt")" -eq 1 ] &&
  grep -q '"schema" : 3,' "$manifest" && grep -q "^Score: 6/12$" "$work/grade.txt" ||
  fail "an older manifest is not configured again once, with a message, and then graded"

# As root, the tests run as nobody: with the course inside a folder of mode 700, the grader says
# which folder nobody cannot enter and how to fix it (the answers program lists its problems from
# its key there, so it would list none).
if [ "$(id -u)" -eq 0 ]; then
  chmod 700 "$work/job@2"
  status=0
  (cd "$course" && ./workbook grade) >"$work/grade.txt" 2>&1 || status=$?
  chmod 755 "$work/job@2"
  [ "$status" -eq 0 ] || fail "grading in a closed folder failed with status $status"
  grep -qF "the tests run as the user nobody (the grader runs as root), who cannot enter $work/job@2; fix: chmod o+rx '$work/job@2', or grade as a normal user (not root)" "$work/grade.txt" ||
    fail "grading in a folder of mode 700 does not name the folder and the fix"
  grep -q "lists no tests" "$work/grade.txt" && fail "grading in a folder of mode 700 still says 'lists no tests'"
  grep -q "m90_reference: listing the tests.*cannot enter $work/job@2" "$work/grade.txt" ||
    fail "the table does not say why the tests could not be listed"
else
  echo "graded kind check: not root, so the tests run as this user: the closed-folder check is skipped"
fi
echo "graded kind check: items of the kinds 'answers' and 'personal' (inputs, identity) graded by the front end as it is, under a path with '@', a space and 'ü'"
