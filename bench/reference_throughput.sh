#!/usr/bin/env bash
# Throughput of `appell reference` (states per second), one process against MPI ranks, in one run:
#   bench/reference_throughput.sh [BUILD_DIR] [STATES] [RANKS] [SCENE BOX] [REPS]
# STATES states drawn in BOX (`--box`, seed 1) of SCENE, in interval and in mpfi at 113 bits.
# Default: the heavy top, every field of its state varied.  The sphere in the bowl (its states must
# stay on the constraints, so the spin about the axis normal to the plane of the centre's meridian
# is varied: omega[1]):
#   bench/reference_throughput.sh build 10000 2 data/scenes/rolling_sphere_bowl.json "omega[1]=-20:20"
# REPS (default 1) repeats each measurement and prints every run and the medians (a shared
# machine's load moves a run by 40%: docs/reference-values.md quotes medians of 3).
set -euo pipefail
build=${1:-build} n=${2:-2000} ranks=${3:-2}
scene=${4:-data/scenes/heavy_top.json}
box=${5:-psi=-3:3,theta=0.2:2.9,phi=-3:3,psi_dot=-5:5,theta_dot=-5:5,phi_dot=-60:60}
reps=${6:-1}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
flags=(-np "$ranks" --oversubscribe)
[ "$(id -u)" -eq 0 ] && flags+=(--allow-run-as-root)
export OMPI_MCA_btl_vader_single_copy_mechanism=none
echo "$scene, $n states in $box"
printf "%-10s %8s %16s %16s %8s\n" scalar states "1 process /s" "$ranks ranks /s" ratio
for scalar in interval mpfi; do
  bits=(); [ $scalar = mpfi ] && bits=(--bits 113)
  ones=() manys=()
  for ((r = 1; r <= reps; ++r)); do
    t0=$(date +%s.%N)
    "$build/appell" reference "$scene" --box "$box" --n "$n" --seed 1 --scalar $scalar "${bits[@]}" --quiet \
      --out "$work/one" > /dev/null
    t1=$(date +%s.%N)
    mpirun "${flags[@]}" "$build/appell-mpi" reference "$scene" --box "$box" --n "$n" --seed 1 --scalar $scalar \
      "${bits[@]}" --quiet --out "$work/many" > /dev/null
    t2=$(date +%s.%N)
    cmp -s "$work/one/reference.csv" "$work/many/reference.csv" || { echo "outputs differ"; exit 1; }
    ones+=("$(awk -v n=$n -v a=$t0 -v b=$t1 'BEGIN { printf "%.0f", n / (b - a) }')")
    manys+=("$(awk -v n=$n -v b=$t1 -v c=$t2 'BEGIN { printf "%.0f", n / (c - b) }')")
    [ "$reps" -gt 1 ] && printf "%-10s %8d %16s %16s %8s  (run %d)\n" $scalar $n "${ones[-1]}" "${manys[-1]}" "" $r
  done
  one=$(printf "%s\n" "${ones[@]}" | sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }')
  many=$(printf "%s\n" "${manys[@]}" | sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }')
  awk -v s=$scalar -v n=$n -v one=$one -v many=$many -v reps=$reps \
    'BEGIN { printf "%-10s %8d %16.0f %16.0f %8.2f%s\n", s, n, one, many, many / one, (reps > 1 ? "  (medians)" : "") }'
done
echo "(wall clock, reading and writing included; mpirun's start-up counted against the ranks)"
