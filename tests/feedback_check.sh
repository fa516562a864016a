#!/bin/sh
# What a student meets when a build goes wrong, in a release of modules 1-2 (the fixture
# "release" of release_setup.sh, built and graded once, which project.release shares):
#   - a copied workbook reconfigures by itself: its build folder, configured for the original
#     folder, would otherwise build and grade the original's files (stale binaries);
#   - a function that forgets its return does not compile (-Werror=return-type), and the grade
#     output shows the compiler's reason with the file and line;
#   - the first build reports its progress, and a warning in an exercise file shows with the
#     grade table on every run until the file is fixed, not only on the run that compiled it.
# Usage: feedback_check.sh RELEASE_DIR WORK_DIR
#   RELEASE_DIR: the fixture's folder (release_setup.sh SOURCE_TREE RELEASE_DIR made it): its
#   release "MBD course/release", whose first grade's output is grade.txt. This check restores
#   what it changes there; the copy it grades is in WORK_DIR.
set -eu
shared=$1
work=$2
first="$shared/MBD course/release"
rm -rf "$work"
mkdir -p "$work"

fail() {
  echo "feedback check: $*" >&2
  exit 1
}

# The release's first grade (the fixture's): the skeleton graded, the build said what it does and
# reported its progress.
[ -f "$shared/grade.txt" ] || fail "no first grade in $shared: run the fixture release_setup.sh first"
grep -q "not implemented yet: M01T1 rotation" "$shared/grade.txt" || fail "the skeleton did not grade: $(cat "$shared/grade.txt")"
grep -q "^workbook: building (a first build takes minutes); the compiler's log: .*/grade.build.log$" "$shared/grade.txt" ||
  fail "the first build does not say what it does: $(cat "$shared/grade.txt")"
grep -E -q "^workbook: \[ *[0-9]+ s\] module 1: your code compiled$" "$shared/grade.txt" ||
  fail "the first build reports no progress: $(cat "$shared/grade.txt")"

# A warning (an unused variable) shows with the table, again on a run that compiles nothing, and
# no more once the file is fixed.
drivers=$first/module01_kinematics/src/drivers.cpp
cp "$drivers" "$work/drivers.cpp"
trap 'cp "$work/drivers.cpp" "$drivers"' EXIT  # the shared release gets its file back, however this ends
sed -i '0,/throw NotImplemented(/s//const int forgotten = 1; throw NotImplemented(/' "$drivers"
for run in compiled again; do
  (cd "$first" && ./workbook grade --module 1 >"$work/warning-$run.txt" 2>&1) || fail "grading with a warning failed"
  grep -E -q "^  module01_kinematics/src/drivers.cpp:[0-9]+:[0-9]+: warning: unused variable .forgotten." "$work/warning-$run.txt" ||
    fail "the warning is not shown ($run): $(cat "$work/warning-$run.txt")"
done
cp "$work/drivers.cpp" "$drivers"
trap - EXIT
(cd "$first" && ./workbook grade --module 1 >"$work/warning-fixed.txt" 2>&1) || fail "grading the fixed file failed"
if grep -q "warning" "$work/warning-fixed.txt"; then fail "the warning stays after the fix: $(cat "$work/warning-fixed.txt")"; fi

# A copy, with the original left in place; in the copy, rotation() without its return.
cp -R "$first" "$work/copy"
sed 's/throw NotImplemented("M01T1 rotation");/const double unused = phi; (void)unused;/' \
  "$work/copy/module01_kinematics/src/planar.cpp" >"$work/planar.cpp"
cmp -s "$work/planar.cpp" "$work/copy/module01_kinematics/src/planar.cpp" && fail "the stub of rotation() was not found"
mv "$work/planar.cpp" "$work/copy/module01_kinematics/src/planar.cpp"
(cd "$work/copy" && ./workbook grade --module 1 2>&1 | sed 's/\x1b\[[0-9;]*[mK]//g' >"$work/copy.txt") || true
cat "$work/copy.txt"
grep -q "was configured for $first" "$work/copy.txt" || fail "the copy did not say that it reconfigures"
grep -E -q "module01_kinematics/src/planar.cpp:[0-9]+:[0-9]+: error: (no return statement|non-void function does not return)" \
  "$work/copy.txt" ||
  fail "the missing return is not an error with its file and line"
grep -q "module01_kinematics does not compile" "$work/copy.txt" || fail "module 1 is not reported as not compiling"
if grep -q "not implemented yet: M01T1 rotation" "$work/copy.txt"; then
  fail "the copy graded the original's stale build"
fi
echo "feedback check: passed"
