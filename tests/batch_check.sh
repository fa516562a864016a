#!/bin/sh
# ./workbook grade --submissions: every subfolder graded, past a submission that does not compile,
# each with its results and its own logs, a one-line summary as it goes, a gradebook with a column
# per module and per task, a lock on the shared tree, and --resume. Also ./workbook handin: the
# zip holds the exercise files and the answers file only, and --submission grades it. --out holds
# a space. The tutorial problems are graded with the numbers of the roster's name (the folder's):
# alice answers her own variant, bob hands in alice's answers and gains nothing by it.
# Graded with the workbook of the fixture "grader" (gradescope_setup.sh: an instructor's copy of
# module 1 whose grader setup.sh built), which project.gradescope, project.submission and
# project.forgers share; the student's copy is a release of the source tree.
# Usage: batch_check.sh SOURCE_TREE GRADER WORK_DIR M01_PROBLEMS_PROGRAM
#   GRADER: the instructor's copy that grades (the fixture's autograder/source).
set -eu
tree=$1
grader=$2
work=$3
problems=$4
rm -rf "$work"
out="$work/class results"  # a path with a space
mkdir -p "$work/class/alice/module01_kinematics" "$work/class/bob/module01_kinematics"
cp "$tree"/solutions/module01_kinematics/*.cpp "$work/class/alice/"
cp "$tree"/solutions/module01_kinematics/*.cpp "$work/class/bob/"
echo "this does not compile" >>"$work/class/bob/joints.cpp"
FMBD_STUDENT=alice "$problems" --model-answers >"$work/class/alice/module01_kinematics/answers.txt"
cp "$work/class/alice/module01_kinematics/answers.txt" "$work/class/bob/module01_kinematics/"

fail() {
  cat "$work/batch.txt" "$out/gradebook.csv" >&2 || true
  echo "batch check: $*" >&2
  exit 1
}

# The shared tree is locked (flock(2) on build/submission.lock) while another process holds it:
# here this script, through flock(1). The lock ends with its holder, however it ends.
mkdir -p "$grader/build"
lock=$grader/build/submission.lock
[ ! -d "$lock" ] || rm -rf "$lock"  # the lock folder of an earlier version
exec 9>>"$lock"
if flock -n 9; then
  echo $$ >"$lock"
  if "$grader/workbook" grade --submissions "$work/class" --out "$work/locked" --module 1 >"$work/locked.txt" 2>&1 9>&-; then
    exec 9>&-
    fail "a second grading ran while the tree was locked"
  fi
  exec 9>&-
  grep -q "another grading of submissions (process $$) is using this copy" "$work/locked.txt" ||
    { cat "$work/locked.txt" >&2; fail "the refusal does not say why"; }
fi
exec 9>&-

"$grader/workbook" grade --submissions "$work/class" --out "$out" --module 1 >"$work/batch.txt" 2>&1 ||
  fail "batch grading failed"
flock -n "$lock" true || fail "the lock was not released"
grep -q "^workbook: \[1/2\] alice: 44/44 graded (" "$work/batch.txt" || fail "no summary line for alice"
grep -q "^workbook: \[2/2\] bob: [0-9]*/44 build_error:M01 (" "$work/batch.txt" || fail "no summary line for bob"
# bob's code does not compile, but his answers are graded: against his own variant, not alice's.
grep -q "^M01,P2,0,2,failed$" "$out/bob/tasks.csv" && grep -q "^M01,P3,0,3,failed$" "$out/bob/tasks.csv" ||
  fail "alice's answers scored for bob: $(cat "$out/bob/tasks.csv")"
gradebook=$out/gradebook.csv
header=$(head -n 1 "$gradebook")
case $header in "submission,score,max_score,status,M01,M01T1,M01T2,"*) ;; *) fail "gradebook header: $header" ;; esac
case $header in *",M01T7,M01P1,M01P2,M01P3") ;; *) fail "gradebook header without the problems' columns: $header" ;; esac
grep -q "^alice,44,44,graded,44,[0-9]" "$gradebook" || fail "alice should have 44 of 44, and 44 in M01"
grep -q "^bob,[0-9]*,44,build_error:M01,[0-9]*,0," "$gradebook" || fail "bob's module does not compile: build_error"
# The module columns add up to the score, and each module's task columns to its column (read by
# the front end, ./workbook inspect); each task's maximum is in tasks.csv, whose total is the
# maximum score.
"$grader/workbook" inspect gradebook "$gradebook" >"$work/gradebook-check.txt" 2>&1 ||
  { cat "$work/gradebook-check.txt" >&2; fail "the gradebook's columns do not add up to the score"; }
