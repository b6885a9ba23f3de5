#!/usr/bin/env bash
# What a long-horizon reference costs per time unit (`simulate` in mpfr at 256 bits, the
# integrator's own steps), two builds side by side: each configuration runs in both at once,
# one process per core, so that both see the same machine.
#   bench/mp_reference_cost.sh BEFORE_BUILD AFTER_BUILD [T_CONE] [T_BOWL] [BITS]
# BEFORE_BUILD and AFTER_BUILD are directories holding an `appell` binary (the old one copied
# aside, e.g. /tmp/before).  Default horizons: 2 time units on the cone, 8 in the bowl.
# Prints the seconds per time unit of each, before/after, and whether the two trajectory.csv
# are byte-identical: at 256 bits they are not (Boost's mpfr_float, before, took 257 bits); at a
# count Boost could take exactly (65, 114, 254, 257, ...) they should be.
set -euo pipefail
before=$1 after=$2 t_cone=${3:-2} t_bowl=${4:-8} bits=${5:-256}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf "%-44s %12s %12s %8s %10s\n" configuration "before s/tu" "after s/tu" ratio files
timed() {  # out_file binary_dir args...: runs appell, writes its seconds to out_file
  local out=$1 dir=$2
  shift 2
  local s e
  s=$(date +%s.%N)
  "$dir/appell" "$@" > /dev/null
  e=$(date +%s.%N)
  awk -v s="$s" -v e="$e" 'BEGIN { print e - s }' > "$out"
}
run() {  # name scene t_end extra...
  local name=$1 scene=$2 t=$3
  shift 3
  local args=(simulate "$scene" --scalar mpfr --bits "$bits" --t-end "$t" --every "$t" --quiet "$@")
  timed "$work/tb" "$before" "${args[@]}" --out "$work/before" &
  local pid=$!
  timed "$work/ta" "$after" "${args[@]}" --out "$work/after"
  wait $pid
  local same=differ
  cmp -s "$work/before/trajectory.csv" "$work/after/trajectory.csv" && same=identical
  awk -v n="$name" -v t="$t" -v b="$(cat "$work/tb")" -v a="$(cat "$work/ta")" -v f="$same" \
    'BEGIN { printf "%-44s %12.3f %12.3f %8.2f %10s\n", n, b / t, a / t, b / a, f }'
}
run "cone, order 60, tol 2^-257 (as shipped)" data/scenes/top_on_cone.json "$t_cone"
run "cone, order 40, tol 2^-140" data/scenes/top_on_cone.json "$t_cone" --order 40 --tol 7.2e-43
run "bowl, order 60, tol 2^-257 (as shipped)" data/scenes/rolling_sphere_bowl.json "$t_bowl"
run "bowl, order 40, tol 2^-140" data/scenes/rolling_sphere_bowl.json "$t_bowl" --order 40 --tol 7.2e-43
