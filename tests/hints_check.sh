#!/bin/sh
# The hint ladders (moduleNN_*/hints.md) and ./workbook hint:
#   - every task of the solutions has a ladder of exactly three levels, and no ladder names a
#     task that does not exist;
#   - a TODO gives the task, not the formula: no formula of a ladder's top level (a line or a
#     `code span` with "=") is restated in the exercise files of its module, but for a
#     constraint's own equation "C = ..." and the few symbols and models a task states;
#   - ./workbook hint opens one level per call, lists the tasks, refuses an unknown task;
#   - a release with --hint-ceiling 1 carries level 1 only and says so; with 0 it has none; by
#     default, level 3 only for the modules whose solutions it carries.
# Usage: hints_check.sh SOURCE_TREE WORK_DIR
set -eu
tree=$1
work=$2
rm -rf "$work"
mkdir -p "$work"

fail() {
  echo "hints check: $*" >&2
  exit 1
}

# 1. A ladder per task, three levels each.
grep -ho 'TASK(M[0-9][0-9]T[0-9]*)' "$tree"/solutions/module*/*.cpp | sed 's/TASK(\(.*\))/\1/' | sort -u >"$work/tasks.txt"
[ -s "$work/tasks.txt" ] || fail "no TASK markers found in $tree/solutions"
for hints in "$tree"/module[0-9][0-9]_*/hints.md; do
  [ -e "$hints" ] || fail "no module has a hints.md"
  awk -v file="$hints" '
    /^## / { if ($2 !~ /^M[0-9][0-9]T[0-9]+$/) { print file ": heading \"" $0 "\" is not a task id"; bad = 1 }
             task = $2; print "task", task; expect = 1; next }
    /^### / { if (task == "" || $0 != "### Level " expect) { print file ": in " task ", \"" $0 "\" where \"### Level " expect "\" belongs"; bad = 1 }
              ++expect; levels[task] = $3; next }
    END { for (t in levels) if (levels[t] != 3) { print file ": " t " has " levels[t] " levels, not 3"; bad = 1 }
          exit bad }' "$hints" >>"$work/ladders.txt" || fail "$(grep -v '^task ' "$work/ladders.txt")"
done
sed -n 's/^task //p' "$work/ladders.txt" | sort >"$work/laddered.txt"
missing=$(comm -23 "$work/tasks.txt" "$work/laddered.txt" | tr '\n' ' ')
[ -z "$missing" ] || fail "tasks without a hint ladder: $missing"
extra=$(comm -13 "$work/tasks.txt" "$work/laddered.txt" | tr '\n' ' ')
[ -z "$extra" ] || fail "ladders of tasks that do not exist (or appear twice): $extra"

