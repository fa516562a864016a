#!/bin/sh
# Checks the spin-up frames CSV (full FFRF, frame at the centroid or clamped at the hub): at 2 rad/s,
# below the first cantilever frequency (2.9 rad/s), both frames stay bounded and end near the
# radial line; at 4 rad/s the clamped frame runs away (its column ends empty: the demo stops a
# run whose tip leaves the line by 1 m) while the centroid frame ends near the line.
#   check_frames.sh <spin_up_frames.csv>
csv=$1
[ -s "$csv" ] || { echo "no CSV at $csv (run the demo test first)"; exit 1; }
awk -F, '
  NR == 1 {
    for (i = 1; i <= NF; ++i) col[$i] = i
    c2 = col["centroid_2 [m]"]; k2 = col["clamped_2 [m]"]; c4 = col["centroid_4 [m]"]; k4 = col["clamped_4 [m]"]
    if (!c2 || !k2 || !c4 || !k4) { print "missing columns in the header: " $0; bad = 1; exit 1 }
    next
  }
  { last = $0; split($0, f, ","); if (f[k4] == "" && !stopped) stopped = $1 }
  END {
    if (bad) exit 1
    split(last, f, ",")
    if (f[c2] == "" || f[k2] == "" || f[c2] * f[c2] > 0.05 ^ 2 || f[k2] * f[k2] > 0.05 ^ 2) {
      print "at 2 rad/s both frames should end within 5 cm of the radial line: " last; exit 1 }
    if (f[c4] == "" || f[c4] * f[c4] > 0.05 ^ 2) { print "at 4 rad/s the centroid frame should end within 5 cm: " last; exit 1 }
    if (!stopped) { print "at 4 rad/s the clamped frame should run away, but it ends at " f[k4] " m"; exit 1 }
    printf "2 rad/s: both frames bounded; 4 rad/s: the clamped frame runs away at t = %s s, the centroid frame ends at %s m\n", stopped, f[c4]
  }' "$csv"
