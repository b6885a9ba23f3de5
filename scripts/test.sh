#!/usr/bin/env bash
# Builds appell with its tests, proofs and examples, and runs them all with CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh -DAPPELL_BUILD_TESTS=ON
cd build
ctest --output-on-failure -j"$(nproc)" "$@"