[ "$("$grader/workbook" inspect tasks "$out/alice/tasks.csv" --sum max_score)" = 44 ] ||
  fail "tasks.csv: the maxima do not add up to 44"
grep -q "does not compile" "$out/bob/grade.txt" || fail "bob's compiler errors are not reported"
# Each submission keeps its own build log, and its grade.txt points there.
grep -q "this does not compile" "$out/bob/logs/m01_student.build.log" || fail "bob's build log is not in his results"
grep -q "logs/m01_student.build.log" "$out/bob/grade.txt" || fail "bob's grade.txt does not point to his own log"
! grep -q "this does not compile" "$out/alice/logs/m01_student.build.log" || fail "alice's log is bob's"
grep -q '<failure type="build_error" message="does not compile: module01_kinematics/src/joints.cpp:' "$out/bob/junit.xml" ||
  fail "bob's junit.xml does not carry the compile error"
for name in alice bob; do
  [ -s "$out/$name/results.json" ] || fail "no results.json for $name"
  [ -s "$out/$name/junit.xml" ] || fail "no junit.xml for $name"
done

# --resume grades only what is missing.
rm "$out/alice/summary.csv"
"$grader/workbook" grade --submissions "$work/class" --out "$out" --module 1 --resume >"$work/resume.txt" 2>&1 ||
  { cat "$work/resume.txt" >&2; fail "resuming failed"; }
grep -q "^workbook: \[2/2\] bob: graded before (--resume): [0-9]*,44,build_error:M01$" "$work/resume.txt" ||
  { cat "$work/resume.txt" >&2; fail "--resume graded bob again"; }
grep -q "^workbook: \[1/2\] alice: 44/44 graded" "$work/resume.txt" || { cat "$work/resume.txt" >&2; fail "--resume did not grade alice"; }
[ "$(wc -l <"$gradebook")" -eq 3 ] || fail "the resumed gradebook does not have both rows"

# handin: a student's copy with alice's files packs exactly the exercise files (those that
# solutions/ provides) and her answers file, and --submission grades the zip (alice.zip: alice's
# variant).
student=$work/student
"$tree/workbook" release --out "$student" --through 1 >/dev/null
cp "$work"/class/alice/*.cpp "$student/module01_kinematics/src/"
cp "$work/class/alice/module01_kinematics/answers.txt" "$student/module01_kinematics/"
"$student/workbook" handin --out "$work/alice.zip" >"$work/handin.txt" 2>&1 || { cat "$work/handin.txt" >&2; fail "handin failed"; }
(cd "$work" && cmake -E tar tf alice.zip | sort) >"$work/zip.txt"
{ (cd "$tree/solutions" && ls module01_kinematics/*.cpp | sed 's|/|/src/|'); echo module01_kinematics/answers.txt; } |
  sort >"$work/expected.txt"
cmp -s "$work/zip.txt" "$work/expected.txt" || { diff "$work/expected.txt" "$work/zip.txt" >&2; fail "the handin zip holds other files than the exercise and answers files"; }
"$grader/workbook" grade --submission "$work/alice.zip" --module 1 --strict >"$work/zip-grade.txt" 2>&1 ||
  { cat "$work/zip-grade.txt" >&2; fail "the handin zip does not grade 44/44"; }
echo "batch check: two submissions graded, one past a compile error; the problems by the roster's name; logs, gradebook columns, lock, --resume and handin"
