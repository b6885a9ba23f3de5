#!/usr/bin/env bash
# Where one unit's compile time goes: compiles SOURCE with clang++ -ftime-trace (the flags of the
# Release build, no precompiled header) and prints the front end's and back end's seconds and the
# templates whose instantiation took longest, each once however deeply nested
# (scripts/time_trace_summary.py).  A developer's tool: clang is not one of the build's
# dependencies (apt-get install -y clang).  Usage, from the source tree after a configure of
# ./build (the generated headers):
#   scripts/time_trace.sh tests/rolling_sphere.cpp [-O1]      # default -O3
#   scripts/time_trace.sh build/generated/model_rolling_sphere_double.cpp
# GCC's -ftime-report gives the phases (parsing, instantiation, optimisation) but not the
# templates; docs/architecture.md, "Build time", has what this showed.
set -euo pipefail
cd "$(dirname "$0")/.."
source=${1:?usage: scripts/time_trace.sh SOURCE [-O1|-O2|-O3]}
level=${2:--O3}
command -v clang++ > /dev/null || { echo "time_trace.sh: clang++ is not installed (apt-get install -y clang)" >&2; exit 2; }
[[ -f build/generated/programs/program_paths.hpp ]] || { echo "time_trace.sh: configure ./build first (scripts/build.sh)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# clang reads GCC's headers: quadmath.h is GCC's own (copied beside), and mpfr.h names _Float128,
# which clang 14 spells __float128.
quadmath=$(find /usr/lib/gcc -name quadmath.h -print -quit)
[[ -n "$quadmath" ]] && cp "$(dirname "$quadmath")"/quadmath*.h "$work"/
clang++ -std=gnu++20 "$level" -DNDEBUG -DBOOST_ALL_NO_LIB -DBOOST_TEST_DYN_LINK -DMPFR_WANT_FLOAT128=1 \
  -D_Float128=__float128 -Iinclude -Itests -Ibuild/generated/programs -isystem /usr/include/eigen3 -isystem "$work" \
  -fPIC -frounding-math -ffp-contract=off -w -ftime-trace -ftime-trace-granularity=100 \
  -c "$source" -o "$work/unit.o"
python3 scripts/time_trace_summary.py "$work/unit.json"
