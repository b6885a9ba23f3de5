#!/usr/bin/env bash
# The main job: builds appell, then evaluates a scene.
#   scripts/run.sh [SCENE] [appell eval options]
# Default: Euler's rigid body (paper sec. 3) in rigorous interval arithmetic.
#
# A first build (no ./build yet) compiles the scalars this job needs: interval and mpfi, which
# every build has, and the one `--scalar` names (APPELL_SCALARS, CMakeLists.txt).  A build
# directory configured before keeps its scalars and gains the one asked for; one with every
# scalar (scripts/test.sh's) stays so.  Only the `appell` command is built.
set -euo pipefail
cd "$(dirname "$0")/.."
if (($# == 0)); then set -- data/scenes/euler_body.json --scalar interval; fi
# The scalar the command asks for, if it is one of the list (appell names an unknown one itself).
asked=""
args=("$@")
for ((i = 0; i + 1 < ${#args[@]}; i++)); do
  if [[ ${args[i]} == --scalar ]]; then asked=${args[i + 1]}; fi
done
known=$(sed -n 's/^  X(ctx, .*"\([a-z0-9-]*\)").*/\1/p' include/appell/scalar/standard_scalars.hpp)
scalars="interval,mpfi"
if [[ -f build/CMakeCache.txt ]]; then
  scalars=$(sed -n 's/^APPELL_SCALARS:[A-Z]*=//p' build/CMakeCache.txt)
  scalars=${scalars:-all}
fi
flags=()
if [[ $scalars != all ]]; then
  if [[ -n $asked ]] && grep -qx -- "$asked" <<<"$known" && ! grep -qx -- "$asked" <<<"$(tr ',;' '\n\n' <<<"$scalars")"; then
    scalars="$scalars,$asked"
  fi
  flags=(-DAPPELL_BUILD_TESTS=OFF -DAPPELL_BUILD_BENCH=OFF "-DAPPELL_SCALARS=$scalars")
fi
scripts/deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${flags[@]}" >/dev/null
cmake --build build -j"$(nproc)" --target appell >/dev/null
exec build/appell eval "$@"
