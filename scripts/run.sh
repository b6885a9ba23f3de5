#!/usr/bin/env bash
# The main job: builds appell, then evaluates a scene.
#   scripts/run.sh [SCENE] [appell eval options]
# Default: Euler's rigid body (paper sec. 3) in rigorous interval arithmetic.
#
# A first build (no ./build yet) compiles what this job needs: the evaluation alone
# (APPELL_EVAL_ONLY: the motion and the linearization left out, their commands exit 2 saying how
# to build them), in interval and mpfi, which every build has, and the scalar `--scalar` names
# (APPELL_SCALARS, CMakeLists.txt), at -O1 (the same results, bit for bit; an evaluation takes
# milliseconds either way; docs/architecture.md, "Build time").  A build directory configured before keeps its choices and
# gains the scalar asked for; one with everything (scripts/test.sh --full's) stays so.  Only the
# `appell` command is built.
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
first=(-DAPPELL_EVAL_ONLY=ON -DAPPELL_RELEASE_OPTIMIZATION=-O1)
if [[ -f build/CMakeCache.txt ]]; then
  first=()
  scalars=$(sed -n 's/^APPELL_SCALARS:[A-Z]*=//p' build/CMakeCache.txt)
  scalars=${scalars:-all}
fi
flags=()
if [[ $scalars != all ]]; then
  if [[ -n $asked ]] && grep -qx -- "$asked" <<<"$known" && ! grep -qx -- "$asked" <<<"$(tr ',;' '\n\n' <<<"$scalars")"; then
    scalars="$scalars,$asked"
  fi
  flags=(-DAPPELL_BUILD_BENCH=OFF "-DAPPELL_SCALARS=$scalars")
  # The tests need double, interval and mpfi (scripts/test.sh's quick tier): a list without them
  # turns them off; one with them (a quick tier's build) keeps its tests as they were.
  listed=$(tr ',;' '\n\n' <<<"$scalars")
  for needed in double interval mpfi; do
    if ! grep -qx -- "$needed" <<<"$listed"; then flags+=(-DAPPELL_BUILD_TESTS=OFF); break; fi
  done
fi
scripts/deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${first[@]}" "${flags[@]}" >/dev/null
# The compiler's output goes to a log (GCC 12 prints false-positive warnings from libstdc++), shown
# when the build fails.
echo "scripts/run.sh: building build/appell (a first build takes about 3 minutes on 2 cores; log: build/run-build.log)" >&2
if ! cmake --build build -j"$(nproc)" --target appell >build/run-build.log 2>&1; then
  tail -n 40 build/run-build.log >&2
  echo "scripts/run.sh: the build failed (the whole log: build/run-build.log)" >&2
  exit 1
fi
exec build/appell eval "$@"
