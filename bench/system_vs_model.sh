#!/usr/bin/env bash
# The paper's scenes moving as system files (one generic path) against their dedicated models,
# in one run: `appell enclose` of each pair to the same T, in interval, run alternately
# (REPS times each, the median time kept), with the steps, the time and the state's largest
# width at T, and the ratios (system file / dedicated model).  Whether the two enclosures
# intersect is tested in CTest (tests/system_motion.cpp); this table is the cost.
#   bench/system_vs_model.sh [BUILD_DIR] [REPS]
set -euo pipefail
build=${1:-build} reps=${2:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
field() { sed -n "s/^  \"$2\": \\([^,]*\\),\$/\\1/p" "$1"; }
run() {  # scene T -> "steps seconds width"
  local times=()
  for ((r = 0; r < reps; ++r)); do
    "$build/appell" enclose "data/scenes/$1" --t-end "$2" --quiet --out "$work/run" > /dev/null
    times+=("$(field "$work/run/summary.json" seconds)")
  done
  local median
  median=$(printf "%s\n" "${times[@]}" | sort -g | sed -n "$(((reps + 1) / 2))p")
  echo "$(field "$work/run/summary.json" steps) $median $(field "$work/run/summary.json" final_largest_width)"
}
printf "%-16s %4s | %6s %9s %9s | %6s %9s %9s | %7s %7s\n" scene T steps seconds width steps seconds width "time x" "width x"
while read -r name model system T; do
  read -r s1 t1 w1 < <(run "$model" "$T")
  read -r s2 t2 w2 < <(run "$system" "$T")
  awk -v n="$name" -v T="$T" -v s1="$s1" -v t1="$t1" -v w1="$w1" -v s2="$s2" -v t2="$t2" -v w2="$w2" \
    'BEGIN { printf "%-16s %4s | %6d %9.3f %9.2e | %6d %9.3f %9.2e | %7.2f %7.2f\n", n, T, s1, t1, w1, s2, t2, w2, t2 / t1, w2 / w1 }'
done <<'PAIRS'
euler_body euler_body.json system_euler_body.json 10
heavy_top heavy_top.json system_heavy_top.json 5
top_on_cone top_on_cone.json system_top_on_cone.json 1
sphere_in_bowl rolling_sphere_bowl.json system_rolling_sphere_bowl.json 2
PAIRS
