#!/usr/bin/env bash
# What a system file's motion costs (issue 30): `appell enclose` of the rolling disk and of the
# nonlinear Whipple bicycle to T = 1 and 10 in interval and in mpfi at 113 bits, with the steps
# (and those rejected), the seconds, and the state's largest width where the run stopped.  A run
# is capped at MAX seconds (--max-seconds): where the cap stops it, the row says how far it got,
# and the time per simulated second measured up to there.
#   bench/system_motion_cost.sh [BUILD_DIR] [MAX]
# The profile of the bicycle's run (docs/motion.md, "A system of your own in motion"):
#   perf record -g BUILD/appell enclose data/scenes/system_whipple_bicycle.json --t-end 0.2 --quiet --out OUT
#   perf report --no-children
set -euo pipefail
build=${1:-build} max=${2:-600}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
field() { sed -n "s/^  \"$2\": \"\\{0,1\\}\\([^,\"]*\\)\"\\{0,1\\},\$/\\1/p" "$1"; }
printf "%-22s %-12s %4s | %6s %8s %9s %9s %10s | %s\n" scene scalar T steps rejected seconds width "s per s" reached
for scene in system_rolling_disk system_whipple_bicycle; do
  for scalar in interval "mpfi --bits 113"; do
    for T in 1 10; do
      "$build/appell" enclose "data/scenes/$scene.json" --scalar $scalar --t-end "$T" --max-seconds "$max" --quiet \
        --out "$work/run" > /dev/null || true
      s="$work/run/summary.json"
      reached=$(field "$s" t_reached)
      awk -v n="$scene" -v sc="${scalar/ --bits /@}" -v T="$T" -v st="$(field "$s" steps)" -v rj="$(field "$s" rejected_steps)" \
        -v sec="$(field "$s" seconds)" -v w="$(field "$s" final_largest_width)" -v r="$reached" -v c="$(field "$s" complete)" \
        'BEGIN { printf "%-22s %-12s %4s | %6d %8d %9.2f %9.2e %10.2f | %s\n", n, sc, T, st, rj, sec, w, sec / r, (c == "true" ? "T" : "t = " r " (cap)") }'
    done
  done
done
