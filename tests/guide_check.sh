#!/bin/sh
# The guides run: every ./workbook command line of a code block in README.md and docs/*.md appears,
# with the same options, in a test script as a real invocation (not a mention in a string, a grep
# pattern or a comment), or is `./workbook test`, which CI runs, or is one of the few run by hand
# below; every relative link of the guides leads somewhere (readme_links.sh); and
# `./workbook studentify` runs here, in a copy of the tree, where it must leave every committed
# skeleton as it is.
# Usage: guide_check.sh SOURCE_TREE WORK_DIR FMBD_GUIDE_COMMANDS
set -eu
tree=$1
work=$2
guide_commands=$3
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

# The commands of the guides that no test runs, each with its reason. Each must still be in a guide.
by_hand() {
  cat <<'LIST'
bench	it builds and grades a fresh release to time it (minutes); project.bench runs every benchmark program with --quick itself
bench --quick	project.bench runs every benchmark program with --quick itself
demo --csv	with a DISPLAY it opens windows; the demo.* tests run every demo program headlessly and check its CSV files
demo --help	it builds a demo first (minutes); the demo.* tests run every demo program
LIST
}

# The guides: the top README and every docs/*.md.
set -- "$tree/README.md"
for guide in "$tree"/docs/*.md; do
  [ -e "$guide" ] && set -- "$@" "$guide"
done
"$guide_commands" guide "$@" >"$work/guide.sh"
grep -q "workbook" "$work/guide.sh" || fail "no commands found in the guides"
signatures <"$work/guide.sh" | sort -u >"$work/guide.txt"
"$guide_commands" run "$tree"/tests/*.sh "$tree/.ci/run" | signatures >"$work/tested.unsorted"
by_hand | cut -f 1 >>"$work/tested.unsorted"
sort -u "$work/tested.unsorted" >"$work/tested.txt"
untested=$(comm -23 "$work/guide.txt" "$work/tested.txt")
[ -z "$untested" ] || fail "these commands of the guides are run by no test: $untested"
gone=$(by_hand | cut -f 1 | sort -u | comm -13 "$work/guide.txt" -)
[ -z "$gone" ] || fail "these commands run by hand are in no guide any more (drop them from by_hand): $gone"

# The guides' links.
sh "$tree/tests/readme_links.sh" "$tree" || fail "dead links in the READMEs and guides (above)"

# ./workbook studentify in a copy regenerates the committed skeletons unchanged.
mkdir -p "$work/copy"
tar -C "$tree" --exclude=./build --exclude=./out --exclude=./.git -cf - . | tar -C "$work/copy" -xf -
(cd "$work/copy" && ./workbook studentify) >"$work/studentify.log" 2>&1 ||
  { cat "$work/studentify.log" >&2; fail "./workbook studentify failed"; }
for folder in "$tree"/module[0-9][0-9]_*/src; do
  relative=${folder#"$tree"/}
  diff -r "$folder" "$work/copy/$relative" >/dev/null || fail "studentify changed $relative: a skeleton is out of date"
done
echo "guide check: $(wc -l <"$work/guide.txt") guide commands are tested ($(by_hand | wc -l) of them by hand); the links lead somewhere; studentify leaves the skeletons unchanged"
