#!/bin/sh
# Forged submissions (tests/forgers/, issue 17) against ./workbook grade --submissions: each
# forger scores 0 or is rejected by the source check with its reason, an accidental trip is
# rejected with a clear message, and the module-1 solutions score 31/31.
# Usage: forgers_check.sh SOURCE_TREE WORK_DIR
set -eu
tree=$1
work=$2
rm -rf "$work"
class=$work/class
mkdir -p "$class"

# Each forger: the committed skeleton of planar.cpp with its snippet appended, or inserted at
# the snippet's line //@skeleton.
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
mkdir -p "$class/perfect"
cp "$tree"/solutions/module01_kinematics/*.cpp "$class/perfect/"

fail() {
  cat "$work/batch.txt" "$work/out/gradebook.csv" >&2 || true
  echo "forgers check: $*" >&2
  exit 1
}
"$tree/workbook" grade --submissions "$class" --out "$work/out" --module 1 >"$work/batch.txt" 2>&1 ||
  fail "batch grading failed"
cat "$work/out/gradebook.csv"
