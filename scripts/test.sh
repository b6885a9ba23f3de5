#!/usr/bin/env bash
# Builds appell with its tests, proofs and examples, and runs the tests with CTest.
# The benchmarks are left out (docs/benchmarks.md: -DAPPELL_BUILD_BENCH=ON builds them);
# the one test bench/ holds (chain_against_simbody) is built with the tests.  Asked for
# explicitly: a build directory configured before keeps its cached choice otherwise.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh -DAPPELL_BUILD_TESTS=ON -DAPPELL_BUILD_BENCH=OFF -DAPPELL_SCALARS=all
cd build
ctest --output-on-failure -j"$(nproc)" "$@"
