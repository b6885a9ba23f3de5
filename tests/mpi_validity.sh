#!/usr/bin/env bash
# appell validity on 2 MPI ranks against the single-process run (CTest: validity_on_mpi):
#   mpi_validity.sh APPELL APPELL_MPI SOURCE_DIR OUT_DIR
# The pieces (validity.csv without its seconds column) and the verdicts' ranges must be the same;
# bad input must be exit 2 from every rank, reported once, nothing written.
set -euo pipefail
appell=$1 appell_mpi=$2 src=$3 out=$4
rm -rf "$out"
mkdir -p "$out"
source "$(dirname "$0")/mpi_flags.sh"  # mpirun_flags
scene=$src/data/scenes/rolling_sphere_bowl_contact.json
args=(--vary mu=0:0.4 --t-end 0.3 --resolution 0.05 --quiet)
"$appell" validity "$scene" "${args[@]}" --jobs 1 --out "$out/one" > "$out/one.txt"
mpirun "${mpirun_flags[@]}" "$appell_mpi" validity "$scene" "${args[@]}" --out "$out/two" > "$out/two.txt"
sed 's/,[^,]*$//' "$out/one/validity.csv" > "$out/one.pieces"  # every field but the last, the seconds
sed 's/,[^,]*$//' "$out/two/validity.csv" > "$out/two.pieces"
cmp "$out/one.pieces" "$out/two.pieces"
grep -q '"processes": 2' "$out/two/summary.json"
grep -E '^  (holds|fails|undecided) for' "$out/one.txt" > "$out/one.ranges"
grep -E '^  (holds|fails|undecided) for' "$out/two.txt" > "$out/two.ranges"
cmp "$out/one.ranges" "$out/two.ranges"
grep -q "^  holds for" "$out/one.ranges" || { echo "no piece proved to hold"; exit 1; }
grep -q "^  fails for" "$out/one.ranges" || { echo "no piece proved to fail"; exit 1; }
grep -c "pieces in" "$out/two.txt" | grep -qx 1 || { echo "the summary line not printed once:"; cat "$out/two.txt"; exit 1; }
echo "validity: the same $(($(wc -l < "$out/one.pieces") - 1)) pieces and verdicts on 1 process and 2 ranks"
# bad input: exit 2, one line on stderr, nothing written
set +e
mpirun "${mpirun_flags[@]}" "$appell_mpi" validity "$scene" --vary nope=0:1 --t-end 1 --out "$out/bad" 2> "$out/bad.err"
bad=$?
set -e
[ "$bad" -eq 2 ] || { echo "bad input: exit $bad, expected 2"; cat "$out/bad.err"; exit 1; }
grep -c "'nope' is not a component" "$out/bad.err" | grep -qx 1 || { cat "$out/bad.err"; exit 1; }
[ ! -e "$out/bad" ] || { echo "bad input wrote $out/bad"; exit 1; }
echo "bad input: exit 2 on 2 ranks, reported once, nothing written"
