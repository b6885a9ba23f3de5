#!/usr/bin/env bash
# The main job: builds appell, then evaluates a scene.
#   scripts/run.sh [SCENE] [appell eval options]
# Default: Euler's rigid body (paper sec. 3) in rigorous interval arithmetic.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh -DAPPELL_BUILD_TESTS=OFF >/dev/null
if (($# == 0)); then set -- data/scenes/euler_body.json --scalar interval; fi
exec build/appell eval "$@"
