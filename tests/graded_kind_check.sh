#!/bin/sh
# A new kind of graded item is one manifest entry and one program: a course whose only item is of
# the kind "answers" (autograder/fixtures/answers: numbers in a text file, checked with a
# tolerance) is graded by ./workbook grade as it is, with its program's feedback in the table and
# in results.json. The course's path holds an '@', a space and a non-ASCII letter (a CI job
# folder, a university home folder), and its test list comes from a trusted build (the program
# and its lister go to the driver as separate arguments, not one string split at '@'). Run as
# root, it is also graded inside a folder that the tests' user (nobody) cannot enter: the grader
# names the folder and the fix instead of "lists no tests".
# Usage: graded_kind_check.sh SOURCE_TREE WORK_DIR
set -eu
tree=$1
work=$2
rm -rf "$work"
# As root the tests run as nobody, who must reach the course for its first grade: where a folder
# above WORK_DIR is closed to nobody (a clone under mktemp -d, mode 700), the course goes to a
# fresh folder under the system's temporary folder instead, opened to all.
if [ "$(id -u)" -eq 0 ] && command -v su >/dev/null 2>&1 && mkdir -p "$work" &&
  ! su nobody -s /bin/sh -c "cd '$work'" 2>/dev/null; then
  rm -rf "$work"
  work=$(mktemp -d)
  chmod 755 "$work"
  trap 'rm -rf "$work"' EXIT
fi

fail() {
  cat "$work/grade.txt" >&2 || true
  echo "graded kind check: $*" >&2
  exit 1
}

# The course: the command, the presets, the manifest functions, the grade driver, the front end,
# and the fixture's CMakeLists.txt, program, key and a student's answers.
course="$work/job@2/Prüfung kurs"
mkdir -p "$course/cmake" "$course/autograder" "$course/tools" "$course/problems"
cp "$tree/workbook" "$tree/CMakePresets.json" "$course/"
cp "$tree/cmake/FmbdManifest.cmake" "$course/cmake/"
cp -R "$tree/autograder/driver" "$course/autograder/"
cp -R "$tree/frontend" "$course/"
cp "$tree"/tools/*.hpp "$tree/tools/process.cpp" "$course/tools/"
fixture=$tree/autograder/fixtures/answers
# The item's test list from a trusted build of the same program (REFERENCE_TARGET), as the
# course's modules have it: the front end then hands the driver a program and its lister.
sed -e 's/TARGET m90_answers TAGS/TARGET m90_answers REFERENCE_TARGET m90_reference TAGS/' \
    -e 's/^fmbd_write_manifest()$/add_executable(m90_reference problems\/answers_kind.cpp)\
get_target_property(definitions m90_answers COMPILE_DEFINITIONS)\
target_compile_definitions(m90_reference PRIVATE ${definitions})\
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
grep -q "^Score: 2/6$" "$work/grade.txt" || fail "expected 2/6 (P1 only)"
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
echo "graded kind check: an item of the kind 'answers' graded by the front end as it is, under a path with '@', a space and 'ü'"
