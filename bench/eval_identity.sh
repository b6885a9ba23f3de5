#!/usr/bin/env bash
# Byte-identity of `appell eval` and `appell enclose` between two binaries: every scene of
# data/scenes in the seven scalars (eval's stdout and exit status), and enclose of a few scenes
# (steps.csv and the exit status).  A change that must not move a result checks it with
#   bench/eval_identity.sh OLD_APPELL NEW_APPELL
# One line per output that differs ("DIFFER ..."), then the counts; exits 1 on any difference.
set -uo pipefail
cd "$(dirname "$0")/.."
old=$1 new=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
same=0 differ=0
for scene in data/scenes/*.json; do
  for scalar in double long-double dd float128 mpfr interval mpfi; do
    "$old" eval "$scene" --scalar "$scalar" > "$work/a" 2>&1; ra=$?
    "$new" eval "$scene" --scalar "$scalar" > "$work/b" 2>&1; rb=$?
    if [ "$ra" = "$rb" ] && cmp -s "$work/a" "$work/b"; then same=$((same + 1)); else
      differ=$((differ + 1)); echo "DIFFER (exit $ra/$rb): eval $scene --scalar $scalar"; fi
  done
done
for run in "data/scenes/heavy_top.json --t-end 2" "data/scenes/euler_body_123.json --scalar mpfi --bits 113 --t-end 2" \
           "data/scenes/rolling_sphere_bowl_contact.json --t-end 0.5" "data/scenes/system_rolling_disk.json --t-end 0.5" \
           "data/scenes/urdf_appell_arm.json --t-end 0.2"; do
  rm -rf "$work/ea" "$work/eb"
  # shellcheck disable=SC2086
  "$old" enclose $run --quiet --out "$work/ea" > /dev/null 2>&1; ra=$?
  # shellcheck disable=SC2086
  "$new" enclose $run --quiet --out "$work/eb" > /dev/null 2>&1; rb=$?
  if [ "$ra" = "$rb" ] && cmp -s "$work/ea/steps.csv" "$work/eb/steps.csv"; then same=$((same + 1)); else
    differ=$((differ + 1)); echo "DIFFER (exit $ra/$rb): enclose $run"; fi
done
echo "$same same, $differ differ"
[ "$differ" = 0 ]
