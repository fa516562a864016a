#!/bin/sh
# Checks the intuitive_energy CSV: the model's own energy is conserved (ideal joints, constant
# M_bar, conservative forces), and the true nodal energy changes by far more, which is the point
# of the demo. Both are measured against the larger of the two changes.
#   check_energy_gap.sh <intuitive_energy.csv>
csv=$1
[ -s "$csv" ] || { echo "no CSV at $csv (run the demo test first)"; exit 1; }
awk -F, '
  NR == 1 {
    for (i = 1; i <= NF; ++i) col[$i] = i
    m = col["model_energy_change [J]"]; t = col["true_energy_change [J]"]
    if (!m || !t) { print "missing energy columns in the header: " $0; bad = 1; exit 1 }
    next
  }
  {
    a = $m < 0 ? -$m : $m; b = $t < 0 ? -$t : $t
    if (a > ma) ma = a
    if (b > mb) mb = b
  }
  END {
    if (bad) exit 1
    printf "largest change: model energy %.3e J, true energy %.3e J\n", ma, mb
    if (mb <= 0) { print "the true energy never changes: nothing is missing?"; exit 1 }
    if (ma > 1e-3 * mb) { print "the model energy is not conserved to 1e-3 of the true energy change"; exit 1 }
  }' "$csv"
