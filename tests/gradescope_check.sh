#!/bin/sh
# A Gradescope run, reproduced in a fake /autograder tree (the fixture "grader" of
# gradescope_setup.sh: the zip of ./workbook gradescope unpacked into source/, and setup.sh's
# build of the grader): run_autograder writes results.json for a full-marks submission, a forged
# one, one that does not compile, and a run where grading itself fails. The tutorial problems are
# graded with the numbers of the student that Gradescope's submission metadata names.
# Usage: gradescope_check.sh SOURCE_TREE WORK_DIR M01_PROBLEMS_PROGRAM
#   WORK_DIR: the fixture's folder (gradescope_setup.sh SOURCE_TREE WORK_DIR made it). What this
#   check changes in source/ (gradescope.conf, the workbook), it restores.
set -eu
tree=$1
work=$2
problems=$3
root=$work/autograder

fail() {
  echo "gradescope check: $*" >&2
  exit 1
}
check_results() {  # check_results NAME CMAKE_DEFINITIONS...
  name=$1
  shift
  cmake "$@" -DRESULTS="$root/results/results.json" -P "$tree/tests/check_results_json.cmake" ||
    { cat "$work/$name.log" >&2; fail "$name: results.json is wrong (above)"; }
}

[ -x "$root/source/run_autograder" ] && [ -f "$work/gradescope.conf" ] ||
  fail "no grader in $root: run the fixture gradescope_setup.sh first"
rm -rf "$root/submission" "$root/results"
mkdir -p "$root/submission"
cp "$work/gradescope.conf" "$root/source/gradescope.conf"
# The grader's tree as the fixture made it, however this check ends.
trap '[ ! -f "$work/workbook" ] || mv "$work/workbook" "$root/source/workbook"; cp "$work/gradescope.conf" "$root/source/gradescope.conf"' EXIT
export FMBD_AUTOGRADER_ROOT="$root"

# Full marks, hidden tests after publishing: the code, and the answers of Ada's variant.
cat >"$root/submission_metadata.json" <<'JSON'
{"id": 1, "users": [{"email": "ada@example.org", "id": 7, "name": "Ada Lovelace"}], "previous_submissions": []}
JSON
cp "$tree"/solutions/module01_kinematics/*.cpp "$root/submission/"
mkdir -p "$root/submission/module01_kinematics"
FMBD_STUDENT=ada@example.org "$problems" --model-answers >"$root/submission/module01_kinematics/answers.txt"
"$root/source/run_autograder" >"$work/full.log" 2>&1 || fail "run_autograder exited non-zero"
check_results full -DSCORE=44 -DMAX_SCORE=44 -DHIDDEN_VISIBILITY=after_published

# A forged submission (issue 17; tests/forgers/fake_list.cpp: its own test list worth 1000 points
# and a token reader): rejected by the source check, with the reason in every test's output;
# the points come from the reference's list.
cat "$tree/module01_kinematics/src/planar.cpp" "$tree/tests/forgers/fake_list.cpp" >"$root/submission/planar.cpp"
"$root/source/run_autograder" >"$work/forged.log" 2>&1 || fail "run_autograder exited non-zero"
check_results forged -DSCORE=7 -DMAX_SCORE=44 \
  "-DOUTPUT_MENTIONS=M01 scores 0: rejected by the source check: module01_kinematics/src/planar.cpp:" \
  "-DTESTS_MENTION=rejected by the source check: module01_kinematics/src/planar.cpp:"
cp "$tree"/solutions/module01_kinematics/planar.cpp "$root/submission/"

# A submission that does not compile: every test of the module fails, and the compiler's error,
# with the student's own file name and line, is in what the student sees: each test's output and
# the top-level output (the run's stdout, the grader's build log, stays hidden).
echo "this does not compile" >>"$root/submission/joints.cpp"
line=$(wc -l <"$root/submission/joints.cpp")
"$root/source/run_autograder" >"$work/broken.log" 2>&1 || fail "run_autograder exited non-zero"
check_results broken -DSCORE=7 -DMAX_SCORE=44 \
  "-DOUTPUT_MENTIONS=module01_kinematics/src/joints.cpp:$line:1: error:" \
  "-DTESTS_MENTION=does not compile: module01_kinematics/src/joints.cpp:$line:1: error:"

# Grading fails (here: a broken configuration): results.json still says so.
echo 'MODULE_ARGS="--module one"' >>"$root/source/gradescope.conf"
"$root/source/run_autograder" >"$work/failed.log" 2>&1 || fail "run_autograder exited non-zero"
check_results failed -DSCORE=0 -DMAX_SCORE=0 "-DOUTPUT_MENTIONS=--module needs a number"

# The grader itself does not run: results.json says so, without a line of its log.
mv "$root/source/workbook" "$work/workbook"
printf '#!/bin/sh\nexit 3\n' >"$root/source/workbook"
chmod +x "$root/source/workbook"
"$root/source/run_autograder" >"$work/not-run.log" 2>&1 || fail "run_autograder exited non-zero"
check_results not-run -DSCORE=0 -DMAX_SCORE=0 "-DOUTPUT_MENTIONS=could not run (exit status 3)"
mv "$work/workbook" "$root/source/workbook"

# The visibility of hidden tests is configurable.
sed 's/^HIDDEN_VISIBILITY=.*/HIDDEN_VISIBILITY=hidden/' "$work/gradescope.conf" >"$root/source/gradescope.conf"
cp "$tree"/solutions/module01_kinematics/joints.cpp "$root/submission/"
"$root/source/run_autograder" >"$work/hidden.log" 2>&1 || fail "run_autograder exited non-zero"
check_results hidden -DSCORE=44 -DMAX_SCORE=44 -DHIDDEN_VISIBILITY=hidden
echo "gradescope check: setup, full marks, a forgery, a compile error, a failed run and a grader that does not run all give valid results.json"
