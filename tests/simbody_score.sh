#!/usr/bin/env bash
# Scores Simbody against appell's reference values (CTest: simbody_scored_*):
#   simbody_score.sh APPELL SIMBODY_REFERENCE heavy_top|sphere_plane SOURCE_DIR OUT_DIR
# 1. appell reference certifies the dataset's states in mpfi at 113 bits, taking every input as
#    the double nearest to its decimal (the problem Simbody solves);
# 2. examples/simbody_reference computes the same quantities with Simbody;
# 3. appell score judges them: at least 13 correct digits in every quantity, or the test fails.
set -euo pipefail
appell=$1 simbody=$2 kind=$3 src=$4 out=$5
# skip: the reference's quantities the program does not compute (appell score --skip): for the
# sphere, the contact force's split into normal and tangential parts and the rest of the derived
# geometry; it gives the accelerations and the contact force.
skip=""
case $kind in
  heavy_top) scene=$src/data/scenes/heavy_top.json ;;
  sphere_plane) scene=$src/data/reference/sphere_plane.json
                skip="normal_force,tangential_force,pivot_couple,friction_ratio,contact_point*,normal*,center_velocity*" ;;
  *) echo "unknown kind $kind" >&2; exit 2 ;;
esac
states=$src/data/reference/${kind}_states.csv
rm -rf "$out"
mkdir -p "$out"
"$appell" reference "$scene" --states "$states" --scalar mpfi --bits 113 --inputs binary64 --out "$out/reference"
"$simbody" "$kind" "$scene" "$states" > "$out/simbody.csv"
"$appell" score "$out/reference" "$out/simbody.csv" --min-digits 13 ${skip:+--skip "$skip"} --plot "$out/score.png" | tee "$out/score.txt"
