#!/bin/sh
# Forged submissions (tests/forgers/, issue 17) against ./workbook grade --submissions: each
# forger is rejected by the source check with its reason (table, results.json, JUnit and the
# gradebook's status), a correct submission with an accidental trip (accidental/) is rejected
# with a clear message, and the module-1 solutions score 37/37 (of 44: the tutorial problems are
# not answered).
# Graded with the workbook of the fixture "grader" (gradescope_setup.sh: an instructor's copy of
# module 1 whose grader setup.sh built), which project.gradescope, project.submission and
# project.batch share.
# Usage: forgers_check.sh SOURCE_TREE GRADER WORK_DIR
#   GRADER: the instructor's copy that grades (the fixture's autograder/source).
set -eu
tree=$1
grader=$2
work=$3
rm -rf "$work"
class=$work/class
mkdir -p "$class"

# A forger: the committed skeleton of planar.cpp with its snippet appended, or inserted at the
# snippet's line //@skeleton. An accidental trip: the solutions, with the snippet appended to
# the solution of planar.cpp.
skeleton=$tree/module01_kinematics/src/planar.cpp
for snippet in "$tree"/tests/forgers/*.cpp; do
  name=$(basename "$snippet" .cpp)
  mkdir -p "$class/$name/module01_kinematics/src"
  if grep -qx '//@skeleton' "$snippet"; then
    awk -v skeleton="$skeleton" '$0 == "//@skeleton" { while ((getline line < skeleton) > 0) print line; next } { print }' \
      "$snippet" >"$class/$name/module01_kinematics/src/planar.cpp"
  else
    cat "$skeleton" "$snippet" >"$class/$name/module01_kinematics/src/planar.cpp"
  fi
done
for snippet in "$tree"/tests/forgers/accidental/*.cpp; do
  name=accidental_$(basename "$snippet" .cpp)
  mkdir -p "$class/$name"
  cp "$tree"/solutions/module01_kinematics/*.cpp "$class/$name/"
  cat "$snippet" >>"$class/$name/planar.cpp"
done
mkdir -p "$class/perfect"
cp "$tree"/solutions/module01_kinematics/*.cpp "$class/perfect/"

fail() {
  cat "$work/batch.txt" "$work/out/gradebook.csv" >&2 || true
  echo "forgers check: $*" >&2
  exit 1
}
"$grader/workbook" grade --submissions "$class" --out "$work/out" --module 1 >"$work/batch.txt" 2>&1 ||
  fail "batch grading failed"

# expect NAME REASON: NAME scores 0 of 44 as rejected, and REASON is in its grade.txt, in
# every test's output of results.json and in its JUnit failures.
file=module01_kinematics/src/planar.cpp
expect() {
  grep -q "^$1,0,44,rejected:M01," "$work/out/gradebook.csv" || fail "$1: expected 0 of 44, rejected"
  grep -q "^$file:[0-9]*: $2" "$work/out/$1/grade.txt" || fail "$1: '$2' is not in grade.txt"
  grep -q "M01 scores 0: rejected by the source check: $file:[0-9]*: " "$work/out/$1/grade.txt" ||
    fail "$1: the table does not say why M01 scores 0"
  # Every test of the code; the tutorial problems (unanswered here) grade the answers file.
  tests=$(($(grep -c '"status": "failed"' "$work/out/$1/results.json") - $(grep -c '"name": "M01P' "$work/out/$1/results.json")))
  [ "$tests" -gt 0 ] && [ "$(grep -c "\"output\": \"rejected by the source check: $file:[0-9]*: " "$work/out/$1/results.json")" -eq "$tests" ] ||
    fail "$1: not every test's output in results.json says that the check rejected it"
  grep -q "\"output\": \"[^\"]*M01 scores 0: rejected by the source check" "$work/out/$1/results.json" ||
    fail "$1: the top-level output of results.json does not say why"
  grep -q "<failure type=\"rejected\" message=\"rejected by the source check: $file:" "$work/out/$1/junit.xml" ||
    fail "$1: junit.xml does not say why"
}
expect static_init "#include <unistd.h>: this header is not allowed in exercise files"
expect proc_fd "uses fopen, which exercise files may not use"
expect local_static "uses read, which exercise files may not use"
expect atexit "uses atexit, which exercise files may not use"
expect memory_scan "defines __cxa_throw with a C name, outside every namespace"
expect fake_list "uses _Exit, which exercise files may not use"
expect macro_paste "'extern' is not allowed in exercise files"
expect macro_paste "uses syscall, which exercise files may not use"
expect macro_define "#include must name its header directly"
expect hand_declared "uses syscall, which exercise files may not use"
expect accidental_debug_dump "#include <fstream>: this header is not allowed in exercise files"
grep -q "^  fix: use the course's headers" "$work/out/accidental_debug_dump/grade.txt" ||
  fail "accidental_debug_dump: no hint how to fix it"
grep -q "^perfect,37,44,graded,37," "$work/out/gradebook.csv" || fail "perfect should have 37 of 44"
# Every forger and the perfect submission are in the gradebook: nothing was left out.
[ "$(($(wc -l <"$work/out/gradebook.csv") - 1))" -eq "$(ls "$class" | wc -l)" ] || fail "the gradebook misses a submission"
echo "forgers check: every forger rejected with its reason, the accidental trip explained, the solutions 37/37"
