#!/usr/bin/env bash
# Builds appell, its tests, proofs and examples with AddressSanitizer and
# UndefinedBehaviorSanitizer in ./build-sanitize (-O1, assertions on) and runs
# the suite there (the valgrind and install tests are left out of that build).
# Any sanitizer report aborts the test that triggered it: CTest then fails.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Sanitize -DCMAKE_CXX_FLAGS_SANITIZE="-O1 -g1" \
  -DAPPELL_SANITIZE=ON -DAPPELL_BUILD_TESTS=ON -DAPPELL_BUILD_BENCH=OFF >/dev/null
cmake --build build-sanitize -j"$(nproc)"
cd build-sanitize
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --output-on-failure -j"$(nproc)" --timeout 1500 "$@"