# 2. The formulas of level 3 are not in the exercise files (spaces ignored). A TODO may state the
# symbols and models that the task is about (they are not what the student derives).
: >"$work/restated.txt"
cat >"$work/task_statements.txt" <<'EOF'
n_i=A_iI~axis_i
b=model.bodies()[k]
f=k(L-L0)+cL_dot+f_a
M=mass_matrix(model,q)
EOF
for hints in "$tree"/module[0-9][0-9]_*/hints.md; do
  module=$(dirname "$hints")
  awk '/^## / { level = 0 } /^### Level / { level = $3; next } level == 3 && /=/ {
         line = $0; found = 0
         while (match(line, /`[^`]*=[^`]*`/)) { print substr(line, RSTART + 1, RLENGTH - 2); line = substr(line, RSTART + RLENGTH); found = 1 }
         if (!found) print $0 }' "$hints" | tr -d ' \t' | awk 'length($0) >= 12 && !/^C=/' | sort -u |
    { grep -v -x -F -f "$work/task_statements.txt" || true; } >"$work/formulas.txt"
  cat "$module"/src/*.cpp | tr -d ' \t' >"$work/exercises.txt"
  while IFS= read -r formula; do
    if grep -F -q -- "$formula" "$work/exercises.txt"; then echo "  $module/src: $formula"; fi
  done <"$work/formulas.txt" >>"$work/restated.txt"
done
[ ! -s "$work/restated.txt" ] ||
  fail "exercise files restate formulas of their hints' level 3 (the TODO gives the task, the ladder the formula):
$(cat "$work/restated.txt")"

# 3. The ladder, one level per call, in a copy with every ladder whole (a release with every
# solution; its build/hints.opened is its own).
"$tree/workbook" release --out "$work/copy" --solutions-through 8 >/dev/null
hint() { (cd "$work/copy" && ./workbook hint "$@") }
for level in 1 2 3; do
  hint m1t3 >"$work/level$level.txt" 2>&1 || fail "./workbook hint m1t3 failed: $(cat "$work/level$level.txt")"
  grep -q "^-- M01T3, level $level --$" "$work/level$level.txt" || fail "call $level did not open level $level: $(cat "$work/level$level.txt")"
  next=$((level + 1))
  ! grep -q "^-- M01T3, level $next --$" "$work/level$level.txt" || fail "call $level opened level $next too"
done
grep -q "^Level 1 of 3. Still stuck? ./workbook hint M01T3 opens level 2.$" "$work/level1.txt" || fail "level 1 does not point to level 2: $(cat "$work/level1.txt")"
grep -q "whole ladder" "$work/level3.txt" || fail "level 3 does not say it is the last: $(cat "$work/level3.txt")"
hint >"$work/list.txt" || fail "./workbook hint without a task failed"
grep -q "^  M01T3   3 of 3 levels opened$" "$work/list.txt" || fail "the list does not show M01T3's opened levels: $(cat "$work/list.txt")"
[ "$(grep -c '^  M[0-9][0-9]T[0-9]* ' "$work/list.txt")" -eq "$(wc -l <"$work/tasks.txt")" ] || fail "the list does not name every task: $(cat "$work/list.txt")"
if hint M01T99 >"$work/unknown.txt" 2>&1; then fail "an unknown task was accepted"; fi
grep -q "has no task M01T99; its tasks: M01T1" "$work/unknown.txt" || fail "an unknown task is not explained: $(cat "$work/unknown.txt")"
hint M01T3 --reset >/dev/null && hint M01T3 >"$work/reset.txt" && grep -q "^Level 1 of 3" "$work/reset.txt" || fail "--reset does not close the ladder"

# 4. The instructor's ceiling in a release.
"$tree/workbook" release --out "$work/ceiling1" --through 2 --hint-ceiling 1 >/dev/null
! grep -q "^### Level [23]" "$work/ceiling1"/module*/hints.md || fail "a release with --hint-ceiling 1 carries higher levels"
(cd "$work/ceiling1" && ./workbook hint M02T1 >/dev/null && ./workbook hint M02T1 >"$work/ceiling.txt") || fail "hint in the release failed"
grep -q "last hint of this release" "$work/ceiling.txt" || fail "the release does not say its ladder stops: $(cat "$work/ceiling.txt")"
# By default, level 3 (the worked formula) only where the release carries the module's solutions.
"$tree/workbook" release --out "$work/default" --through 2 --solutions-through 1 >/dev/null
grep -q "^### Level 3" "$work/default"/module01_*/hints.md || fail "a release with module 1's solutions lacks its level 3"
! grep -q "^### Level 3" "$work/default"/module02_*/hints.md || fail "a release without module 2's solutions carries its level 3"
grep -q "^### Level 2" "$work/default"/module02_*/hints.md || fail "the default release lost module 2's level 2"
"$tree/workbook" release --out "$work/ceiling0" --through 1 --hint-ceiling 0 >/dev/null
[ ! -e "$work/ceiling0/module01_kinematics/hints.md" ] || fail "a release with --hint-ceiling 0 carries hints"
if (cd "$work/ceiling0" && ./workbook hint M01T1 >"$work/none.txt" 2>&1); then fail "hint succeeded without hints"; fi
grep -q "no hints" "$work/none.txt" || fail "a release without hints does not say so: $(cat "$work/none.txt")"
echo "hints check: $(wc -l <"$work/tasks.txt") ladders of three levels; one level per call; the release ceiling holds"
