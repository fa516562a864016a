#!/bin/sh
# Every benchmark program runs (--quick) and prints well-formed rows "group,case,quantity,value,unit"
# with a finite number as the value. Times are printed, never checked.
# The rows are read by the front end's reader of that format (./workbook inspect bench).
# Usage: bench_check.sh SOURCE_TREE WORK_DIR NAME=PROGRAM...
set -eu
tree=$1
work=$2
shift 2
rm -rf "$work"
mkdir -p "$work"
[ $# -gt 0 ] || { echo "bench check: no benchmark programs" >&2; exit 1; }
for benchmark in "$@"; do
  name=${benchmark%%=*}
  executable=${benchmark#*=}
  "$executable" --quick >"$work/$name.csv" 2>"$work/$name.err" ||
    { cat "$work/$name.err" >&2; echo "bench check: fmbd-bench-$name failed" >&2; exit 1; }
  rows=$("$tree/workbook" inspect bench "$work/$name.csv") || { echo "bench check: fmbd-bench-$name's rows (above)" >&2; exit 1; }
  echo "bench check: $name: $rows"
done
