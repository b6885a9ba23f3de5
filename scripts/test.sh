#!/usr/bin/env bash
# Builds appell with its tests, proofs and examples, and runs the tests with CTest.
#   scripts/test.sh [--full] [ctest options]
# The quick tier (the default) compiles the library in double, interval and mpfi: the point
# scalar every command defaults to and the two rigorous scalars every build has (CMake's
# APPELL_SCALARS); a test case that needs another scalar says so and is skipped
# (tests/built_scalars.hpp), and `--scalar` naming one is exit 2 saying how to build it.  It
# compiles at -O1 (the same results, bit for bit; a third less compile time than -O3; the suites
# it runs take about as long: docs/architecture.md, "Build time") and leaves out the CTest entries
# labelled long (the bicycle's two motions and contacts_long, a minute or two each; the two
# valgrind runs of the backends' suites; docs/testing.md, "Two tiers").
# --full compiles all eight scalars at -O3, what a user's Release build has, and runs every case
# and entry (what CI runs: .ci/run).  The benchmarks are left out (docs/benchmarks.md:
# -DAPPELL_BUILD_BENCH=ON builds them); the one test bench/ holds (chain_against_simbody) is built
# with the tests.  The tier's choices are passed explicitly: a build directory configured before
# (scripts/run.sh's first build: the evaluation alone, -O1) keeps its cached choices otherwise.
set -euo pipefail
cd "$(dirname "$0")/.."
scalars=double,interval,mpfi
optimization=-O1
if [[ ${1:-} == --full ]]; then
  scalars=all
  optimization=-O3
  shift
fi
scripts/build.sh -DAPPELL_BUILD_TESTS=ON -DAPPELL_BUILD_BENCH=OFF "-DAPPELL_SCALARS=$scalars" -DAPPELL_EVAL_ONLY=OFF \
  "-DAPPELL_RELEASE_OPTIMIZATION=$optimization"
cd build
left_out=()
if [[ $scalars != all ]]; then
  echo "test.sh: the quick tier (the library in $scalars, $optimization, the entries labelled long left out);" \
    "scripts/test.sh --full runs every scalar and every entry" >&2
  left_out=(-LE '^long$')
fi
ctest --output-on-failure --no-tests=error -j"$(nproc)" "${left_out[@]}" "$@"
