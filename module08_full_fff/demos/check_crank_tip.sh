#!/bin/sh
# Checks the flexible slider-crank CSV: on every row the crank tip is one crank length from the
# crank hub (the animation draws that segment), and the hub stays at the bearing O = (0, 0).
#   check_crank_tip.sh <slider_crank_deflection.csv> <crank length [m]>
csv=$1
length=$2
[ -s "$csv" ] || { echo "no CSV at $csv (run the demo test first)"; exit 1; }
awk -F, -v L="$length" '
  NR == 1 {
    for (i = 1; i <= NF; ++i) col[$i] = i
    hx = col["crank_hub_x [m]"]; hy = col["crank_hub_y [m]"]; tx = col["crank_tip_x [m]"]; ty = col["crank_tip_y [m]"]
    if (!hx || !hy || !tx || !ty) { print "missing crank_hub_/crank_tip_ columns in the header: " $0; bad = 1; exit 1 }
    next
  }
  {
    ++rows
    dx = $tx - $hx; dy = $ty - $hy; d = sqrt(dx * dx + dy * dy)
    if (d - L > 1e-6 || L - d > 1e-6) { printf "row %d (t = %s s): crank tip %.6f m from the hub, expected %s m\n", NR, $1, d, L; bad = 1; exit 1 }
    if ($hx * $hx + $hy * $hy > 1e-12) { printf "row %d: crank hub at (%s, %s), expected the bearing (0, 0)\n", NR, $hx, $hy; bad = 1; exit 1 }
  }
  END {
    if (bad) exit 1
    if (rows < 10) { print "only " rows " rows"; exit 1 }
    printf "crank tip %s m from the hub on all %d rows\n", L, rows
  }' "$csv"
