#!/bin/sh
# Checks the spin-up tip deflection CSV where the demo has its stiffened curve (module 8 with
# geometric stiffening, your M08T7 and M08T8): at the slow rate it agrees with the linear
# full FFRF (peaks within 10 %); at the fast rate, where the linear full FFRF runs away (its peak
# beyond 2 m), it stays bounded (|tip| below 1.5 m throughout) and ends within 5 cm of the radial line.
#   check_stiffened.sh <spin_up_tip_deflection.csv>
csv=$1
[ -s "$csv" ] || { echo "no CSV at $csv (run the demo test first)"; exit 1; }
awk -F, '
  function abs(x) { return x < 0 ? -x : x }
  NR == 1 {
    for (i = 1; i <= NF; ++i) col[$i] = i
    s8 = col["slow_module8 [m]"]; ss = col["slow_stiffened [m]"]; f8 = col["fast_module8 [m]"]; fs = col["fast_stiffened [m]"]
    if (!s8 || !ss || !f8 || !fs) { print "missing columns in the header: " $0; bad = 1; exit 1 }
    next
  }
  {
    if (abs($s8) > p_s8) p_s8 = abs($s8)
    if (abs($ss) > p_ss) p_ss = abs($ss)
    if ($f8 != "" && abs($f8) > p_f8) p_f8 = abs($f8)
    if ($fs == "") gap = 1
    else if (abs($fs) > p_fs) p_fs = abs($fs)
    last = $fs
  }
  END {
    if (bad) exit 1
    if (p_s8 == 0 || abs(p_ss - p_s8) > 0.1 * p_s8) {
      printf "slow rate: the stiffened peak %.4f m should be within 10 %% of the linear FFRF peak %.4f m\n", p_ss, p_s8; exit 1 }
    if (p_f8 < 2) { printf "fast rate: the linear FFRF should run away (peak %.3f m)\n", p_f8; exit 1 }
    if (gap || p_fs > 1.5 || abs(last) > 0.05) {
      printf "fast rate: the stiffened tip should stay within 1.5 m and end within 5 cm (peak %.3f m, end %s m)\n", p_fs, last; exit 1 }
    printf "slow rate: peaks %.4f m (linear) and %.4f m (stiffened); fast rate: linear %.2f m, stiffened %.3f m, ends at %s m\n", p_s8, p_ss, p_f8, p_fs, last
  }' "$csv"
