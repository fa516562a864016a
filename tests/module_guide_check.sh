#!/bin/sh
# The instructor guide's "Adding a module" (docs/instructors.md) is followed, step by step, in a small copy of the course: the
# tree without build/, .git, its modules, solutions, tests, mistakes and extras (so nothing but
# the tools, the grader and the front end is built), to which the fixture module of
# autograder/fixtures/module (module09_fixture: one exercise function, a visible and a hidden
# test of a closed form, a mutant) is added by the guide's steps. Then:
#   - ./workbook studentify writes its skeleton from the solution (the TODO, the stub, no code);
#   - the manifest build/student/course.json lists the module and its graded item M09;
#   - ./workbook grade --solutions --module 9 scores full and writes its timings;
#   - ./workbook grade --module 9 (the skeleton) scores 0, every test "not implemented";
#   - the module's ctest checks exist and pass: reference, skeleton, source check, skeleton in
#     sync, the mutant caught;
#   - ./workbook release --out DIR carries its skeleton and visible test, not its hidden test, its
#     solution or the fixtures.
# The copy has no module 1..8, so module 9 links no earlier stage here: what the guide says about
# the earlier stages (module N links 1..N-1) is the course's, not checked here.
# Usage: module_guide_check.sh SOURCE_TREE WORK_DIR
set -eu
tree=$1
# The tests' user (nobody, as root) must reach the course (reachable_work.sh).
. "$tree/tests/reachable_work.sh"
reachable_work "$2"
mkdir -p "$work"
course=$work/course
fixture=$tree/autograder/fixtures/module
log=$work/log.txt

fail() {
  cat "$log" >&2 2>/dev/null || true
  echo "module guide check: $*" >&2
  exit 1
}

# The course without its modules: what every module shares (tools, grader, front end, cmake/).
mkdir -p "$course"
tar -C "$tree" --exclude=./build --exclude=./out --exclude=./.git --exclude='./module[0-9][0-9]_*' \
  --exclude=./solutions --exclude=./tests --exclude=./extras --exclude=./examples --exclude=./include \
  --exclude=./problems --exclude='./autograder/module[0-9][0-9]_*' --exclude=./autograder/fixtures \
  --exclude=./autograder/gradescope --exclude=./autograder/mistakes -cf - . | tar -C "$course" -xf -
mkdir -p "$course/solutions" "$course/autograder/mistakes"

# Step 1: the module folder (CMakeLists.txt with fmbd_add_stage, include/, README.md, hints.md).
cp -R "$fixture/module09_fixture" "$course/"
grep -q "^fmbd_add_stage($" "$course/module09_fixture/CMakeLists.txt" || fail "the fixture has no fmbd_add_stage"
# Step 2: fmbd_add_module after the last module's line of the top-level CMakeLists.txt.
grep -q "^fmbd_add_module(module08_full_fff)$" "$course/CMakeLists.txt" || fail "CMakeLists.txt has no module 8 line"
sed -i 's/^fmbd_add_module(module08_full_fff)$/&\nfmbd_add_module(module09_fixture)/' "$course/CMakeLists.txt"
# Step 3: the solution, the only hand-edited copy of the exercise file.
cp -R "$fixture/solutions/module09_fixture" "$course/solutions/"
# Step 4: an empty exercise file (the build names it), then ./workbook studentify fills it.
mkdir -p "$course/module09_fixture/src"
: >"$course/module09_fixture/src/spring.cpp"
# Step 5: the graded tests, visible and hidden; step 6: the mutants.
cp -R "$fixture/autograder/module09_fixture" "$course/autograder/"
cp -R "$fixture/autograder/mistakes/module09_fixture" "$course/autograder/mistakes/"

(cd "$course" && nice -n 10 ./workbook studentify) >"$log" 2>&1 || fail "./workbook studentify failed"
skeleton=$course/module09_fixture/src/spring.cpp
grep -q "TODO(M09T1)" "$skeleton" && grep -q 'throw std::logic_error("not implemented yet: M09T1' "$skeleton" &&
  ! grep -q "std::sqrt" "$skeleton" && ! grep -q "SOLUTION" "$skeleton" ||
  { cat "$skeleton" >&2; fail "studentify did not write the skeleton of module 9"; }

manifest=$course/build/student/course.json
grep -q '"folder" : "module09_fixture"' "$manifest" && grep -q '"id" : "M09"' "$manifest" ||
  fail "the manifest $manifest does not list module 9 and its graded item M09"

# Step 7: the reference scores full; its times go to autograder/timings.txt.
(cd "$course" && nice -n 10 ./workbook grade --solutions --module 9 --strict --timings-out "$work/m09-timings.txt") \
  >"$log" 2>&1 || fail "the reference of module 9 does not score full"
grep -q "^Score: 3/3" "$log" || fail "expected 3/3 for the reference of module 9"
[ "$(grep -c "^M09	" "$work/m09-timings.txt")" -eq 2 ] || fail "expected the times of 2 tests: $(cat "$work/m09-timings.txt")"
grep "^M09	" "$work/m09-timings.txt" >>"$course/autograder/timings.txt"

(cd "$course" && nice -n 10 ./workbook grade --module 9) >"$log" 2>&1 || fail "grading the skeleton failed"
grep -q "^Score: 0/3" "$log" && grep -q "not implemented yet: M09T1" "$log" ||
  fail "the skeleton of module 9 does not score 0 with \"not implemented\""

# The checks of every module: the skeleton and the mutant programs, then its ctest tests.
(cd "$course" && nice -n 10 cmake --build build/student -j1 --target m09_skeleton m09_mutant_period_without_two_pi m09_legal_variants) \
  >"$log" 2>&1 || fail "the skeleton and mutant programs of module 9 do not build"
(cd "$course" && ctest --test-dir build/student -R '^m09[.]' -N) >"$log" 2>&1
for check in reference_passes_every_test skeleton_fails_every_test_with_not_implemented vet_passes_the_reference \
  vet_passes_the_skeleton vet_passes_legal_variants skeleton_in_sync.spring.cpp mutant_caught.period_without_two_pi; do
  grep -q " m09[.]$check$" "$log" || fail "no test m09.$check"
done
(cd "$course" && ctest --test-dir build/student -R '^m09[.]' --output-on-failure) >"$log" 2>&1 ||
  fail "a check of module 9 failed"

# The release carries the skeleton and the visible test, not the hidden test, the solution or
# the fixtures.
(cd "$course" && ./workbook release --out "$work/release") >"$log" 2>&1 || fail "the release failed"
release=$work/release
[ -f "$release/module09_fixture/src/spring.cpp" ] && [ -f "$release/autograder/module09_fixture/visible/spring.test.cpp" ] ||
  fail "the release lacks module 9's skeleton or visible test"
cmp -s "$skeleton" "$release/module09_fixture/src/spring.cpp" || fail "the release's exercise file is not the skeleton"
[ ! -e "$release/autograder/module09_fixture/hidden" ] && [ ! -e "$release/solutions" ] &&
  [ ! -e "$release/autograder/mistakes" ] || fail "the release carries module 9's hidden test, solution or mutant"
! grep -rq "four times the mass doubles the period" "$release" || fail "the release names the hidden test"
grep -q "^M09	visible" "$release/autograder/timings.txt" && ! grep -q "^M09	hidden" "$release/autograder/timings.txt" ||
  fail "the release's timings are not module 9's visible ones"
echo "module guide check: module 9 added by the guide: skeleton written, reference 3/3, skeleton 0/3, its checks pass, released without its hidden test"
