#!/usr/bin/env bash
# Byte-identity of `appell reference` between two binaries (a change that must not move a byte
# of the datasets: printing, reading, writing), on 14 runs that reach every path: both certified
# scalars, --inputs binary64, --project, a URDF robot, refused states, extreme magnitudes and
# subnormals, state names that JSON must escape.
#   bench/reference_identity.sh OLD_APPELL NEW_APPELL
# Prints one line a run: "same" (exit statuses and both files equal) or "DIFFER"; exits 1 on any.
set -uo pipefail
cd "$(dirname "$0")/.."
old=$1 new=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
run() {
  rm -rf "$work/a" "$work/b"
  "$old" reference "$@" --quiet --out "$work/a" >/dev/null 2>&1; ra=$?
  "$new" reference "$@" --quiet --out "$work/b" >/dev/null 2>&1; rb=$?
  if [ "$ra" = "$rb" ] && [ -f "$work/a/reference.csv" ] && cmp -s "$work/a/reference.csv" "$work/b/reference.csv" &&
     cmp -s "$work/a/reference.jsonl" "$work/b/reference.jsonl"; then
    echo "same (exit $ra, $(wc -l < "$work/a/reference.csv") lines): $*"
  else
    echo "DIFFER (exit $ra/$rb): $*"
    failed=1
  fi
}
top="psi=-3:3,theta=0.2:2.9,phi=-3:3,psi_dot=-5:5,theta_dot=-5:5,phi_dot=-60:60"
run data/scenes/heavy_top.json --box "$top" --n 2000 --seed 3 --scalar interval
run data/scenes/heavy_top.json --box "$top" --n 300 --seed 3 --scalar mpfi --bits 113
run data/scenes/heavy_top.json --states data/reference/heavy_top_states.csv --scalar interval --inputs binary64
run data/scenes/heavy_top.json --states data/reference/heavy_top_states.csv --scalar mpfi --bits 200 --inputs binary64
run data/scenes/rolling_sphere_bowl.json --box "omega[1]=-20:20" --n 200 --seed 2 --scalar mpfi --bits 200
run data/scenes/rolling_sphere_bowl.json --box "omega[1]=-20:20" --n 200 --seed 2 --scalar mpfi --bits 40
run data/scenes/urdf_kr5.json --box "state.shoulder_yaw.q=-1:1,state.elbow_roll.q=-2:2" --n 200 --seed 2 --scalar interval
run data/scenes/urdf_kr5.json --box "state.shoulder_yaw.q=-1:1" --n 50 --seed 4 --scalar interval --inputs binary64
run data/scenes/system_whipple_bicycle.json --box "phi=-0.5:0.5" --n 50 --seed 2 --scalar interval
run data/scenes/top_on_cone.json --box "theta=0.1:1.5" --n 500 --seed 2 --scalar interval
run data/reference/sphere_plane.json --states data/reference/sphere_plane_states.csv --scalar interval
run data/reference/sphere_plane.json --states data/reference/sphere_plane_states.csv --scalar interval --project 1e-12
run data/scenes/euler_body.json --states data/reference/euler_body_extreme_states.csv --scalar interval
run data/scenes/euler_body.json --states data/reference/euler_body_extreme_states.csv --scalar mpfi --bits 64
exit $failed
