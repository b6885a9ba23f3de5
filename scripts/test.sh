#!/usr/bin/env bash
# Builds appell with its tests, proofs, examples and benchmarks, and runs the tests with CTest.
# The benchmarks are asked for explicitly: a build directory configured first by
# scripts/run.sh (tests off) caches APPELL_BUILD_BENCH=OFF, and bench/ holds one
# test (chain_against_simbody).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh -DAPPELL_BUILD_TESTS=ON -DAPPELL_BUILD_BENCH=ON
cd build
ctest --output-on-failure -j"$(nproc)" "$@"
