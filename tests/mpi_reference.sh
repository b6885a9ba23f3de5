#!/usr/bin/env bash
# appell reference on 2 MPI ranks against the single-process run (CTest: reference_on_mpi):
#   mpi_reference.sh APPELL APPELL_MPI SOURCE_DIR OUT_DIR
# The datasets (reference.csv, reference.jsonl) must be byte-identical, in both rigorous scalars,
# with a refused state among them; bad input must be exit 2 from every rank, reported once.
set -euo pipefail
appell=$1 appell_mpi=$2 src=$3 out=$4
rm -rf "$out"
mkdir -p "$out"
source "$(dirname "$0")/mpi_flags.sh"  # mpirun_flags
scene=$src/data/scenes/heavy_top.json
{ cat "$src/data/reference/heavy_top_states.csv"; echo "vertical,0,0,0,1,1,1"; } > "$out/states.csv"
for scalar in interval mpfi; do
  set +e
  "$appell" reference "$scene" --states "$out/states.csv" --scalar $scalar --bits 113 --out "$out/one_$scalar" 2>/dev/null
  one=$?
  mpirun "${mpirun_flags[@]}" "$appell_mpi" reference "$scene" --states "$out/states.csv" --scalar $scalar --bits 113 \
    --out "$out/two_$scalar" 2>/dev/null
  two=$?
  set -e
  [ "$one" -eq 3 ] && [ "$two" -eq 3 ] || { echo "exit statuses $one (1 process) and $two (2 ranks), expected 3 (one state refused)"; exit 1; }
  cmp "$out/one_$scalar/reference.csv" "$out/two_$scalar/reference.csv"
  cmp "$out/one_$scalar/reference.jsonl" "$out/two_$scalar/reference.jsonl"
  grep -q '"processes": 2' "$out/two_$scalar/manifest.json"
  echo "$scalar: reference.csv and reference.jsonl byte-identical on 1 process and 2 ranks ($(wc -l < "$out/one_$scalar/reference.csv") lines)"
done
# bad input: exit 2, one line on stderr
printf 'psi,theta\n1,NaN\n' > "$out/bad.csv"
set +e
mpirun "${mpirun_flags[@]}" "$appell_mpi" reference "$scene" --states "$out/bad.csv" --out "$out/bad" 2> "$out/bad.err"
bad=$?
set -e
[ "$bad" -eq 2 ] || { echo "bad input: exit $bad, expected 2"; cat "$out/bad.err"; exit 1; }
grep -c "line 2, column 2 (theta): NaN is not a finite number" "$out/bad.err" | grep -qx 1 || { cat "$out/bad.err"; exit 1; }
[ ! -e "$out/bad" ] || { echo "bad input wrote $out/bad"; exit 1; }
echo "bad input: exit 2 on 2 ranks, reported once, nothing written"
