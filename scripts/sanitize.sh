#!/usr/bin/env bash
# Builds appell, its tests, proofs and examples with AddressSanitizer and
# UndefinedBehaviorSanitizer in ./build-sanitize (-O1, assertions on) and runs
# the suite there (the valgrind and install tests are left out of that build).
# Any sanitizer report aborts the test that triggered it: CTest then fails.
#
#   scripts/sanitize.sh            the whole suite (about 40 minutes on 2 cores: the library
#                                  is compiled a second time; run it before a release)
#   scripts/sanitize.sh --numbers  the numbers layer only (appell_numbers: the scalars'
#                                  functions and backends, decimal conversions, the verified
#                                  solve) and its suites, label `numbers`, in ./build-sanitize-numbers:
#                                  a few minutes, what CI runs (.ci/run)
# --numbers, if given, comes first; the other arguments go to ctest.
# APPELL_SANITIZE_BUILD_SECONDS=N: stop the build after N seconds (CI's budget, .ci/run); the
# script then exits 75 without running the suites.  The units compiled by then are in the build
# cache (a later run goes on from there); the objects written in the last minutes are removed,
# since one of them may have been cut short.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
dir=build-sanitize
configure=()
targets=()
labels=()
if [ "${1:-}" = "--numbers" ]; then
  shift
  dir=build-sanitize-numbers
  # No precompiled header: its target compiles against the whole library (appell_core).
  configure=(-DAPPELL_PCH=OFF)
  targets=(--target appell_numbers_tests)  # the suites labelled `numbers` (tests/CMakeLists.txt)
  labels=(-L numbers)
fi
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Sanitize -DCMAKE_CXX_FLAGS_SANITIZE="-O1 -g1" \
  -DAPPELL_SANITIZE=ON -DAPPELL_BUILD_TESTS=ON -DAPPELL_BUILD_BENCH=OFF "${configure[@]}" >/dev/null
build=(cmake --build "$dir" -j"$(nproc)" "${targets[@]}")
if [ -n "${APPELL_SANITIZE_BUILD_SECONDS:-}" ]; then
  if timeout -k 30 "$APPELL_SANITIZE_BUILD_SECONDS" "${build[@]}"; then
    :
  else
    status=$?
    if [ "$status" -ne 124 ] && [ "$status" -ne 137 ]; then exit "$status"; fi
    find "$dir" \( -name '*.o' -o -name '*.gch' \) -mmin -5 -delete
    echo "sanitize.sh: the build stopped at its budget of $APPELL_SANITIZE_BUILD_SECONDS s; the suites were not run" >&2
    exit 75
  fi
else
  "${build[@]}"
fi
cd "$dir"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --output-on-failure -j"$(nproc)" --timeout 1500 "${labels[@]}" "$@"
