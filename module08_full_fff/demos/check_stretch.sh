#!/bin/sh
# Checks the spinning_beam CSV (a free beam, undeformed at t = 0, spinning at Omega):
#   - module 8's elongation, averaged over its whole oscillations (t = 0, a minimum, to its last
#     minimum), is the static FE stretch in the same basis within 1 %;
#   - module 7 does not stretch (below 1e-6 of that);
#   - the whole-mesh static FE stretch is the closed form rho Omega^2 L^3 / (12 E) of a uniform
#     rod spinning about its middle within 1 %, and the basis keeps 95 % of it.
#   check_stretch.sh <spinning_beam.csv> <rho [kg/m^3]> <E [Pa]> <L [m]> <Omega [rad/s]>
csv=$1
[ -s "$csv" ] || { echo "no CSV at $csv (run the demo test first)"; exit 1; }
awk -F, -v rho="$2" -v E="$3" -v L="$4" -v W="$5" '
  function abs(x) { return x < 0 ? -x : x }
  NR == 1 {
    for (i = 1; i <= NF; ++i) col[$i] = i
    c7 = col["module7 [um]"]; c8 = col["module8 [um]"]; cb = col["static_fe_basis [um]"]; cm = col["static_fe_mesh [um]"]
    if (!c7 || !c8 || !cb || !cm) { print "missing columns in the header: " $0; bad = 1; exit 1 }
    next
  }
  { ++n; t[n] = $1; s[n] = $c8; basis = $cb; mesh = $cm; if (abs($c7) > worst7) worst7 = abs($c7) }
  END {
    if (bad) exit 1
    for (i = 2; i < n; ++i) if (s[i] <= s[i - 1] && s[i] < s[i + 1]) last = i
    if (!last) { print "module 8 completes no oscillation in " n " rows"; exit 1 }
    for (i = 2; i <= last; ++i) area += 0.5 * (s[i] + s[i - 1]) * (t[i] - t[i - 1])
    mean = area / (t[last] - t[1])
    closed = 1e6 * rho * W * W * L * L * L / (12 * E)
    printf "module 8: mean stretch %.3f um (%d rows, to t = %s s); static FE: same basis %.3f um (%+.2f %%), whole mesh %.3f um; closed form %.3f um; module 7: at most %.2e um\n",
      mean, n, t[last], basis, 100 * (mean - basis) / basis, mesh, closed, worst7
    if (abs(mean - basis) > 0.01 * basis) { print "module 8 does not oscillate about the static FE stretch (1 %)"; exit 1 }
    if (worst7 > 1e-6 * basis) { print "module 7 stretches: it has no centrifugal force and should not"; exit 1 }
    if (abs(mesh - closed) > 0.01 * closed) { print "the whole-mesh static FE stretch is not the closed form (1 %)"; exit 1 }
    if (basis < 0.95 * mesh || basis > 1.001 * mesh) { print "the basis does not hold the static stretch (95 % of the whole mesh)"; exit 1 }
  }' "$csv"
