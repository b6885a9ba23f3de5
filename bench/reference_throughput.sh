#!/usr/bin/env bash
# Throughput of `appell reference` (states per second), one process against MPI ranks, in one run:
#   bench/reference_throughput.sh [BUILD_DIR] [STATES] [RANKS]
# The heavy top at STATES random states (default 2000) in interval and in mpfi at 113 bits.
set -euo pipefail
build=${1:-build} n=${2:-2000} ranks=${3:-2}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 - "$n" > "$work/states.csv" <<'PY'
import random, sys
rng = random.Random(1)
print("state,psi,theta,phi,psi_dot,theta_dot,phi_dot")
for i in range(int(sys.argv[1])):
    d = lambda lo, hi: "%.6f" % rng.uniform(lo, hi)
    print("s%d,%s,%s,%s,%s,%s,%s" % (i, d(-3, 3), d(0.2, 2.9), d(-3, 3), d(-5, 5), d(-5, 5), d(-60, 60)))
PY
flags=(-np "$ranks" --oversubscribe)
[ "$(id -u)" -eq 0 ] && flags+=(--allow-run-as-root)
export OMPI_MCA_btl_vader_single_copy_mechanism=none
scene=data/scenes/heavy_top.json
printf "%-10s %8s %16s %16s %8s\n" scalar states "1 process /s" "$ranks ranks /s" ratio
for scalar in interval mpfi; do
  t0=$(date +%s.%N)
  "$build/appell" reference $scene --states "$work/states.csv" --scalar $scalar --bits 113 --out "$work/one" > /dev/null 2>&1
  t1=$(date +%s.%N)
  mpirun "${flags[@]}" "$build/appell-mpi" reference $scene --states "$work/states.csv" --scalar $scalar --bits 113 \
    --out "$work/many" > /dev/null 2>&1
  t2=$(date +%s.%N)
  cmp -s "$work/one/reference.csv" "$work/many/reference.csv" || { echo "outputs differ"; exit 1; }
  awk -v s=$scalar -v n=$n -v a=$t0 -v b=$t1 -v c=$t2 -v r=$ranks \
    'BEGIN { one = n / (b - a); many = n / (c - b); printf "%-10s %8d %16.0f %16.0f %8.2f\n", s, n, one, many, many / one }'
done
echo "(wall clock, reading and writing included; mpirun's start-up counted against the ranks)"
