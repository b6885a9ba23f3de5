#!/usr/bin/env bash
# Robots from URDF against the engines, in one run: forward dynamics and every joint's wrench at
# each robot's scene state, appell (appell_bench_urdf's fd-SCALAR/ROBOT: no checks, the engines'
# work) and DART, MuJoCo and Bullet (tests/engines/*_reference time SCENE REPS), their processes
# interleaved round by round so that a slow spell of the machine touches all of them; the median
# of the rounds, microseconds, and appell's ratio to the fastest engine: double, interval, and at
# 113 bits the rigorous mpfi and arb and the point mpfr (arb's cost against it: issue 57, point 4).
#
# Usage: bench/robots_vs_engines.sh [BUILD_DIR] [ROUNDS]   (default build, 3)
# The build needs -DAPPELL_BUILD_BENCH=ON (appell_bench_urdf) and -DAPPELL_BUILD_TESTS=ON (the
# engines' programs; each one found is timed).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
rounds=${2:-3}
robots=(urdf_appell_arm urdf_wam urdf_kr5 urdf_atlas)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for ((r = 1; r <= rounds; ++r)); do
  echo "round $r of $rounds" >&2
  for robot in "${robots[@]}"; do
    for engine in dart mujoco bullet; do
      exe="$build/tests/engines/${engine}_reference"
      [ -x "$exe" ] || continue
      us=$("$exe" time "data/scenes/$robot.json" 20000 | awk '{print $2}')
      echo "$engine,$robot,$us" >>"$out/times.csv"
    done
  done
  "$build/bench/appell_bench_urdf" --benchmark_filter='^fd-' --benchmark_min_time=0.2 \
    --benchmark_out="$out/appell_$r.json" --benchmark_out_format=json >/dev/null
done
python3 - "$out" "$rounds" "${robots[@]}" <<'EOF'
import json, statistics, sys, glob, collections
out, rounds, robots = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
t = collections.defaultdict(list)
for line in open(out + "/times.csv"):
    e, r, us = line.strip().split(",")
    t[(e, r)].append(float(us))
for f in glob.glob(out + "/appell_*.json"):
    for b in json.load(open(f))["benchmarks"]:
        scalar, robot = b["name"][3:].split("/")
        unit = {"ns": 1e-3, "us": 1.0, "ms": 1e3}[b["time_unit"]]
        t[(scalar, robot.replace(".json", ""))].append(b["real_time"] * unit)
med = {k: statistics.median(v) for k, v in t.items()}
engines = [e for e in ("dart", "mujoco", "bullet") if any((e, r) in med for r in robots)]
scalars = [s for s in ("double", "interval", "mpfi", "arb", "mpfr") if any((s, r) in med for r in robots)]
print(f"forward dynamics and every joint's wrench, microseconds (median of {rounds} interleaved rounds)")
print(f"{'robot':18}" + "".join(f"{e:>10}" for e in engines) + "".join(f"{s:>12}" for s in scalars) +
      "".join(f"{s + '/best':>15}" for s in scalars) + (f"{'arb/mpfr':>10}" if "arb" in scalars and "mpfr" in scalars else ""))
for r in robots:
    best = min((med[(e, r)] for e in engines if (e, r) in med), default=float("nan"))
    row = f"{r[5:]:18}" + "".join(f"{med.get((e, r), float('nan')):10.2f}" for e in engines)
    row += "".join(f"{med.get((s, r), float('nan')):12.1f}" for s in scalars)
    row += "".join(f"{med.get((s, r), float('nan')) / best:15.1f}" for s in scalars)
    if ("arb", r) in med and ("mpfr", r) in med:
        row += f"{med[('arb', r)] / med[('mpfr', r)]:10.2f}"
    print(row)
EOF
