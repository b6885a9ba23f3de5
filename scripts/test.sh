#!/usr/bin/env bash
# Builds appell with its tests, proofs and examples, and runs the tests with CTest.
# The benchmarks are left out (docs/benchmarks.md: -DAPPELL_BUILD_BENCH=ON builds them);
# the one test bench/ holds (chain_against_simbody) is built with the tests.  Asked for
# explicitly: a build directory configured before (scripts/run.sh's first build: the evaluation
# alone, two scalars, -O2) keeps its cached choices otherwise.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh -DAPPELL_BUILD_TESTS=ON -DAPPELL_BUILD_BENCH=OFF -DAPPELL_SCALARS=all -DAPPELL_EVAL_ONLY=OFF \
  -DAPPELL_RELEASE_OPTIMIZATION=-O3
cd build
ctest --output-on-failure -j"$(nproc)" "$@"
