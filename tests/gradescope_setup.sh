#!/bin/sh
# A fake /autograder tree (the CTest fixture "grader"), as Gradescope makes it: the zip of
# ./workbook gradescope --module 1 unpacked into source/, checked (executable scripts, hidden
# tests, no mistake catalogue, nothing the release policy omits, the solutions), and setup.sh run
# once: it builds the grader. project.gradescope runs run_autograder in it; project.submission,
# project.batch and project.forgers grade with its workbook (source/, an instructor's copy of
# module 1 whose grader is built), so that the grader is built once for all four.
# Usage: gradescope_setup.sh SOURCE_TREE WORK_DIR
set -eu
tree=$1
work=$2
rm -rf "$work"
root=$work/autograder
mkdir -p "$root/source" "$root/submission"

fail() {
  echo "gradescope setup: $*" >&2
  exit 1
}

"$tree/workbook" gradescope --out "$work/module01.zip" --module 1 >/dev/null
(cd "$root/source" && cmake -E tar xf "$work/module01.zip")
[ -x "$root/source/setup.sh" ] && [ -x "$root/source/run_autograder" ] || fail "setup.sh and run_autograder must be executable"
[ -d "$root/source/autograder/module01_kinematics/hidden" ] || fail "the hidden tests are missing"
[ ! -e "$root/source/autograder/mistakes" ] || fail "the mistake catalogue is in the zip"
omitted=$("$tree/workbook" inspect policy "$tree/autograder/release_policy.txt" --rule gradescope-omit) ||
  fail "the release policy cannot be read"
[ -n "$omitted" ] || fail "the release policy leaves nothing out of the Gradescope zip"
for path in $omitted; do
  [ ! -e "$root/source/$path" ] || fail "$path is in the zip; the release policy omits it"
done
[ -d "$root/source/solutions" ] || fail "the solutions (the test lists of the grader) are missing"

"$root/source/setup.sh" >"$work/setup.log" 2>&1 || { cat "$work/setup.log" >&2; fail "setup.sh failed"; }
cp "$root/source/gradescope.conf" "$work/gradescope.conf"  # as written, for the checks that change it
echo "gradescope setup: the zip unpacked and checked; setup.sh built the grader"
