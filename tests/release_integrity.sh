#!/bin/sh
# A student release holds no code that restates a solution it does not carry, and no maintainer
# material. Releases of all modules with the solutions of none, modules 1-4 and all of them; each
# is searched by fmbd-similarity for the solution blocks of the modules it does not carry. Then a
# disguised copy of a solution block (identifiers renamed, numbers changed) is planted into a given
# file of a release, and the tool must report it. The released checks headers of the autograder
# declare no helper that only hidden tests use. Nothing is built.
# The allow-list tools/similarity.allow names the files that may match, each with its reason.
# Usage: release_integrity.sh SOURCE_TREE WORK_DIR FMBD_SIMILARITY PLANT_FILE
#                             FMBD_HIDDEN_ONLY_HELPERS
#   PLANT_FILE: a file of the release, relative to its root, that receives the planted copy.
set -eu
tree=$1
work=$2
similarity=$3
plant_file=$4
hidden_only_helpers=$5
rm -rf "$work"
mkdir -p "$work"

fail() {
  echo "release integrity: $*" >&2
  exit 1
}

modules=$(cd "$tree" && ls -d module[0-9][0-9]_* | wc -l)
[ "$modules" -eq 8 ] || fail "expected 8 modules in $tree, found $modules"

# The arguments of the release policy's rules, read by the front end (./workbook inspect).
policy() {
  "$tree/workbook" inspect policy "$tree/autograder/release_policy.txt" --rule "$1" ||
    fail "the release policy (autograder/release_policy.txt) cannot be read"
}
omitted=$(policy omit)
omitted_engine=$(policy omit-engine)
[ -n "$omitted" ] || fail "the release policy (autograder/release_policy.txt) omits nothing"

