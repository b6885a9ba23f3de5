#!/usr/bin/env bash
# Issue 57's and 58's goals for the motion, each run against the binary of another version in the
# same run, one after the other (never side by side: --jobs 2 takes both cores):
#   the KR5 to T = 1, the WAM to T = 1, Atlas (pelvis fixed) to T = 0.1, Atlas standing to T = 1
#   (on its torques, and held by joint stiffness: scripts/standing_gains.py),
#   each capped at MAX seconds (default 120), and the Whipple bicycle at 5 m/s to T = 10, capped at
#   2 MAX; per run: the time, how far it got, its steps (rejected) and its final width.
#   bench/enclose_goals.sh BUILD_DIR [OTHER_APPELL] [MAX]
# ONLY="urdf_kr5 urdf_wam" in the environment runs those scenes alone.
# OTHER_APPELL: an `appell` built from another commit, inside a build folder (its data paths are
# its folder's); leave it out to run this build's alone.  The binary this one is compared with in
# docs/benchmarks.md is d4ccc66's: `git worktree add /tmp/old d4ccc66` and build it there, or
# relink as the docs say.
set -euo pipefail
build=${1:-build} other=${2:-} max=${3:-120}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
field() { sed -n "s/^  \"$2\": \"\\{0,1\\}\\([^,\"]*\\)\"\\{0,1\\},\$/\\1/p" "$1"; }
printf "%-34s %-6s %5s | %8s %10s %14s %9s\n" scene binary T seconds reached "steps (rej.)" width
while read -r scene T cap; do
  if [ -n "${ONLY:-}" ] && [[ " $ONLY " != *" $scene "* ]]; then continue; fi
  for which in this other; do
    bin="$build/appell"
    if [ "$which" = other ]; then
      [ -n "$other" ] || continue
      bin="$other"
    fi
    start=$(date +%s.%N)
    "$bin" enclose "data/scenes/$scene.json" --t-end "$T" --max-seconds "$cap" --quiet --out "$work/run" > /dev/null || true
    end=$(date +%s.%N)
    s="$work/run/summary.json"
    awk -v n="$scene" -v b="$which" -v T="$T" -v sec="$(echo "$end - $start" | bc)" -v r="$(field "$s" t_reached)" \
      -v st="$(field "$s" steps)" -v rj="$(field "$s" rejected_steps)" -v w="$(field "$s" final_largest_width)" \
      'BEGIN { printf "%-34s %-6s %5s | %8.1f %10.4g %14s %9.3g\n", n, b, T, sec, r, st " (" rj ")", w }'
  done
done <<LIST
urdf_kr5 1 $max
urdf_wam 1 $max
urdf_atlas 0.1 $max
urdf_atlas_standing 1 $max
urdf_atlas_standing_held 1 $max
system_whipple_bicycle_weave_5 10 $((2 * max))
LIST
