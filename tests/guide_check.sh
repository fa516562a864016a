#!/bin/sh
# The instructor guide of the README runs: every ./workbook command in it appears, with the same
# options, in a test script (or is `./workbook test`, which CI runs), and `./workbook studentify`
# runs here, in a copy of the tree, where it must leave every committed skeleton as it is.
# Usage: guide_check.sh SOURCE_TREE WORK_DIR
set -eu
tree=$1
work=$2
rm -rf "$work"
mkdir -p "$work"

fail() {
  echo "guide check: $*" >&2
  exit 1
}

# signatures: "COMMAND --option ..." (options sorted) of each workbook call on stdin.
signatures() {
  awk '/^[ \t]*#/ { next }
    { for (i = 1; i < NF; ++i) if ($i ~ /workbook"?$/) break
      if (i >= NF) next
      command = $(i + 1); gsub(/[^a-z]/, "", command)
      n = 0
      for (j = i + 2; j <= NF; ++j) {
        word = $j; end = word ~ /[)|>;]/; sub(/[)|>;].*/, "", word)
        if (word ~ /^--[a-z-]+$/) options[++n] = word
        if (end) break
      }
      for (a = 2; a <= n; ++a) for (b = a; b > 1 && options[b - 1] > options[b]; --b) {
        t = options[b]; options[b] = options[b - 1]; options[b - 1] = t }
      line = command; for (a = 1; a <= n; ++a) line = line " " options[a]
      print line }'
}

# The guide: the fenced sh blocks between "## Instructor guide" and the next section.
sed -n '/^## Instructor guide/,/^## [^I]/p' "$tree/README.md" |
  awk '/^[ \t]*```sh/ { inside = 1; next } /^[ \t]*```/ { inside = 0 } inside' >"$work/guide.sh"
grep -q "workbook" "$work/guide.sh" || fail "no commands found in the README's instructor guide"
signatures <"$work/guide.sh" | sort -u >"$work/guide.txt"
cat "$tree"/tests/*.sh "$tree/.ci/run" | signatures | sort -u >"$work/tested.txt"
untested=$(comm -23 "$work/guide.txt" "$work/tested.txt")
[ -z "$untested" ] || fail "these commands of the instructor guide are run by no test: $untested"

# ./workbook studentify in a copy regenerates the committed skeletons unchanged.
mkdir -p "$work/copy"
tar -C "$tree" --exclude=./build --exclude=./out --exclude=./.git -cf - . | tar -C "$work/copy" -xf -
(cd "$work/copy" && ./workbook studentify) >"$work/studentify.log" 2>&1 ||
  { cat "$work/studentify.log" >&2; fail "./workbook studentify failed"; }
for folder in "$tree"/module[0-9][0-9]_*/src; do
  relative=${folder#"$tree"/}
  diff -r "$folder" "$work/copy/$relative" >/dev/null || fail "studentify changed $relative: a skeleton is out of date"
done
echo "guide check: $(wc -l <"$work/guide.txt") guide commands are tested; studentify leaves the skeletons unchanged"
