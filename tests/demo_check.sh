#!/bin/sh
# ./workbook demo on a machine where a first `./workbook grade` configured build/student before
# the demo packages were there (its course manifest lists no demos): it configures again and
# finds the demos.
# Where CMake still finds no gnuplot-iostream (here: Boost hidden from it), it exits non-zero with
# the command that installs the packages. And its own options: a demo's parameters go after --,
# and need a demo NAME. Nothing but the front end is compiled: the checks stop before a demo is
# built.
# Usage: demo_check.sh SOURCE_TREE WORK_DIR
set -eu
tree=$1
work=$2
rm -rf "$work"
mkdir -p "$work/copy"

fail() {
  echo "demo check: $*" >&2
  exit 1
}

# A copy of the sources without build folders.
(cd "$tree" && tar --exclude=./build --exclude=./out --exclude=./.git -cf - .) | (cd "$work/copy" && tar -xf -)
cd "$work/copy"

# Options of ./workbook demo itself: refused before anything is built for a demo.
status=0
./workbook demo -- --spin-rate 40 >"$work/no-name.txt" 2>&1 || status=$?
[ "$status" -eq 2 ] && grep -q "parameters after -- need a demo NAME" "$work/no-name.txt" ||
  fail "parameters without a demo NAME: exit $status, $(cat "$work/no-name.txt")"
status=0
./workbook demo spinning_beam --spin-rate 40 >"$work/no-dashes.txt" 2>&1 || status=$?
[ "$status" -eq 2 ] && grep -q "go after --: ./workbook demo NAME -- --spin-rate" "$work/no-dashes.txt" ||
  fail "a demo parameter before --: exit $status, $(cat "$work/no-dashes.txt")"

# The stale state: configured with no demos in the manifest (its writer's, with the demos off: as
# a build configured before the demo packages were installed has none).
cmake --preset student >"$work/configure.txt" 2>&1 || fail "configuring the copy failed: $(cat "$work/configure.txt")"
grep -q '"name" : "spinning_beam"' build/student/course.json || fail "this machine has no demo packages: nothing to check"
cmake -DFMBD_BUILD_DEMOS=OFF build/student >"$work/configure-off.txt" 2>&1 ||
  fail "configuring the copy without demos failed: $(cat "$work/configure-off.txt")"
! grep -q '"spinning_beam"' build/student/course.json || fail "the demos were not taken out of the manifest"
status=0
./workbook demo no_such_demo >"$work/stale.txt" 2>&1 || status=$?
cat "$work/stale.txt"
grep -q "configuring it again" "$work/stale.txt" || fail "a manifest without demos did not configure again"
[ "$status" -eq 2 ] && grep -q "no demo named 'no_such_demo'; the demos are: .*spinning_beam" "$work/stale.txt" ||
  fail "after configuring again the demos are not listed (exit $status)"

# A package CMake cannot find: no demos, exit non-zero with the install command.
cmake -DCMAKE_DISABLE_FIND_PACKAGE_Boost=ON build/student >"$work/no-boost.txt" 2>&1 || fail "configuring without Boost failed"
status=0
./workbook demo >"$work/missing.txt" 2>&1 || status=$?
cat "$work/missing.txt"
[ "$status" -ne 0 ] || fail "no demo was built, and ./workbook demo exited 0"
if command -v dpkg-query >/dev/null 2>&1; then
  grep -q "^  sudo apt-get install -y --no-install-recommends gnuplot-nox libgnuplot-iostream-dev libboost-iostreams-dev libboost-filesystem-dev libboost-system-dev$" \
    "$work/missing.txt" || fail "the install command is not given"
else
  grep -q "brew install gnuplot boost" "$work/missing.txt" || fail "the install command is not given"
fi
echo "demo check: passed"
