#!/bin/sh
# Checks one row of spin_up_thresholds.csv (spin_up_beam --threshold on): the spin rate at which
# steady spin loses stability, found from the eigenvalues of the linearised equations, against
# time simulations of steady spin with the tip kicked by `kick`:
#   - just below the threshold (rate_below, a few % under it) the tip never leaves steady spin by
#     more than twice the kick;
#   - just above it (rate_above) it runs away, to 100 kicks and more;
#   - the simulated growth rate above it is the largest real eigenvalue there, within 5 %;
#   - with E, I, rho A and L given: the threshold is the first cantilever frequency
#     1.8751^2 sqrt(E I / (rho A L^4)) of Euler-Bernoulli within 1 % (the frame clamped at the hub,
#     where the centrifugal term leaves omega_1^2 - Omega^2 to the first mode).
#   check_thresholds.sh <spin_up_thresholds.csv> <model: 7 or 8> <frame: 0 centroid, 1 clamped> [E I rhoA L]
csv=$1
[ -s "$csv" ] || { echo "no CSV at $csv (run the demo first)"; exit 1; }
awk -F, -v model="$2" -v frame="$3" -v E="$4" -v I="$5" -v rhoA="$6" -v L="$7" '
  function abs(x) { return x < 0 ? -x : x }
  NR == 1 {
    for (i = 1; i <= NF; ++i) col[$i] = i
    split("model [-],frame [-],threshold [rad/s],rate_below [rad/s],peak_below [m],rate_above [rad/s],peak_above [m],growth_linear [1/s],growth_simulated [1/s],kick [m]", names, ",")
    for (i in names) if (!col[names[i]]) { print "missing column " names[i] " in the header: " $0; bad = 1; exit 1 }
    next
  }
  $col["model [-]"] == model && $col["frame [-]"] == frame {
    found = 1
    w = $col["threshold [rad/s]"]; lo = $col["rate_below [rad/s]"]; hi = $col["rate_above [rad/s]"]
    pb = $col["peak_below [m]"]; pa = $col["peak_above [m]"]; kick = $col["kick [m]"]
    gl = $col["growth_linear [1/s]"]; gs = $col["growth_simulated [1/s]"]
  }
  END {
    if (bad) exit 1
    if (!found) { print "no row for model " model ", frame " frame; exit 1 }
    printf "model %s, frame %s: threshold %s rad/s; kicked by %s m: peak %s m at %s rad/s, %s m at %s rad/s; growth %s 1/s (eigenvalue %s 1/s)\n", model, frame, w, kick, pb, lo, pa, hi, gs, gl
    if (!(lo < w && w < hi && hi - lo <= 0.1 * w)) { print "the kicked runs should lie a few % below and above the threshold"; exit 1 }
    if (!(kick > 0) || pb > 2 * kick) { print "below the threshold the tip should stay within two kicks of steady spin"; exit 1 }
    if (pa < 100 * kick) { print "above the threshold the tip should run away (100 kicks)"; exit 1 }
    if (!(gl > 0) || abs(gs - gl) > 0.05 * gl) { print "the simulated growth should be the largest real eigenvalue within 5 %"; exit 1 }
    if (L != "") {
      w1 = 1.8751 ^ 2 * sqrt(E * I / (rhoA * L ^ 4))
      printf "first cantilever frequency (Euler-Bernoulli): %.4f rad/s\n", w1
      if (abs(w - w1) > 0.01 * w1) { print "the threshold should be the first cantilever frequency within 1 %"; exit 1 }
    }
  }' "$csv"
