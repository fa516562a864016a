#!/bin/sh
# Tooling conventions: every ctest test has a kind label (cmake/FmbdLabels.cmake); the job count
# follows a container's cgroup limits; clangd, started from the repository root, finds the compile
# commands of the student build (.clangd).
# Usage: tooling_check.sh SOURCE_TREE BUILD_DIR
set -eu
tree=$1
build=$2
work=$build/tooling-check
fail() {
  echo "tooling check: $*" >&2
  exit 1
}
count() { ctest --test-dir "$build" -N "$@" | sed -n 's/^Total Tests: //p'; }

[ "$(count -LE '.')" = 0 ] || { ctest --test-dir "$build" -N -LE '.' >&2; fail "these tests have no label"; }
[ "$(count -L '^unlabelled$')" = 0 ] || { ctest --test-dir "$build" -N -L '^unlabelled$' >&2; fail "these tests fit no kind"; }
all=$(count)
kinds=0
for kind in graded mutant project tools driver demo extras; do
  kinds=$((kinds + $(count -L "^$kind\$")))
done
[ "$kinds" = "$all" ] || fail "the kinds label $kinds tests, there are $all: a test has two kinds"
[ "$(count -L '^mutant$')" = "$(count -R '^m[0-9][0-9][.]mutant_caught[.]')" ] || fail "not every mutant is labelled mutant"
ctest --test-dir "$build" -N -L '^M03$' | grep -q "m03[.]reference_passes_every_test" || fail "M03 does not label module 3's graded tests"

# autograder/timings.txt gives every graded test its calibrated timeout: it lists each test of the
# reference builds, and nothing else.
mkdir -p "$work"
for lister in "$build"/autograder/m[0-9][0-9]_reference; do
  "$lister" --fmbd-list >"$work/listing.txt" || fail "$lister --fmbd-list failed"
  "$tree/workbook" inspect listing "$work/listing.txt" || fail "the listing of $lister cannot be read (above)"
done | sort >"$work/graded-tests.txt"
[ -s "$work/graded-tests.txt" ] || fail "no reference test program lists any test"
"$tree/workbook" inspect timings "$tree/autograder/timings.txt" >"$work/timed-tests.txt.unsorted" ||
  fail "autograder/timings.txt is not in its format (above)"
sort "$work/timed-tests.txt.unsorted" >"$work/timed-tests.txt"
if ! cmp -s "$work/graded-tests.txt" "$work/timed-tests.txt"; then
  diff "$work/timed-tests.txt" "$work/graded-tests.txt" | sed -n 's/^> /  untimed: /p; s/^< /  no longer a test: /p' >&2
  fail "autograder/timings.txt is out of date; regenerate it with ./workbook grade --solutions --jobs 1 --timings-out autograder/timings.txt (./workbook bench does)"
fi

# Compiles and tests at once follow a container's CPU quota and memory limit, not the host's cores
# (a fake cgroup tree: v2 files, then v1).
cgroup=$work-cgroup
rm -rf "$cgroup" && mkdir -p "$cgroup/cpu" "$cgroup/memory"
jobs_here() { env -u FMBD_JOBS FMBD_CGROUP_ROOT="$cgroup" "$tree/workbook" help | sed -n 's/^Compiles and tests at once here: \([0-9]*\) .*/\1/p'; }
cores=$(nproc)
[ "$(jobs_here)" = "$cores" ] || fail "without a cgroup limit: $(jobs_here) jobs, expected the $cores cores"
echo "100000 100000" >"$cgroup/cpu.max"
[ "$(jobs_here)" = 1 ] || fail "a CPU quota of 1: $(jobs_here) jobs"
echo "max 100000" >"$cgroup/cpu.max"
echo $((800 * 1024 * 1024)) >"$cgroup/memory.max"
[ "$(jobs_here)" = 1 ] || fail "800 MB of memory: $(jobs_here) jobs"
echo 9223372036854771712 >"$cgroup/memory.max"
[ "$(jobs_here)" = "$cores" ] || fail "an unlimited cgroup v1 memory: $(jobs_here) jobs"
rm "$cgroup/cpu.max" "$cgroup/memory.max"
echo 50000 >"$cgroup/cpu/cpu.cfs_quota_us"
echo 100000 >"$cgroup/cpu/cpu.cfs_period_us"
[ "$(jobs_here)" = 1 ] || fail "a v1 CPU quota of half a core: $(jobs_here) jobs"
rm -rf "$cgroup"

# Packages: an optional one (Spectra, absent from Ubuntu 22.04) is asked for only where the
# distribution offers it. Fake dpkg-query, apt-cache and id: catch2, nlohmann/json, CLI11 and Spectra are
# missing, and the user is not root, so the workbook prints the install command and stops.
fake=$work-bin
rm -rf "$fake" && mkdir -p "$fake"
printf '#!/bin/sh\ncase "$*" in *catch2* | *nlohmann-json3-dev* | *libcli11-dev* | *libspectra-dev*) exit 1 ;; esac\necho "install ok installed"\n' >"$fake/dpkg-query"
printf '#!/bin/sh\n[ "$1" = -u ] && echo 1000\n' >"$fake/id"
printf '#!/bin/sh\n[ -n "${FAKE_OFFERS_SPECTRA:-}" ]\n' >"$fake/apt-cache"
chmod +x "$fake/dpkg-query" "$fake/id" "$fake/apt-cache"
wanted=$(PATH=$fake:$PATH "$tree/workbook" grade 2>&1 | sed -n 's/^  sudo apt-get install -y --no-install-recommends//p' || true)
[ "$wanted" = " catch2 nlohmann-json3-dev libcli11-dev" ] || fail "without Spectra in the distribution, the install command asks for '$wanted'"
wanted=$(FAKE_OFFERS_SPECTRA=1 PATH=$fake:$PATH "$tree/workbook" grade 2>&1 | sed -n 's/^  sudo apt-get install -y --no-install-recommends//p' || true)
[ "$wanted" = " catch2 nlohmann-json3-dev libcli11-dev libspectra-dev" ] || fail "with Spectra in the distribution, the install command asks for '$wanted'"
rm -rf "$fake"

# clangd from the root of a fresh copy, configured as a student's first ./workbook grade does.
rm -rf "$work"
mkdir -p "$work"
tar -C "$tree" --exclude=./build --exclude=./out --exclude=./.git -cf - . | tar -C "$work" -xf -
(cd "$work" && cmake --preset student >configure.log 2>&1) || { cat "$work/configure.log" >&2; fail "configuring the student preset failed"; }
grep -q "module01_kinematics/src/planar.cpp" "$work/build/student/compile_commands.json" ||
  fail "build/student/compile_commands.json does not list the exercise files"
if command -v clangd >/dev/null 2>&1; then
  (cd "$work" && clangd --check=module01_kinematics/src/planar.cpp >clangd.log 2>&1) || true
  grep -q "Loaded compilation database from .*/build/student/compile_commands.json" "$work/clangd.log" ||
    { tail -n 20 "$work/clangd.log" >&2; fail "clangd does not find the compile commands from the root"; }
  grep -q "All checks completed, 0 errors" "$work/clangd.log" || { tail -n 20 "$work/clangd.log" >&2; fail "clangd reports errors"; }
else
  echo "tooling check: clangd is not installed; checked .clangd's compile commands only"
fi
rm -rf "$work"
echo "tooling check: $all tests labelled by kind; clangd finds the student build's compile commands"