# unreleased_solutions M: the solution files of modules M+1..8, one per line.
unreleased_solutions() {
  for folder in "$tree"/solutions/module[0-9][0-9]_*; do
    number=${folder##*/module}; number=${number%%_*}
    [ "${number#0}" -le "$1" ] || ls "$folder"/*.cpp
  done
}

# similarity_over ALLOW RELEASE M: fmbd-similarity over RELEASE for the solution files of modules
# M+1..8, each one argument (the tree's path may hold spaces).
similarity_over() {
  allow=$1
  over=$2
  solutions=$(unreleased_solutions "$3")
  set --
  while IFS= read -r file; do
    [ -z "$file" ] || set -- "$@" "$file"
  done <<EOF
$solutions
EOF
  "$similarity" --allow "$allow" "$over" "$@"
}

for m in 0 4 8; do
  release=$work/release-$m
  "$tree/workbook" release --out "$release" --through 8 --solutions-through "$m" >/dev/null

  # The similarity check (its report is kept in WORK/similarity-M.txt).
  if ! similarity_over "$tree/tools/similarity.allow" "$release" "$m" >"$work/similarity-$m.txt" 2>&1; then
    cat "$work/similarity-$m.txt"
    fail "the release with the solutions of modules 1..$m restates the solutions of later modules (above)"
  fi
  tail -n 1 "$work/similarity-$m.txt"

  # What the release policy omits (the instructor's material, the maintainer tools) is absent;
  # the engine (extras, the umbrella header, the consumer project) only with every solution.
  for path in $omitted; do
    [ "$path" != solutions ] || [ "$m" -eq 0 ] || continue  # those released are added back (below)
    for found in "$release"/$path; do  # PATH may hold a *
      [ ! -e "$found" ] || fail "${found#"$release"/} is in the release; the release policy omits $path"
    done
  done
  for path in $omitted_engine; do
    if [ "$m" -lt 8 ]; then
      [ ! -e "$release/$path" ] || fail "$path is in the release with the solutions of modules 1..$m"
    elif [ -e "$tree/$path" ]; then
      [ -e "$release/$path" ] || fail "$path is missing from the release with every solution"
    fi
  done
  [ -z "$(ls -d "$release"/solutions/module* 2>/dev/null | sed -n "$((m + 1))p")" ] ||
    fail "the release with the solutions of modules 1..$m carries more of them"
  # The worked solutions of the tutorial problems come with their module's solutions, not before;
  # the problems themselves (their statements and programs) and no answers file are in every one.
  for worked in "$tree"/solutions/module*/problems.md; do
    folder=${worked%/problems.md}; folder=${folder##*/}
    number=${folder#module}; number=${number%%_*}
    if [ "${number#0}" -le "$m" ]; then
      [ -f "$release/solutions/$folder/problems.md" ] || fail "the worked solutions of $folder are missing from the release with solutions 1..$m"
    else
      [ ! -e "$release/solutions/$folder/problems.md" ] || fail "the release with solutions 1..$m has the worked solutions of $folder"
    fi
    [ -f "$release/$folder/problems/problems.cpp" ] || fail "the problems of $folder are missing from the release with solutions 1..$m"
    [ ! -e "$release/$folder/answers.txt" ] || fail "the release with solutions 1..$m carries an answers file of $folder"
  done

  # Mutants, wherever they are.
  if find "$release" -name '*.mutant' | grep .; then fail "mutants in the release (above)"; fi
  if grep -rln "@@ replace\|fmbd-mutate\|fmbd-similarity" "$release" --include='*.md' --include='*.txt' \
       --include='*.cmake' --include='*.cpp' --include='*.hpp' | grep -v "^$release/autograder/CMakeLists.txt$" | grep .; then
    fail "the release documents the mutant format or the maintainer tools (files above)"
  fi

  # READMEs and guides (docs/): every relative link leads to a path of the release (the extras'
  # too, where it has them); no instructor-only part; the module READMEs without benchmarks or maintainer commands.
  sh "$tree/tests/readme_links.sh" "$release" || fail "dead links in the READMEs of the release with solutions 1..$m (above)"
  if grep -rn "instructor-only\|^## For instructors\|^## Instructor guide" "$release" --include=README.md ||
     grep -n "instructor-only\|^# For instructors\|^## Instructor guide" "$release"/docs/*.md; then
    fail "the release READMEs or guides hold instructor-only parts (lines above)"
  fi
  if grep -n "workbook bench\|fmbd-bench\|bench/\|workbook test\|workbook release\|workbook studentify\|mutant" \
       "$release"/module[0-9][0-9]_*/README.md; then
    fail "the module READMEs of the release hold benchmark or maintainer material (lines above)"
  fi

  # Skeletons name no folder the student lacks.
  if grep -rn "solutions/" "$release"/module[0-9][0-9]_*/src; then
    fail "exercise files mention solutions/ (above)"
  fi
done

# Released checks headers declare only what the release uses (a visible test, or a released
# helper that one calls): a helper of the hidden tests only lives in hidden/ with them, since its
# name and comments would show what the hidden tests try (fmbd-hidden-only-helpers:
# tests/tools/hidden_only_helpers.cpp).
checks=$work/release-0/autograder/module03_lagrange
"$hidden_only_helpers" "$work/release-0" >"$work/hidden-only.txt" ||
  { cat "$work/hidden-only.txt"; fail "released checks headers declare names that only hidden tests use (above)"; }
# The check can fail: a declaration that nothing released uses, planted into a released header,
# is named; once a visible test uses it, it is not.
cp "$checks/dynamics_checks.hpp" "$work/dynamics_checks.hpp"
sed -i 's|^}  // namespace fmbd::testing::m03$|Model planted_scenario(double size);\n&|' "$checks/dynamics_checks.hpp"
if "$hidden_only_helpers" "$work/release-0" >"$work/hidden-only-planted.txt"; then
  fail "a planted declaration that nothing released uses was not reported"
fi
grep -qx "autograder/module03_lagrange/dynamics_checks.hpp: planted_scenario" "$work/hidden-only-planted.txt" ||
  { cat "$work/hidden-only-planted.txt"; fail "the report does not name the planted declaration"; }
visible=$(ls "$checks"/visible/*.test.cpp | head -n 1)
cp "$visible" "$work/visible.test.cpp"
echo "static const auto planted_use = &planted_scenario;" >>"$visible"
"$hidden_only_helpers" "$work/release-0" >"$work/hidden-only-used.txt" ||
  { cat "$work/hidden-only-used.txt"; fail "a declaration that a visible test uses was reported"; }
cp "$work/dynamics_checks.hpp" "$checks/dynamics_checks.hpp"
cp "$work/visible.test.cpp" "$visible"

# The tool can fail: a copy of an unreleased solution block, disguised, in a given file.
release=$work/release-0
[ -f "$release/$plant_file" ] || fail "no file $plant_file to plant into"
source=$(unreleased_solutions 4 | head -n 1)
awk '/\/\/ BEGIN SOLUTION/ { inside = 1; next } /\/\/ END SOLUTION/ { if (inside) exit } inside' "$source" |
  awk '
    function plus7(digits,   sum, carry, i, d) {  # in decimal, exact for any length
      sub(/^0+/, "", digits); carry = 7; sum = ""
      for (i = length(digits); i > 0; --i) {
        d = substr(digits, i, 1) + carry; sum = (d % 10) sum; carry = int(d / 10)
      }
      return (carry ? carry : "") sum
    }
    BEGIN { split("auto bool const double for if else int return static_cast", words, " ")
            for (w in words) keep[words[w]] = 1 }
    { out = ""; rest = $0
      while (match(rest, /[A-Za-z0-9_]+/)) {  # each word: an identifier, an integer, or neither (1e)
        word = substr(rest, RSTART, RLENGTH)
        if (word ~ /^[0-9]+$/) word = plus7(word)                             # change every integer
        else if (word ~ /^[A-Za-z_]/ && !(word in keep)) word = word "_copy"  # rename every identifier
        out = out substr(rest, 1, RSTART - 1) word; rest = substr(rest, RSTART + RLENGTH)
      }
      print out rest }
  ' >"$work/planted.txt"
[ "$(wc -l <"$work/planted.txt")" -ge 4 ] || fail "the first solution block of $source is too short to plant"
grep -q "_copy" "$work/planted.txt" || fail "the planted copy renamed no identifier"
{ echo "/* planted by the test:"; cat "$work/planted.txt"; echo "*/"; } >"$work/commented.txt"
cp "$release/$plant_file" "$work/original"

# Inside a comment the copy is not code: no match.
cat "$work/original" "$work/commented.txt" >"$release/$plant_file"
similarity_over "$tree/tools/similarity.allow" "$release" 0 >"$work/similarity-commented.txt" 2>&1 ||
  { cat "$work/similarity-commented.txt"; fail "a solution inside a comment counts as code"; }

# As code it is reported, with both locations; an allow-list entry with a reason tolerates it.
cat "$work/original" "$work/planted.txt" >"$release/$plant_file"
if similarity_over "$tree/tools/similarity.allow" "$release" 0 >"$work/similarity-planted.txt" 2>&1; then
  cat "$work/similarity-planted.txt"
  fail "fmbd-similarity missed a copy of $source planted into $plant_file"
fi
grep -q "^$plant_file:[0-9]*-[0-9]*: restates $source:[0-9]*-[0-9]*$" "$work/similarity-planted.txt" ||
  { cat "$work/similarity-planted.txt"; fail "the report does not name both places"; }
{ cat "$tree/tools/similarity.allow"; printf '%s  # planted on purpose by the test\n' "$plant_file"; } >"$work/allow.txt"
similarity_over "$work/allow.txt" "$release" 0 >"$work/similarity-allowed.txt" 2>&1 ||
  { cat "$work/similarity-allowed.txt"; fail "an allowed file still fails the check"; }
grep -q "^allowed: $plant_file (planted on purpose by the test)$" "$work/similarity-allowed.txt" ||
  fail "the allowed match is not reported as allowed"
{ cat "$tree/tools/similarity.allow"; printf '%s\n' "$plant_file"; } >"$work/allow-no-reason.txt"
if similarity_over "$work/allow-no-reason.txt" "$release" 0 >/dev/null 2>&1; then
  fail "an allow-list entry without a reason was accepted"
fi
# In a git checkout, a release holds only what git tracks: a grade log that names hidden tests, or
# a student's submission, lying in the instructor's tree stays out, and the release names them.
# (A clone of the committed tree, so that nothing is planted into the tree the other tests read.)
stray=""
if command -v git >/dev/null 2>&1 && git -C "$tree" ls-files --error-unmatch workbook >/dev/null 2>&1; then
  clone=$work/clone
  git clone -q "$tree" "$clone"
  hidden_name=$(grep -ho 'GRADED_TEST("[^"]*"' "$tree"/autograder/module01_*/hidden/*.test.cpp | head -n 1 |
    sed 's/GRADED_TEST("//; s/"$//')
  [ -n "$hidden_name" ] || fail "no hidden test name of module 1 found"
  echo "  0/1  FAIL  (hidden) $hidden_name" >"$clone/grade.log"
  mkdir -p "$clone/submissions/alice"
  echo "// a student's planar.cpp" >"$clone/submissions/alice/planar.cpp"
  (cd "$clone" && ./workbook release --out "$work/release-clone" --through 1) >"$work/release-clone.txt" 2>&1 ||
    { cat "$work/release-clone.txt"; fail "the release of a clone failed"; }
  for file in grade.log submissions; do
    [ ! -e "$work/release-clone/$file" ] || fail "$file, which git does not track, is in the release"
  done
  if grep -rlaF -- "$hidden_name" "$work/release-clone" | grep .; then fail "a hidden test name is in the release (above)"; fi
  grep -q "left out of the copy, not tracked by git (2 files): grade.log submissions/alice/planar.cpp" \
    "$work/release-clone.txt" || { cat "$work/release-clone.txt"; fail "the release does not name what it left out"; }
  [ -f "$work/release-clone/module01_kinematics/src/planar.cpp" ] || fail "the release of the clone lacks module 1"
  stray="; files that git does not track stay out of a release"
fi
echo "release integrity: releases with the solutions of 0, 4 and 8 modules restate no other solution;" \
  "a disguised copy planted into $plant_file is caught; no released checks header declares a hidden-only helper$stray"
