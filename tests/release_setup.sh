#!/bin/sh
# The student releases that project.release and project.feedback share (the CTest fixture
# "release"), made and built once: modules 1-2 with the solutions of module 1 at a path with a
# space, a week-3 release (modules 1-3, solutions of 1-2) and the whole course. In the first, the
# front end is built (./workbook help) and the release graded once: its first build, whose output
# both checks read (help.txt, grade.txt, tasks.csv). The checks that use the release restore what they change.
# Usage: release_setup.sh SOURCE_TREE WORK_DIR
set -eu
tree=$1
work=$2
rm -rf "$work"
release="$work/MBD course/release"  # a checkout path with a space (macOS: ~/Documents/MBD course)

fail() {
  echo "release setup: $*" >&2
  exit 1
}

"$tree/workbook" release --out "$release" --through 2 --solutions-through 1
"$tree/workbook" release --out "$work/week3" --through 3 --solutions-through 2 >/dev/null
"$tree/workbook" release --out "$work/full" >/dev/null

# The first commands in the release: help (configures build/student, builds the front end) and a
# first grade of everything it has (project.release and project.feedback check its output, and
# project.release its table of tasks, tasks.csv).
(cd "$release" && ./workbook help) >"$work/help.txt" 2>&1 || { cat "$work/help.txt"; fail "help failed"; }
(cd "$release" && ./workbook grade --csv "$work/tasks.csv") >"$work/grade.txt" 2>&1 ||
  { cat "$work/grade.txt"; fail "grading failed"; }
echo "release setup: releases of weeks 2 and 3 and the whole course; the first built and graded"
