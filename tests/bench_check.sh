#!/bin/sh
# Every benchmark program runs (--quick) and prints well-formed rows "group,case,quantity,value,unit"
# with a finite number as the value. Times are printed, never checked.
# Usage: bench_check.sh WORK_DIR NAME=PROGRAM...
set -eu
work=$1
shift
rm -rf "$work"
mkdir -p "$work"
[ $# -gt 0 ] || { echo "bench check: no benchmark programs" >&2; exit 1; }
for benchmark in "$@"; do
  name=${benchmark%%=*}
  executable=${benchmark#*=}
  "$executable" --quick >"$work/$name.csv" 2>"$work/$name.err" ||
    { cat "$work/$name.err" >&2; echo "bench check: fmbd-bench-$name failed" >&2; exit 1; }
  awk -F, -v name="$name" '
    NF != 5 { printf "bench check: %s line %d has %d fields, not 5: %s\n", name, NR, NF, $0; bad = 1 }
    NF == 5 && $4 !~ /^-?[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?$/ {
      printf "bench check: %s line %d: value \"%s\" is not a number\n", name, NR, $4; bad = 1 }
    END { if (NR == 0) { printf "bench check: %s printed nothing\n", name; bad = 1 }; exit bad }' \
    "$work/$name.csv" >&2
  echo "bench check: $name: $(wc -l <"$work/$name.csv") rows"
done
