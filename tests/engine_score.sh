#!/usr/bin/env bash
# Scores an engine on a robot against appell's reference values (CTest: engine_scored_*):
#   engine_score.sh APPELL ENGINE_PROGRAM NAME SCENE OUT_DIR MIN_DIGITS [N [SKIP]]
# 1. the engine's program draws N (default 200) random states of the scene's joints (seeded);
# 2. appell reference certifies them in mpfi at 113 bits, every input (the URDF's numbers too)
#    taken as the double nearest to its decimal: the problem the engine solves;
# 3. the engine computes the same quantities (joint accelerations, every joint's wrench);
# 4. appell score judges them: at least MIN_DIGITS correct digits in every quantity, or it fails;
#    every quantity of the reference must be given but those SKIP names (appell score --skip: what
#    the engine does not compute, said where the test is defined).
set -euo pipefail
appell=$1 engine=$2 name=$3 scene=$4 out=$5 min=$6 n=${7:-200} skip=${8:-}
rm -rf "$out"
mkdir -p "$out"
"$engine" states "$scene" "$n" 1 > "$out/states.csv"
"$appell" reference "$scene" --states "$out/states.csv" --scalar mpfi --bits 113 --inputs binary64 --out "$out/reference"
"$engine" values "$scene" "$out/states.csv" > "$out/$name.csv"
"$appell" score "$out/reference" "$out/$name.csv" --min-digits "$min" ${skip:+--skip "$skip"} --plot "$out/score.png" | tee "$out/score.txt"
