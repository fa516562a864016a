#!/bin/sh
# ./workbook grade --submissions: every subfolder graded, past a submission that does not
# compile, with a results folder each and a CSV gradebook. Usage: batch_check.sh SOURCE_TREE WORK_DIR
set -eu
tree=$1
work=$2
rm -rf "$work"
mkdir -p "$work/class/alice" "$work/class/bob"
cp "$tree"/solutions/module01_kinematics/*.cpp "$work/class/alice/"
cp "$tree"/solutions/module01_kinematics/*.cpp "$work/class/bob/"
echo "this does not compile" >>"$work/class/bob/joints.cpp"

fail() {
  cat "$work/batch.txt" "$work/out/gradebook.csv" >&2 || true
  echo "batch check: $*" >&2
  exit 1
}
"$tree/workbook" grade --submissions "$work/class" --out "$work/out" --module 1 >"$work/batch.txt" 2>&1 ||
  fail "batch grading failed"
grep -qx "alice,31,31,graded" "$work/out/gradebook.csv" || fail "alice should have 31 of 31"
grep -qx "bob,0,31,graded" "$work/out/gradebook.csv" || fail "bob's module does not compile: 0 of 31"
grep -q "does not compile" "$work/out/bob/grade.txt" || fail "bob's compiler errors are not reported"
for name in alice bob; do
  [ -s "$work/out/$name/results.json" ] || fail "no results.json for $name"
  [ -s "$work/out/$name/junit.xml" ] || fail "no junit.xml for $name"
done
echo "batch check: two submissions graded, one past a compile error; gradebook written"
