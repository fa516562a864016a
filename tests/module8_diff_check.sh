#!/bin/sh
# Module 8's reference diff from module 7 (solutions/module08_full_fff/from_module7.md, released
# with the module's solutions) shows the functions that put a flexible body into the system's
# equations. This check recomputes every diff that its block names (its "@@ M07Tk name -> M08Tk
# name" lines) from solutions/ and fails, with both versions, where the file and the code differ.
# Usage: module8_diff_check.sh SOURCE_TREE
set -eu
tree=$1
readme=$tree/solutions/module08_full_fff/from_module7.md
m7=$tree/solutions/module07_intuitive_flexible/intuitive_flexible.cpp
m8=$tree/solutions/module08_full_fff/ffrf.cpp
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# body FILE NAME: the lines between BEGIN SOLUTION and END SOLUTION of function NAME.
body() {
  awk -v name="$2(" '
    !found && index($0, name) > 0 && $0 !~ /^ / { found = 1; next }
    found && /\/\/ END SOLUTION/ { exit }
    found && inside { print }
    found && /\/\/ BEGIN SOLUTION/ { inside = 1 }' "$1"
}

# The README's block, between its markers and without the ```diff fence.
sed -n '/<!-- module 8 diff: begin -->/,/<!-- module 8 diff: end -->/p' "$readme" | grep -v '^<!--' | grep -v '^```' \
  >"$work/readme"
[ -s "$work/readme" ] || { echo "module 8 diff: no block between the markers in $readme" >&2; exit 1; }

: >"$work/code"
grep '^@@ ' "$work/readme" | while IFS= read -r header; do
  old=$(echo "$header" | awk '{print $3}')
  new=$(echo "$header" | awk '{sub(/:$/, "", $6); print $6}')
  body "$m7" "$old" >"$work/old"
  body "$m8" "$new" >"$work/new"
  [ -s "$work/old" ] || { echo "module 8 diff: no solution body of $old in $m7" >&2; exit 1; }
  [ -s "$work/new" ] || { echo "module 8 diff: no solution body of $new in $m8" >&2; exit 1; }
  echo "$header" >>"$work/code"
  diff -U 1000 "$work/old" "$work/new" | tail -n +4 >>"$work/code" || true
done
if ! cmp -s "$work/readme" "$work/code"; then
  echo "module 8 diff: from_module7.md's block differs from the diff of the reference solutions:" >&2
  diff "$work/readme" "$work/code" >&2 || true
  exit 1
fi
changed=$(grep -c '^[-+]' "$work/code" || true)
echo "module 8 diff: the reference diff is the code's ($changed changed lines)"
[ "$changed" -le 15 ] || { echo "module 8 diff: $changed changed lines, more than 15" >&2; exit 1; }
